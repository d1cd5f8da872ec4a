// Case paths of sweeps: every accepted path reads and writes its own value, and each kind of bad
// path is refused with a reason naming what is wrong.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sweep/case_paths.hpp"
#include "case_text_fixture.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "model/case_checks.hpp"

namespace vi {
namespace {

// The base case with two supports, ratio damping, a harmonic and a step load, a displacement step
// with a modal velocity: every path has something to address.
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
                             "[air]\npressure = \"100 Pa\"\n"
                             "[solver]\nhorizon = \"50 us\"\n";
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

TEST(SweepCasePaths, EveryFormReadsBackWhatWasSet) {
    const Case full = full_case();
    const Case alpha = alpha_case();
    Case by_velocity = full;  // solver.settle_velocity means something only with the velocity rule
    by_velocity.solver.settle_rule = SolverSettings::SettleRule::velocity;
    by_velocity.solver.settle_velocity = 1e-3;
    int checked = 0;
    for (const std::string& form : case_path_forms()) {
        std::string text = instance(form);
        const bool needs_alpha = text == "damping.alpha" || text == "damping.beta" || text == "initial.force";
        const Case& base = needs_alpha ? alpha : text == "solver.settle_velocity" ? by_velocity : full;
        if (text.rfind("loads[1].", 0) == 0 && (text.find("frequency") != std::string::npos ||
                                                text.find("phase") != std::string::npos ||
                                                text.find("offset") != std::string::npos)) {
            text[6] = '0';  // the harmonic load is loads[0]
        }
        if (text == "electrodes[1].frequency") text[11] = '0';  // the sine electrode is electrodes[0]
        SCOPED_TRACE(text);
        const CasePath p = resolve_case_path(text, base);
        EXPECT_EQ(p.text(), text);
        Case c = base;
        const double value = is_integer_path(p) ? 4.0 : 0.375;
        set_case_value(c, p, value);
        EXPECT_EQ(get_case_value(c, p), value);
        EXPECT_FALSE(case_path_unit(p).empty());
        ++checked;
    }
    EXPECT_EQ(checked, 55);  // 47, the adhesion keys (3), the air keys (4) and solver.settle_velocity
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

TEST(SweepCasePaths, BadPathsSayWhatIsWrong) {
    const Case full = full_case();
    const Case alpha = alpha_case();
    const struct {
        const char* path;
        const Case* on;
        const char* reason;
    } cases[] = {
        {"supports[0].foo", &full, "unknown key 'foo' in supports[i] (accepted: position, gap,"},
        {"foo.bar", &full, "unknown key 'foo' (accepted: beam, material, supports[i],"},
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

}  // namespace
}  // namespace vi
