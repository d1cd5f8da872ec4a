// The keys of [[loads]] and [[electrodes]]: what drives the beam in time.

#include "model/case_schema_bind.hpp"
#include "model/case_schema_builtin.hpp"
#include "model/run_estimate.hpp"

namespace vi::schema {
namespace {

using FunctionKind = TimeFunction::Kind;
using WaveKind = Waveform::Kind;

KeyCondition load_of_kind(FunctionKind k, const std::string& name) {
    return when<PointLoad>([k](const PointLoad& p) { return p.time.kind == k; }, {"kind"},
                           "only with $.kind = \"" + name + "\"", "only for a load of kind \"" + name + "\"");
}

// A shape key of an electrode's waveform is set through its Waveform, and g(t) built again, exactly
// as a case file with that value would build it.
void rebuild(Electrode& e) {
    if (built_from_shape(e.waveform.kind)) e.time = waveform_function(e.waveform, e.voltage);
}

// The condition "waveform is one of kinds"; `names` lists them as the messages do.
KeyCondition waveform_in(std::vector<WaveKind> kinds, const std::string& names) {
    return when<Electrode>(
        [kinds](const Electrode& e) { return std::find(kinds.begin(), kinds.end(), e.waveform.kind) != kinds.end(); },
        {"waveform"}, "only with $.waveform = " + names, "only for waveform = " + names);
}

// One shape key of the waveform: a time, a level or a frequency stored in e.waveform.
KeySpec& shape_key(SectionSpec& s, KeySpec k, double Waveform::*field, KeyCondition c) {
    KeySpec& key = s.add_key(std::move(k)).only(std::move(c));
    return bind<Electrode>(key, [field](Electrode& e, std::size_t) -> double& { return e.waveform.*field; }, rebuild);
}

void add_layer_keys(SectionSpec& s) {
    bind_member(s.add_key(number_key("dielectric_thickness", Dimension::length)).otherwise(0.0).in(non_negative())
                    .means("t_d of a layer on the electrode, below `gap`"),
                &Electrode::dielectric_thickness);
    // A case file may give a layer's keys beside a thickness of 0; they mean something only above it.
    KeyCondition layer = when<Electrode>([](const Electrode& e) { return e.dielectric_thickness > 0.0; }, {},
                                         "only with a dielectric_thickness above 0", "", "`dielectric_thickness` > 0");
    layer.in_file = false;
    KeySpec& eps = s.add_key(number_key("dielectric_permittivity", Dimension::dimensionless)).otherwise(1.0).only(layer);
    eps.range.lo = 1.0;
    eps.range.too_low = "must be at least 1 (relative permittivity)";
    eps.needing("dielectric_thickness", "needs dielectric_thickness (the layer it belongs to)");
    bind_member(eps.means("its relative permittivity eps_r"), &Electrode::dielectric_permittivity);
    bind_member(s.add_key(number_key("dielectric_modulus", Dimension::pressure)).otherwise(250e9, "250 GPa (silicon nitride)")
                    .in(positive()).only(layer)
                    .needing("dielectric_thickness", "needs dielectric_thickness (the layer it belongs to)")
                    .means("Young's modulus E_d of the layer, for the contact on it (docs/electrostatics.md §2)"),
                &Electrode::dielectric_modulus);
    KeySpec& w = s.add_key(number_key("work_of_adhesion", Dimension::surface_energy)).in(positive()).only(layer);
    w.needing("dielectric_thickness", "needs dielectric_thickness (the layer the beam adheres to)");
    w.means("w of the dielectric layer: the layer is adhesive (docs/adhesion.md §9)").default_text = "none (not adhesive)";
    bind_optional<Electrode>(w, [](Electrode& e) -> std::optional<double>& { return e.work_of_adhesion; });
    KeyCondition adhesive = when<Electrode>([](const Electrode& e) { return e.work_of_adhesion.has_value(); }, {},
                                            "only with an adhesive layer (work_of_adhesion given)", "",
                                            "`work_of_adhesion`");
    adhesive.in_file = false;
    bind_member(s.add_key(number_key("adhesion_range", Dimension::length)).otherwise(kDefaultAdhesionRange, "2 nm")
                    .in(positive()).only(adhesive)
                    .needing("work_of_adhesion", "needs work_of_adhesion (the adhesion it is the range of)")
                    .means("the range of that adhesion"),
                &Electrode::adhesion_range);
}

void add_waveform_keys(SectionSpec& s) {
    const std::vector<std::string> names{"constant", "step", "ramp", "pulse", "two_step", "sine", "table"};
    const std::vector<WaveKind> kinds{WaveKind::constant, WaveKind::step,     WaveKind::ramp, WaveKind::pulse,
                                      WaveKind::two_step, WaveKind::sine, WaveKind::table};
    KeySpec& wave = s.add_key(choice_key("waveform", names)).otherwise(std::string("constant"));
    wave.means("V(t) = voltage g(t): `\"constant\"`; `\"step\"` on at `t_on`; `\"ramp\"` up over `rise`; `\"pulse\"` "
               "up over `rise`, held for `hold`, down over `fall`; `\"two_step\"` up to `level` x `voltage` over "
               "`rise`, held for `hold`, then up to `voltage` over `rise` (a shaped drive); `\"sine\"` V = bias + "
               "voltage sin(2 pi f t + phase); `\"table\"` volts from a CSV file");
    bind_choice<Electrode>(wave, [](Electrode& e) -> WaveKind& { return e.waveform.kind; }, kinds);
    const std::string timed = "\"step\", \"ramp\", \"pulse\" or \"two_step\"";
    shape_key(s, number_key("t_on", Dimension::time).otherwise(0.0).in(non_negative()).means("when the drive starts"),
              &Waveform::t_on, waveform_in({WaveKind::step, WaveKind::ramp, WaveKind::pulse, WaveKind::two_step}, timed));
    const KeyCondition edged =
        waveform_in({WaveKind::ramp, WaveKind::pulse, WaveKind::two_step}, "\"ramp\", \"pulse\" or \"two_step\"");
    shape_key(s, number_key("rise", Dimension::time).require().in(positive()).means("each rising edge's duration"),
              &Waveform::rise, edged);
    shape_key(s, number_key("hold", Dimension::time).require().in(positive())
                     .means("pulse: at full voltage; two_step: at the first level"),
              &Waveform::hold, waveform_in({WaveKind::pulse, WaveKind::two_step}, "\"pulse\" or \"two_step\""));
    shape_key(s, number_key("fall", Dimension::time).require().in(positive()).means("the falling edge's duration"),
              &Waveform::fall, waveform_in({WaveKind::pulse}, "\"pulse\""));
    shape_key(s, number_key("level", Dimension::dimensionless).require().in(non_negative())
                     .means("the first level as a fraction of `voltage`"),
              &Waveform::level, waveform_in({WaveKind::two_step}, "\"two_step\""));
    const KeyCondition sine = waveform_in({WaveKind::sine}, "\"sine\"");
    shape_key(s, number_key("frequency", Dimension::frequency).require().in(positive()).means("f"), &Waveform::frequency,
              sine);
    shape_key(s, number_key("phase", Dimension::dimensionless, "rad").otherwise(0.0).means("radians"), &Waveform::phase,
              sine);
    shape_key(s, number_key("bias", Dimension::voltage).otherwise(0.0).means("the mean voltage"), &Waveform::bias, sine);
    KeySpec& table = s.add_key(table_file_key("table", "V_V")).require();
    table.only(waveform_in({WaveKind::table}, "\"table\""));
    table.empty_text = "must not be empty (a CSV file name with columns t_s,V_V)";
    table.means("CSV file with the header `t_s,V_V` (volts, times strictly increasing), relative to the case file");
    bind_text<Electrode>(table, [](Electrode& e) -> std::string& { return e.table_file; });
    table.table = [](Case& c, std::size_t i) { return &c.electrodes[i].time; };
}

}  // namespace

SectionSpec loads_section() {
    SectionSpec s = array_section<PointLoad>("loads", "load", &Case::loads, 0);
    s.params = [](Case& c, std::size_t i) { return i < c.loads.size() ? &c.loads[i].params : nullptr; };
    bind_member(s.add_key(number_key("position", Dimension::dimensionless, "x/l")).require()
                    .in(interval(0, true, 1, false, " (x/l)")).means("x/l of the load; not at a clamped or pinned end"),
                &PointLoad::position);
    bind_member(s.add_key(number_key("amplitude", Dimension::force)).require().means("the force scale, positive up"),
                &PointLoad::amplitude);
    KeySpec& kind = s.add_key(choice_key("kind", {"constant", "step", "harmonic", "table"})).require();
    kind.means("the time function g(t): `\"constant\"` g = 1; `\"step\"` g = 0 before `t_on`, 1 from then on; "
               "`\"harmonic\"` g = `offset` + sin(2 pi `frequency` t + `phase`); `\"table\"` piecewise linear "
               "through the rows of a CSV file, held at its first and last values outside it");
    bind_choice<PointLoad>(kind, [](PointLoad& p) -> FunctionKind& { return p.time.kind; },
                           std::vector<FunctionKind>{FunctionKind::constant, FunctionKind::step, FunctionKind::harmonic,
                                                     FunctionKind::table});
    const auto time_field = [](double TimeFunction::*f) {
        return [f](PointLoad& p, std::size_t) -> double& { return p.time.*f; };
    };
    bind<PointLoad>(s.add_key(number_key("t_on", Dimension::time)).require().in(non_negative())
                        .only(load_of_kind(FunctionKind::step, "step")).means("step time"),
                    time_field(&TimeFunction::t_on));
    bind<PointLoad>(s.add_key(number_key("frequency", Dimension::frequency)).require().in(positive())
                        .only(load_of_kind(FunctionKind::harmonic, "harmonic")).means("f"),
                    time_field(&TimeFunction::frequency_hz));
    bind<PointLoad>(s.add_key(number_key("phase", Dimension::dimensionless, "rad")).otherwise(0.0)
                        .only(load_of_kind(FunctionKind::harmonic, "harmonic")).means("radians"),
                    time_field(&TimeFunction::phase));
    bind<PointLoad>(s.add_key(number_key("offset", Dimension::dimensionless)).otherwise(0.0)
                        .only(load_of_kind(FunctionKind::harmonic, "harmonic")).means("mean value of g"),
                    time_field(&TimeFunction::offset));
    KeySpec& table = s.add_key(table_file_key("table", "g")).require().only(load_of_kind(FunctionKind::table, "table"));
    table.empty_text = "must not be empty (a CSV file name)";
    table.means("CSV file with the header `t_s,g` (below), relative to the case file's folder");
    bind_text<PointLoad>(table, [](PointLoad& p) -> std::string& { return p.table_file; });
    table.table = [](Case& c, std::size_t i) { return &c.loads[i].time; };
    return s;
}

SectionSpec electrodes_section() {
    SectionSpec s = array_section<Electrode>("electrodes", "electrode", &Case::electrodes, kMaxElectrodes);
    s.params = [](Case& c, std::size_t i) { return i < c.electrodes.size() ? &c.electrodes[i].params : nullptr; };
    // A table gives volts itself (columns t_s,V_V); every other waveform scales g(t) by `voltage`.
    s.before = [](Case& c, std::size_t i, const std::function<bool(std::string_view)>&) { c.electrodes[i].voltage = 1.0; };
    s.after = [](Case& c, std::size_t i) {
        Electrode& e = c.electrodes[i];
        rebuild(e);
        if (e.waveform.kind == WaveKind::table) e.time.kind = FunctionKind::table;
    };
    bind_member(s.add_key(number_key("from", Dimension::dimensionless, "x/l")).require()
                    .in(interval(0, false, 1, true, " (x/l)")).means("where the span along the beam starts"),
                &Electrode::from);
    bind_member(s.add_key(number_key("to", Dimension::dimensionless, "x/l")).require()
                    .in(interval(0, true, 1, false, " (x/l)")).means("where it ends, above `from`; need not fall on nodes"),
                &Electrode::to);
    bind_choice<Electrode>(s.add_key(choice_key("side", {"below", "above"})).otherwise(std::string("below"))
                               .means("`\"below\"` pulls the beam down, `\"above\"` up"),
                           [](Electrode& e) -> Side& { return e.side; }, std::vector<Side>{Side::below, Side::above});
    bind_member(s.add_key(number_key("gap", Dimension::length)).require().in(positive())
                    .means("beam to electrode at rest, dielectric included"),
                &Electrode::gap);
    add_layer_keys(s);
    KeySpec& width = s.add_key(number_key("width", Dimension::length)).in(positive(" (or left out: the beam's width)"));
    width.means("effective electrode width w_e").default_text = "the beam's width";
    bind_member(width, &Electrode::width);
    width.is_set = [](const Case& c, std::size_t i) { return c.electrodes[i].width != 0.0; };
    bind_choice<Electrode>(s.add_key(choice_key("fringing", {"none", "meijs-fokkema"})).otherwise(std::string("none"))
                               .means("`\"none\"` (parallel plate) or `\"meijs-fokkema\"` (docs/electrostatics.md §2)"),
                           [](Electrode& e) -> Fringing& { return e.fringing; },
                           std::vector<Fringing>{Fringing::none, Fringing::meijs_fokkema});
    KeySpec& voltage = s.add_key(number_key("voltage", Dimension::voltage)).require();
    voltage.only(when<Electrode>([](const Electrode& e) { return e.waveform.kind != WaveKind::table; }, {"waveform"},
                                 "only with $.waveform other than \"table\" (a table gives volts)",
                                 "not for a table waveform (it gives volts itself)", "`waveform` not `\"table\"`"));
    bind_member(voltage.means("the amplitude"), &Electrode::voltage, rebuild);
    add_waveform_keys(s);
    return s;
}

}  // namespace vi::schema
