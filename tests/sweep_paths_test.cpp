// Case paths of sweeps: every accepted path reads and writes its own value, and each kind of bad
// path is refused with a reason naming what is wrong.

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "sweep/case_paths.hpp"
#include "case_text_fixture.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "model/case_checks.hpp"
#include "model/case_schema.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

namespace vi {
namespace {

// The base case with two supports, ratio damping, a harmonic and a step load, a displacement step
// with a modal velocity, electrodes with a sine, a step (on an adhesive layer), a pulse and a
// two-step drive, air and two film spans, two materials and two sections (one layered): every path
// has something to address.
Case full_case() {
    const std::string text = test::kBaseCase +
                             "[damping]\nratios = [0.01, 0.02]\nmodes = [1, 3]\n"
                             "[[supports]]\nposition = 1.0\ngap = \"1 um\"\nstiffness = \"100 N/m\"\ndamping = \"1e-6 N s/m\"\n"
                             "[[supports]]\nposition = 0.5\nside = \"above\"\nprestress = \"0.5 um\"\nstiffness = \"200 N/m\"\n"
                             "adhesion = \"jkr\"\nwork_of_adhesion = \"0.1 J/m^2\"\ncontact_radius = \"1 um\"\n"
                             "damping_ratio = 0.1\n"
                             "[initial]\nkind = \"displacement\"\ndisplacement = \"1 um\"\nvelocity_shape = \"mode\"\n"
                             "velocity = \"0.1 m/s\"\nvelocity_mode = 2\n"
                             "[[loads]]\nposition = 0.8\namplitude = \"1 uN\"\nkind = \"harmonic\"\nfrequency = \"100 kHz\"\n"
                             "[[loads]]\nposition = 0.6\namplitude = \"2 uN\"\nkind = \"step\"\nt_on = \"1 us\"\n"
                             "[[electrodes]]\nfrom = 0.1\nto = 0.5\ngap = \"2 um\"\nvoltage = \"5 V\"\nwaveform = \"sine\"\nfrequency = \"1 kHz\"\n"
                             "[[electrodes]]\nfrom = 0.2\nto = 0.9\ngap = \"2 um\"\ndielectric_thickness = \"0.1 um\"\nvoltage = \"5 V\"\nwaveform = \"step\"\nt_on = \"1 us\"\n"
                             "work_of_adhesion = \"0.01 J/m^2\"\n"
                             "[[electrodes]]\nfrom = 0.6\nto = 0.7\ngap = \"3 um\"\nvoltage = \"5 V\"\nwaveform = \"pulse\"\nrise = \"1 us\"\nhold = \"2 us\"\nfall = \"1 us\"\n"
                             "[[electrodes]]\nfrom = 0.7\nto = 0.8\ngap = \"3 um\"\nvoltage = \"5 V\"\nwaveform = \"two_step\"\nrise = \"10 ns\"\nlevel = 0.8\nhold = \"2 us\"\n"
                             "[air]\npressure = \"100 Pa\"\n"
                             "[[films]]\nfrom = 0.0\nto = 0.05\ngap = \"1 um\"\n"
                             "[[films]]\nfrom = 0.92\nto = 0.95\nside = \"above\"\ngap = \"1 um\"\n"
                             "[solver]\nhorizon = \"50 us\"\n"
                             "[[materials]]\nname = \"a\"\nyoungs_modulus = \"100 GPa\"\ndensity = \"5000 kg/m^3\"\npoisson_ratio = 0.3\n"
                             "[[materials]]\nname = \"b\"\nyoungs_modulus = \"80 GPa\"\ndensity = \"9000 kg/m^3\"\npoisson_ratio = 0.4\n"
                             "[[beam.sections]]\nfrom = 0\nto = 0.5\n"
                             "layers = [{ material = \"a\", thickness = \"1 um\" }, { material = \"b\", thickness = \"1 um\" }]\n"
                             "[[beam.sections]]\nfrom = 0.5\nto = 1\nwidth = \"20 um\"\nthickness = \"1.5 um\"\n"
                             "holes = { size = \"2 um\", pitch = \"5 um\" }\n";
    return read_case_text(text, "full.toml");
}

// The same case with alpha/beta damping and a force step without velocity.
Case alpha_case() {
    const std::string text = test::kBaseCase + "[damping]\nalpha = \"100 1/s\"\nbeta = \"1e-9 s\"\n" +
                             "[initial]\nkind = \"force\"\nforce = \"1 uN\"\n";
    return read_case_text(text, "alpha.toml");
}

// A concrete path for a form of case_path_forms ("supports[i].gap" -> "supports[1].gap").
std::string instance(std::string form) {
    for (const char* from : {"[i]", "[k]"}) {
        const auto at = form.find(from);
        if (at != std::string::npos) form.replace(at, 3, "[1]");
    }
    return form;
}

std::string error_of(const std::string& path, const Case& c) {
    try {
        resolve_case_path(path, c);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// The registered section (register_section) a path leads into, or null for a built-in one.
const SectionSpec* registered_section(const std::string& path) {
    const SectionSpec* s = case_schema().section(path.substr(0, path.find_first_of(".[")));
    return s != nullptr && s->registered ? s : nullptr;
}

TEST(SweepCasePaths, EveryFormReadsBackWhatWasSet) {
    const Case full = full_case();
    const Case alpha = alpha_case();
    Case by_velocity = full;  // solver.settle_velocity means something only with the velocity rule
    by_velocity.solver.settle_rule = SolverSettings::SettleRule::velocity;
    by_velocity.solver.settle_velocity = 1e-3;
    // A Hertz support (supports[1].law = "hertz", a law its family registers): its keys apply there,
    // the counter-surface's modulus and Poisson ratio only without effective_modulus.
    Case hertz = full;
    hertz.supports[1].params.texts["law"] = "hertz";
    Case hertz_star = hertz;
    hertz_star.supports[1].params.numbers["effective_modulus"] = 5e10;
    const auto hertz_key = [](const std::string& t) {
        for (const char* key : {".radius", ".restitution", ".reference_speed", ".resistivity", ".film_resistivity",
                                ".hardness", ".mean_free_path", ".r_on", ".youngs_modulus", ".poisson_ratio",
                                ".yield_strength", ".wear_coefficient"}) {
            if (t.rfind("supports[", 0) == 0 && t.size() > std::string(key).size() &&
                t.compare(t.size() - std::string(key).size(), std::string::npos, key) == 0) {
                return true;
            }
        }
        return false;
    };
    int checked = 0, registered = 0;
    for (const std::string& form : case_path_forms()) {
        std::string text = instance(form);
        const bool needs_alpha = text == "damping.alpha" || text == "damping.beta" || text == "initial.force";
        const bool star = text.rfind("supports[", 0) == 0 && text.find(".effective_modulus") != std::string::npos;
        const Case& base = needs_alpha                         ? alpha
                           : text == "solver.settle_velocity" ? by_velocity
                           : star                              ? hertz_star
                           : hertz_key(text)                   ? hertz
                                                               : full;
        if (text.rfind("loads[1].", 0) == 0 && (text.find("frequency") != std::string::npos ||
                                                text.find("phase") != std::string::npos ||
                                                text.find("offset") != std::string::npos)) {
            text[6] = '0';  // the harmonic load is loads[0]
        }
        // The sine electrode is electrodes[0], the pulse electrodes[2], the two-step drive electrodes[3].
        for (const char* key : {".frequency", ".phase", ".bias"}) {
            if (text == std::string("electrodes[1]") + key) text[11] = '0';
        }
        if (text == "electrodes[1].rise" || text == "electrodes[1].hold" || text == "electrodes[1].fall") text[11] = '2';
        if (text == "electrodes[1].level") text[11] = '3';
        SCOPED_TRACE(text);
        // A section a force family registers: on the full case with entries of it added (two of an
        // array, for the [1] of the path), so that a new section needs nothing here.
        const SectionSpec* own = registered_section(text);
        Case with_entries = full;
        while (own != nullptr && own->count(with_entries) < (own->array ? 2u : 1u)) add_entry(*own, with_entries);
        const Case& at = own != nullptr ? with_entries : base;
        const CasePath p = resolve_case_path(text, at);
        EXPECT_EQ(p.text(), text);
        Case c = at;
        const double value = is_integer_path(p) ? 4.0 : 0.375;
        set_case_value(c, p, value);
        EXPECT_EQ(get_case_value(c, p), value);
        EXPECT_FALSE(case_path_unit(p).empty());
        ++(own != nullptr ? registered : checked);
    }
    std::printf("[ paths ] %d paths of registered sections\n", registered);
    // 47, the adhesion keys (3), the air keys (4), solver.settle_velocity and the waveform's shape
    // keys beyond t_on and frequency (rise, hold, fall, level, phase, bias); since every number of the
    // schema is a path, the electrode's dielectric_modulus, work_of_adhesion, adhesion_range and
    // width, and the film's from, to and gap; the Hertz law's 13 numbers; solver.field_step.
    // The sections' from, to, width, thickness, holes.size and holes.pitch and the materials' five
    // numbers.
    EXPECT_EQ(checked, 93);
}

TEST(SweepCasePaths, ValuesLandWhereTheCaseFileWouldPutThem) {
    const Case base = full_case();
    Case c = base;
    set_case_value(c, resolve_case_path("supports[0].position", c), 0.75);
    EXPECT_EQ(c.supports[0].position, 0.75);
    EXPECT_EQ(c.supports[1].position, 0.5);
    set_case_value(c, resolve_case_path("beam.elements", c), 12);
    EXPECT_EQ(c.beam.elements, 12);
    set_case_value(c, resolve_case_path("damping.ratios[1]", c), 0.05);
    EXPECT_EQ(c.damping.ratio2, 0.05);
    EXPECT_EQ(c.damping.ratio1, 0.01);
    set_case_value(c, resolve_case_path("damping.modes[0]", c), 2);
    EXPECT_EQ(c.damping.mode1, 2);
    set_case_value(c, resolve_case_path("loads[1].t_on", c), 3e-6);
    EXPECT_EQ(c.loads[1].time.t_on, 3e-6);
    set_case_value(c, resolve_case_path("solver.horizon", c), 2e-5);
    EXPECT_EQ(c.solver.horizon, 2e-5);
    EXPECT_TRUE(check_case(c).empty());
}

TEST(SweepCasePaths, GapAndPrestressAreTwoViewsOfTheSurface) {
    Case c = full_case();
    const CasePath gap = resolve_case_path("supports[0].gap", c);
    const CasePath pre = resolve_case_path("supports[0].prestress", c);
    EXPECT_DOUBLE_EQ(get_case_value(c, gap), 1e-6);
    EXPECT_DOUBLE_EQ(get_case_value(c, pre), -1e-6);
    set_case_value(c, pre, 2e-7);
    EXPECT_EQ(c.supports[0].surface, 2e-7);
    EXPECT_EQ(c.supports[0].surface_key, "prestress");
    set_case_value(c, gap, 3e-7);
    EXPECT_EQ(c.supports[0].surface, -3e-7);
    EXPECT_EQ(c.supports[0].surface_key, "gap");
    EXPECT_THROW(set_case_value(c, gap, -1e-7), InputError);
    EXPECT_THROW(set_case_value(c, pre, -1e-7), InputError);
}

TEST(SweepCasePaths, DampingAndDampingRatioReplaceEachOther) {
    Case c = full_case();
    set_case_value(c, resolve_case_path("supports[1].damping", c), 2e-6);
    EXPECT_FALSE(c.supports[1].damping_ratio.has_value());
    EXPECT_EQ(c.supports[1].damping, 2e-6);
    set_case_value(c, resolve_case_path("supports[0].damping_ratio", c), 0.3);
    EXPECT_EQ(c.supports[0].damping_ratio, 0.3);
    EXPECT_EQ(c.supports[0].damping, 0.0);
}

TEST(SweepCasePaths, IntegerPathsRefuseFractions) {
    Case c = full_case();
    const CasePath p = resolve_case_path("beam.elements", c);
    EXPECT_TRUE(is_integer_path(p));
    EXPECT_FALSE(is_integer_path(resolve_case_path("beam.length", c)));
    EXPECT_THROW(set_case_value(c, p, 10.5), InputError);
    EXPECT_THROW(set_case_value(c, p, 1e12), InputError);
}

// A message of InputError thrown by f, or "" when none is.
template <class F>
std::string input_error_of(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(SweepCasePaths, TextValuesTakeThePathsUnitsAsSetDoes) {
    Case c = full_case();
    set_case_text(c, "supports[0].gap", "0.5 um");
    EXPECT_DOUBLE_EQ(c.supports[0].surface, -0.5e-6);
    set_case_text(c, "supports[0].gap", "2.5e-7");  // a plain number is SI
    EXPECT_DOUBLE_EQ(c.supports[0].surface, -2.5e-7);
    set_case_text(c, "material.youngs_modulus", "150GPa");
    EXPECT_DOUBLE_EQ(c.material.youngs_modulus, 150e9);
    set_case_text(c, "supports[1].position", "0.25");
    EXPECT_EQ(c.supports[1].position, 0.25);
    set_case_text(c, "beam.elements", "12");
    EXPECT_EQ(c.beam.elements, 12);
    EXPECT_TRUE(check_case(c).empty());

    const Case before = c;
    const std::string wrong_unit = input_error_of([&] { set_case_text(c, "supports[0].gap", "0.5 kg"); });
    EXPECT_EQ(wrong_unit.rfind("supports[0].gap: ", 0), 0u) << wrong_unit;
    EXPECT_NE(wrong_unit.find("kg"), std::string::npos) << wrong_unit;
    const std::string no_unit_here = input_error_of([&] { set_case_text(c, "supports[1].position", "0.5 um"); });
    EXPECT_EQ(no_unit_here.rfind("supports[1].position: ", 0), 0u) << no_unit_here;
    const std::string fraction = input_error_of([&] { set_case_text(c, "beam.elements", "10.5"); });
    EXPECT_EQ(fraction, "beam.elements: must be a whole number");
    const std::string bad_path = input_error_of([&] { set_case_text(c, "suports[0].gap", "1 um"); });
    EXPECT_EQ(bad_path.rfind("suports[0].gap: ", 0), 0u) << bad_path;
    EXPECT_NE(bad_path.find("supports"), std::string::npos) << bad_path;
    EXPECT_EQ(c.supports[0].surface, before.supports[0].surface);
    EXPECT_EQ(c.beam.elements, before.beam.elements);
}

TEST(SweepCasePaths, BadPathsSayWhatIsWrong) {
    const Case full = full_case();
    const Case alpha = alpha_case();
    const struct {
        const char* path;
        const Case* on;
        const char* reason;
    } cases[] = {
        {"supports[0].foo", &full, "unknown key 'foo' in supports[i] (accepted: position, gap,"},
        {"foo.bar", &full, "unknown key 'foo' (accepted: beam, beam.sections[i], material, materials[i], supports[i],"},
        {"supports[0].stifness", &full, "unknown key 'stifness' in supports[i] (did you mean 'stiffness'?)"},
        {"suports[0].gap", &full, "unknown key 'suports' (did you mean 'supports'?)"},
        {"supports[2].position", &full, "supports[2]: index out of range (the case has 2 supports)"},
        {"loads[0].amplitude", &alpha, "loads[0]: index out of range (the case has 0 loads)"},
        {"supports.position", &full, "supports: needs an index, like supports[0].position"},
        {"supports", &full, "supports: needs an index and a key"},
        {"beam", &full, "beam: needs a key (length, width, thickness, elements, residual_stress)"},
        {"beam[0].length", &full, "beam: takes no index"},
        {"beam.length[0]", &full, "beam.length: takes no index"},
        {"damping.ratios", &full, "damping.ratios: needs an index, [0] or [1]"},
        {"damping.ratios[2]", &full, "damping.ratios[2]: index out of range (0 or 1)"},
        {"damping.alpha", &full, "damping.alpha: the case gives damping.ratios"},
        {"damping.ratios[0]", &alpha, "damping.ratios[0]: the case gives no damping.ratios"},
        {"initial.force", &full, "initial.force: only with initial.kind = \"force\""},
        {"initial.velocity", &alpha, "initial.velocity: only with an initial velocity"},
        {"loads[1].frequency", &full, "loads[1].frequency: only for a load of kind \"harmonic\""},
        {"loads[0].t_on", &full, "loads[0].t_on: only for a load of kind \"step\""},
        {"electrodes[1].rise", &full, "electrodes[1].rise: only for waveform = \"ramp\", \"pulse\" or \"two_step\""},
        {"electrodes[2].level", &full, "electrodes[2].level: only for waveform = \"two_step\""},
        {"electrodes[0].t_on", &full, "electrodes[0].t_on: only for waveform = \"step\", \"ramp\", \"pulse\" or"},
        {"electrodes[3].bias", &full, "electrodes[3].bias: only for waveform = \"sine\""},
        {"supports[x].position", &full, "supports: expected an index in brackets"},
        {"Beam.length", &full, "is not a path like"},
        {"beam.length ", &full, "is not a path like"},
        {"", &full, "is not a path like"},
    };
    for (const auto& k : cases) {
        const std::string err = error_of(k.path, *k.on);
        EXPECT_NE(err.find(k.reason), std::string::npos) << k.path << " -> " << err;
        EXPECT_EQ(err.find('\n'), std::string::npos) << k.path;
    }
}

// A shape key set by a sweep builds the waveform again, exactly as a case file with that value
// would: the two-step drive, the pulse's start, the sine's bias (volts, kept when the voltage
// changes), and a ramp's voltage (a ramp is a table inside, but not a table waveform).
TEST(SweepCasePaths, WaveformShapeKeysBuildTheWaveformAsACaseFileWould) {
    const Case base = full_case();
    Case c = base;
    set_case_value(c, resolve_case_path("electrodes[3].rise", c), 20e-9);
    set_case_value(c, resolve_case_path("electrodes[3].level", c), 0.5);
    set_case_value(c, resolve_case_path("electrodes[3].hold", c), 3e-6);
    set_case_value(c, resolve_case_path("electrodes[2].t_on", c), 4e-6);
    set_case_value(c, resolve_case_path("electrodes[0].bias", c), 2.0);
    set_case_value(c, resolve_case_path("electrodes[0].phase", c), 0.5);
    set_case_value(c, resolve_case_path("electrodes[0].voltage", c), 4.0);
    EXPECT_TRUE(check_case(c).empty());
    std::string text = test::kBaseCase +
                       "[damping]\nratios = [0.01, 0.02]\nmodes = [1, 3]\n"
                       "[[supports]]\nposition = 1.0\ngap = \"1 um\"\nstiffness = \"100 N/m\"\n"
                       "[[electrodes]]\nfrom = 0.1\nto = 0.5\ngap = \"2 um\"\nvoltage = \"4 V\"\nwaveform = \"sine\"\n"
                       "frequency = \"1 kHz\"\nphase = 0.5\nbias = \"2 V\"\n"
                       "[[electrodes]]\nfrom = 0.2\nto = 0.9\ngap = \"2 um\"\nvoltage = \"5 V\"\nwaveform = \"step\"\n"
                       "[[electrodes]]\nfrom = 0.6\nto = 0.7\ngap = \"3 um\"\nvoltage = \"5 V\"\nwaveform = \"pulse\"\n"
                       "t_on = \"4 us\"\nrise = \"1 us\"\nhold = \"2 us\"\nfall = \"1 us\"\n"
                       "[[electrodes]]\nfrom = 0.7\nto = 0.8\ngap = \"3 um\"\nvoltage = \"5 V\"\nwaveform = \"two_step\"\n"
                       "rise = \"20 ns\"\nlevel = 0.5\nhold = \"3 us\"\n";
    const Case file = read_case_text(text, "file.toml");
    for (std::size_t i : {0u, 2u, 3u}) {
        SCOPED_TRACE(i);
        const TimeFunction& a = c.electrodes[i].time;
        const TimeFunction& b = file.electrodes[i].time;
        EXPECT_EQ(a.kind, b.kind);
        EXPECT_EQ(a.times, b.times);
        EXPECT_EQ(a.values, b.values);
        EXPECT_EQ(a.frequency_hz, b.frequency_hz);
        EXPECT_EQ(a.phase, b.phase);
        EXPECT_EQ(a.offset, b.offset);
    }
    const TimeFunction& two = c.electrodes[3].time;
    EXPECT_EQ(two.values, (std::vector<double>{0.0, 0.5, 0.5, 1.0}));
    EXPECT_DOUBLE_EQ(two(1e-6), 0.5);
    EXPECT_DOUBLE_EQ(two(4e-6), 1.0);
    EXPECT_EQ(c.electrodes[0].time.offset, 0.5);  // 2 V of bias over 4 V of amplitude
    set_case_value(c, resolve_case_path("electrodes[0].voltage", c), 8.0);
    EXPECT_EQ(c.electrodes[0].time.offset, 0.25) << "the bias stays 2 V when the amplitude changes";

    Case ramp = read_case_text(test::kBaseCase + "[[electrodes]]\nfrom = 0.1\nto = 0.9\ngap = \"2 um\"\n"
                                                 "voltage = \"5 V\"\nwaveform = \"ramp\"\nrise = \"1 us\"\n",
                               "ramp.toml");
    set_case_value(ramp, resolve_case_path("electrodes[0].voltage", ramp), 7.0);
    set_case_value(ramp, resolve_case_path("electrodes[0].rise", ramp), 2e-6);
    EXPECT_EQ(ramp.electrodes[0].voltage, 7.0);
    EXPECT_EQ(ramp.electrodes[0].time.times, (std::vector<double>{0.0, 2e-6}));
}

// Set values are checked as a case file's: a negative rise, a hold of zero, a negative level, a
// bias with no amplitude are refused with the case file's own message, and a sweep point with
// one fails with it instead of running.
TEST(SweepCasePaths, WaveformShapeKeysAreCheckedAsInACaseFile) {
    const Case base = full_case();
    const struct {
        const char* path;
        double value;
        const char* problem;
    } bad[] = {
        {"electrodes[3].rise", -1e-9, "electrodes[3].rise: must be positive"},
        {"electrodes[2].hold", 0.0, "electrodes[2].hold: must be positive"},
        {"electrodes[2].fall", -1e-6, "electrodes[2].fall: must be positive"},
        {"electrodes[1].t_on", -1e-6, "electrodes[1].t_on: must not be negative"},
        {"electrodes[3].level", -0.5, "electrodes[3].level: must not be negative"},
        {"electrodes[0].frequency", 0.0, "electrodes[0].frequency: must be positive"},
    };
    for (const auto& b : bad) {
        SCOPED_TRACE(b.path);
        Case c = base;
        set_case_value(c, resolve_case_path(b.path, c), b.value);
        const std::vector<CaseProblem> problems = check_case(c);
        ASSERT_EQ(problems.size(), 1u);
        EXPECT_EQ(problems[0].key + ": " + problems[0].message, b.problem);
        const SweepGrid grid({SweepAxis{b.path, resolve_case_path(b.path, base), {b.value}}});
        const SweepPointResult r = run_sweep_point(base, grid, 0, SweepSettings{});
        EXPECT_EQ(r.status, std::string("error: ") + b.problem);
    }
    Case c = base;
    set_case_value(c, resolve_case_path("electrodes[0].bias", c), 1.0);
    set_case_value(c, resolve_case_path("electrodes[0].voltage", c), 0.0);
    const std::vector<CaseProblem> problems = check_case(c);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].key, "electrodes[0].voltage");
    // The same values in a case file: the same message, at the key's line.
    const std::string two_step = test::kBaseCase + "[[electrodes]]\nfrom = 0.1\nto = 0.9\ngap = \"2 um\"\n"
                                                   "voltage = \"5 V\"\nwaveform = \"two_step\"\nlevel = 0.5\n"
                                                   "hold = \"1 us\"\nrise = \"-1 ns\"\n";
    try {
        read_case_text(two_step, "bad.toml");
        ADD_FAILURE() << "a negative rise was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(": electrodes[0].rise: must be positive"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace vi
