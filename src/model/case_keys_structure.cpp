// The keys of the top level, [beam], [material], [damping] and [initial]; and the built-in schema.

#include "model/case_schema_bind.hpp"
#include "model/case_schema_builtin.hpp"
#include "model/run_estimate.hpp"

namespace vi::schema {
namespace {

const std::vector<std::string> kEnds{"clamped", "pinned", "free"};
const std::vector<EndCondition> kEndValues{EndCondition::clamped, EndCondition::pinned, EndCondition::free};

}  // namespace

SectionSpec top_level_section() {
    SectionSpec s = table_section<Case>("", true);
    KeySpec& name = s.add_key(text_key("name"));
    name.means("Name of the case, used for output files and reports; must not be empty")
        .otherwise(std::string(), "the file name without its directory and extension (`cases/foo.toml` gives `foo`)");
    name.empty_text = "must not be empty";
    bind_text<Case>(name, [](Case& c) -> std::string& { return c.name; });
    return s;
}

SectionSpec beam_section() {
    SectionSpec s = table_section<Beam>("beam", true);
    bind_member(s.add_key(number_key("length", Dimension::length)).require().in(positive()).means("l"), &Beam::length);
    bind_member(s.add_key(number_key("width", Dimension::length)).require().in(positive()).means("w"), &Beam::width);
    bind_member(s.add_key(number_key("thickness", Dimension::length)).require().in(positive())
                    .means("t (the bending direction)"),
                &Beam::thickness);
    KeySpec& m = s.add_key(integer_key("elements")).require();
    m.means("m, elements of the uniform mesh before the supports get their nodes (a grid node within 0.1 of an "
            "element of a support moves onto it; otherwise a node is added there: docs/model.md §3); for a "
            "transient at most " + std::to_string(kMaxExactElements) + " ([Limits](#limits))");
    m.range = interval(1, false, kMaxElements, false);
    m.range.too_low = "must be at least 1";
    m.range.too_high = "must be at most " + std::to_string(kMaxElements) +
                       ": the roundoff of the stiffness matrix grows like 5 m^4, so finer meshes only lose digits "
                       "(docs/case-files.md, Limits)";
    bind_member(m, &Beam::elements);
    bind_choice<Beam>(s.add_key(choice_key("left", kEnds)).otherwise(std::string("clamped")).means("end condition at x = 0"),
                      [](Beam& b) -> EndCondition& { return b.left; }, kEndValues);
    bind_choice<Beam>(s.add_key(choice_key("right", kEnds)).otherwise(std::string("free")).means("end condition at x = l"),
                      [](Beam& b) -> EndCondition& { return b.right; }, kEndValues);
    // Residual stress and stretching act only where both ends hold the axis; check_case refuses a
    // nonzero stress or stretching otherwise (a path may still set them: the check then names them).
    KeySpec& stress = s.add_key(number_key("residual_stress", Dimension::pressure)).otherwise(0.0);
    stress.means("sigma0, the residual axial stress, tension positive; the axial force N0 = sigma0 w t adds the "
                 "geometric stiffness N0 int N_i' N_j' dx to K (modes, static states and transients all see it). "
                 "Only with both ends clamped or pinned; a compression must stay below Euler's buckling stress "
                 "(docs/electrostatics.md §8)");
    bind_member(stress, &Beam::residual_stress);
    KeySpec& stretch = s.add_key(flag_key("stretching")).otherwise(std::string("false"));
    stretch.means("mid-plane stretching: the axial force (E A / (2 l)) int v'^2 dx of a beam whose ends hold its axis, "
                  "a nonlinear force element (transients then need CVODE). Only with both ends clamped or pinned");
    bind_member(stretch, &Beam::stretching);
    return s;
}

SectionSpec material_section() {
    SectionSpec s = table_section<Material>("material", true);
    bind_member(s.add_key(number_key("youngs_modulus", Dimension::pressure)).require().in(positive()).means("E"),
                &Material::youngs_modulus);
    bind_member(s.add_key(number_key("density", Dimension::density)).require().in(positive()).means("rho"),
                &Material::density);
    bind_member(s.add_key(number_key("poisson_ratio", Dimension::dimensionless)).require()
                    .in(interval(-1.0, true, 0.5, true)).means("nu"),
                &Material::poisson_ratio);
    bind_member(s.add_key(flag_key("plate_modulus")).otherwise(std::string("false"))
                    .means("use E / (1 - nu^2) in the stiffness (wide beams)"),
                &Material::plate_modulus);
    return s;
}

SectionSpec beam_sections_section() {
    SectionSpec s;
    s.name = "beam.sections";
    s.array = true;
    s.entry_word = "section";
    s.count = [](const Case& c) { return c.beam.sections.size(); };
    s.add = [](Case& c) { c.beam.sections.emplace_back(); };
    s.exclusive = {{"thickness", "layers"}};
    bind_member(s.add_key(number_key("from", Dimension::dimensionless, "x/l")).require()
                    .in(interval(0, false, 1, false, " (x/l)")).means("where the section starts"),
                &BeamSection::from);
    bind_member(s.add_key(number_key("to", Dimension::dimensionless, "x/l")).require()
                    .in(interval(0, false, 1, false, " (x/l)"))
                    .means("where it ends; the sections, in order, cover the beam from 0 to 1 without gaps or overlaps"),
                &BeamSection::to);
    KeySpec& w = s.add_key(number_key("width", Dimension::length)).in(positive());
    w.means("w of this section (electrodes and films over it use it too)");
    w.default_text = "beam.width";
    bind_optional<BeamSection>(w, [](BeamSection& x) -> std::optional<double>& { return x.width; });
    KeySpec& t = s.add_key(number_key("thickness", Dimension::length)).in(positive());
    t.only(when<BeamSection>([](const BeamSection& x) { return x.layers.empty(); }, {"layers"},
                             "cannot be combined with $.layers (the layers' thicknesses give it)",
                             "the section has layers; set their thicknesses in the case file"));
    t.when.doc_text = "no `layers`";
    t.means("t of this section, of [material]");
    t.default_text = "beam.thickness (or the layers' sum)";
    bind_optional<BeamSection>(t, [](BeamSection& x) -> std::optional<double>& { return x.thickness; });
    KeySpec& layers = s.add_key(layer_stack_key("layers"));
    layers.means("the stack, bottom to top, each layer of a [[materials]] entry: the transformed section gives the "
                 "neutral axis, EI, EA and rho A; the layers' residual stresses the axial force of a beam whose ends "
                 "hold the axis and the released curl (docs/model.md, sections and layers)");
    layers.default_text = "one layer of [material]";
    layers.layers = [](Case& c, std::size_t i) { return &c.beam.sections[i].layers; };
    layers.is_set = [](const Case& c, std::size_t i) { return !c.beam.sections[i].layers.empty(); };
    KeySpec& holes = s.add_key(hole_array_key("holes"));
    holes.means("release holes through the section in a square array, each a square of side `size` (or a circle of "
                "diameter `size`) at `pitch` along and across: the ligament efficiency sets EI and EA, the solid "
                "fraction rho A and the area of electrodes under it, and the holes vent the squeeze film "
                "(docs/model.md, perforated sections; docs/squeeze-film.md §9)");
    holes.default_text = "none (solid)";
    holes.holes = [](Case& c, std::size_t i) { return &c.beam.sections[i].holes; };
    holes.is_set = [](const Case& c, std::size_t i) { return c.beam.sections[i].holes.has_value(); };
    const KeyCondition holed = when<BeamSection>([](const BeamSection& x) { return x.holes.has_value(); }, {},
                                                 "needs $.holes", "the section has no holes (give them in the case file "
                                                                  "to vary their size or pitch)");
    for (const bool size : {true, false}) {
        KeySpec part = number_key(size ? "size" : "pitch", Dimension::length).in(positive()).only(holed);
        part.set_refuses_out_of_range = true;
        part.means(size ? "the holes' side (square) or diameter (circle)" : "their spacing, along and across");
        part.get_number = [size](const Case& c, std::size_t i, std::size_t) {
            const Holes& h = *c.beam.sections[i].holes;
            return size ? h.size : h.pitch;
        };
        part.set_number = [size](Case& c, std::size_t i, std::size_t, double v) {
            Holes& h = *c.beam.sections[i].holes;
            (size ? h.size : h.pitch) = v;
        };
        holes.parts.push_back(std::move(part));
    }
    return s;
}

SectionSpec materials_section() {
    SectionSpec s;
    s.name = "materials";
    s.array = true;
    s.entry_word = "material";
    s.count = [](const Case& c) { return c.materials.size(); };
    s.add = [](Case& c) { c.materials.emplace_back(); };
    KeySpec& name = s.add_key(text_key("name")).require();
    name.means("how a section's layers name it; unique");
    name.empty_text = "must not be empty";
    bind_text<LayerMaterial>(name, [](LayerMaterial& m) -> std::string& { return m.name; });
    bind_member(s.add_key(number_key("youngs_modulus", Dimension::pressure)).require().in(positive()).means("E"),
                &LayerMaterial::youngs_modulus);
    bind_member(s.add_key(number_key("density", Dimension::density)).require().in(positive()).means("rho"),
                &LayerMaterial::density);
    bind_member(s.add_key(number_key("poisson_ratio", Dimension::dimensionless)).require()
                    .in(interval(-1.0, true, 0.5, true)).means("nu (E / (1 - nu^2) with material.plate_modulus)"),
                &LayerMaterial::poisson_ratio);
    bind_member(s.add_key(number_key("residual_stress", Dimension::pressure)).otherwise(0.0)
                    .means("sigma_r, the layer's in-plane stress while the beam is held straight and at length, tension "
                           "positive"),
                &LayerMaterial::residual_stress);
    bind_member(s.add_key(number_key("stress_gradient", Dimension::dimensionless, "Pa/m")).otherwise(0.0)
                    .means("Gamma, how that stress grows toward the layer's top (it adds the moment Gamma w t^3 / 12)"),
                &LayerMaterial::stress_gradient);
    return s;
}

SectionSpec damping_section() {
    SectionSpec s = table_section<RayleighDamping>("damping", false);
    s.exclusive = {{"ratios", "alpha"}, {"ratios", "beta"}};
    // Ratios given in the file decide which pair of keys the section holds.
    s.before = [](Case& c, std::size_t, const std::function<bool(std::string_view)>& has) {
        c.damping.from_ratios = has("ratios");
    };
    const std::string no_ratios = "the case gives no damping.ratios (add them to the case file to sweep them)";
    KeyCondition ratios = when<RayleighDamping>([](const RayleighDamping& d) { return d.from_ratios; }, {},
                                                "needs damping.ratios (the modes the ratios refer to)", no_ratios);
    KeySpec& r = s.add_key(number_pair_key("ratios")).in(non_negative()).only(ratios);
    r.when.doc_text = "-";
    r.means("damping ratios xi1, xi2 at two bending modes; alpha and beta follow from them");
    bind<RayleighDamping>(r, [](RayleighDamping& d, std::size_t k) -> double& { return k == 0 ? d.ratio1 : d.ratio2; });
    // Mode numbers above the mesh's are refused when the modes are computed (naming this key).
    KeySpec& m = s.add_key(integer_pair_key("modes")).only(ratios);
    m.range.lo = 1.0;
    m.range.too_low = "mode numbers start at 1";
    m.otherwise(1.0, "`[1, 2]`").default_numbers = {1.0, 2.0};
    m.when.doc_text = "`ratios`";
    m.means("the bending mode numbers (1-based, beam without supports) the ratios refer to; must differ");
    bind<RayleighDamping>(m, [](RayleighDamping& d, std::size_t k) -> int& { return k == 0 ? d.mode1 : d.mode2; });
    KeyCondition direct = when<RayleighDamping>(
        [](const RayleighDamping& d) { return !d.from_ratios; }, {}, "cannot be combined with damping.ratios",
        "the case gives damping.ratios; sweep damping.ratios[0] or damping.ratios[1]", "no `ratios`");
    bind_member(s.add_key(number_key("alpha", Dimension::mass_damping)).otherwise(0.0).in(non_negative()).only(direct)
                    .means("mass-proportional coefficient"),
                &RayleighDamping::alpha);
    bind_member(s.add_key(number_key("beta", Dimension::time)).otherwise(0.0).in(non_negative()).only(direct)
                    .means("stiffness-proportional coefficient"),
                &RayleighDamping::beta);
    return s;
}

SectionSpec initial_section() {
    using Kind = InitialState::Kind;
    using Velocity = InitialState::Velocity;
    SectionSpec s = table_section<InitialState>("initial", false);
    // Without [initial] the transient starts from the static equilibrium at rest.
    s.absent = [](Case& c) { c.initial.kind = Kind::rest; };
    s.before = [](Case& c, std::size_t, const std::function<bool(std::string_view)>& has) {
        if (!has("velocity_shape")) c.initial.velocity_kind = has("velocity") ? Velocity::uniform : Velocity::none;
    };
    KeySpec& kind = s.add_key(choice_key("kind", {"rest", "displacement", "force"}));
    kind.otherwise(std::string("displacement"), "`\"displacement\"` (`\"rest\"` without the table)");
    kind.means("`\"rest\"`: start in the equilibrium; `\"displacement\"`: lift the point at `position` by "
               "`displacement` above the equilibrium with a static point force there; `\"force\"`: apply the static "
               "point force `force` there");
    bind_choice<InitialState>(kind, [](InitialState& x) -> Kind& { return x.kind; },
                              std::vector<Kind>{Kind::rest, Kind::displacement, Kind::force});
    bind_member(s.add_key(number_key("position", Dimension::dimensionless, "x/l")).otherwise(1.0, "1 (the right end)")
                    .in(interval(0, true, 1, false, " (x/l)"))
                    .means("x/l of the lifted or loaded point (and of the point whose velocity `velocity_shape = "
                           "\"mode\"` sets)"),
                &InitialState::position);
    const auto of_kind = [](Kind k, const char* name) {
        return when<InitialState>([k](const InitialState& x) { return x.kind == k; }, {"kind"},
                                  std::string("only with $.kind = \"") + name + "\"");
    };
    bind_member(s.add_key(number_key("displacement", Dimension::length)).require().only(of_kind(Kind::displacement, "displacement"))
                    .means("y0, the lift above the equilibrium, positive up"),
                &InitialState::displacement);
    bind_member(s.add_key(number_key("force", Dimension::force)).require().only(of_kind(Kind::force, "force"))
                    .means("the static point force, positive up"),
                &InitialState::force);
    KeySpec& shape = s.add_key(choice_key("velocity_shape", {"none", "uniform", "mode"}));
    shape.otherwise(std::string("none"), "`\"uniform\"` when `velocity` is given, else `\"none\"`");
    shape.means("initial velocity field: `\"none\"` (release from rest); `\"uniform\"`: every transverse DOF moves at "
                "`velocity`, rotations at 0; `\"mode\"`: along the unsupported bending mode `velocity_mode`, scaled so "
                "that the point at `position` moves at `velocity`");
    bind_choice<InitialState>(shape, [](InitialState& x) -> Velocity& { return x.velocity_kind; },
                              std::vector<Velocity>{Velocity::none, Velocity::uniform, Velocity::mode});
    bind_member(s.add_key(number_key("velocity", Dimension::velocity)).require()
                    .only(when<InitialState>([](const InitialState& x) { return x.velocity_kind != Velocity::none; },
                                             {"velocity_shape"}, "only with $.velocity_shape = \"uniform\" or \"mode\"",
                                             "only with an initial velocity (initial.velocity_shape not \"none\")"))
                    .means("the velocity, positive up"),
                &InitialState::velocity);
    KeySpec& mode = s.add_key(integer_key("velocity_mode")).otherwise(1.0);
    mode.range.lo = 1.0;  // the "must be at least 1" of a lower bound; one above the mesh's modes is refused when they are computed
    mode.only(when<InitialState>([](const InitialState& x) { return x.velocity_kind == Velocity::mode; },
                                 {"velocity_shape"}, "only with $.velocity_shape = \"mode\""));
    mode.means("the bending mode number (1-based, beam without supports)");
    bind_member(mode, &InitialState::velocity_mode);
    return s;
}

const CaseSchema& builtin_case_schema_sections() {
    static const CaseSchema schema{{top_level_section(), beam_section(), beam_sections_section(), material_section(),
                                    materials_section(), supports_section(),
                                    damping_section(), initial_section(), loads_section(), electrodes_section(),
                                    air_section(), films_section(), solver_section()}};
    return schema;
}

}  // namespace vi::schema

namespace vi {

const CaseSchema& builtin_case_schema() { return schema::builtin_case_schema_sections(); }

}  // namespace vi
