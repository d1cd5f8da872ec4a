// Case files: good ones read to the expected SI values; each bad one fails with "FILE:LINE: KEY: reason".

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <string>

#include "io/case_reader.hpp"
#include "case_text_fixture.hpp"
#include "model/input_error.hpp"

namespace {

using vi::read_case_text;

const std::string& kBase = vi::test::kBaseCase;

// kBase with line n (1-based) replaced by `text` (which may hold several lines, or none: "").
std::string with_line(int n, const std::string& text, std::string base = kBase) {
    std::size_t begin = 0;
    for (int i = 1; i < n; ++i) begin = base.find('\n', begin) + 1;
    const std::size_t end = base.find('\n', begin);
    return base.replace(begin, end - begin + 1, text.empty() ? "" : text + "\n");
}

// kBase with `text` inserted as line n, pushing the old line n down.
std::string insert_line(int n, const std::string& text) {
    std::size_t begin = 0;
    for (int i = 1; i < n; ++i) begin = kBase.find('\n', begin) + 1;
    return std::string(kBase).insert(begin, text + "\n");
}

// A [[supports]] entry starting at line 11 when appended to kBase.
std::string support(const std::string& position, const std::string& extra = "") {
    return "[[supports]]\nposition = " + position + "\nstiffness = \"50 N/m\"\n" + extra;
}

// Reading text fails with a one-line message starting with prefix.
void expect_error(const std::string& text, const std::string& prefix) {
    try {
        read_case_text(text, "bad.toml");
        ADD_FAILURE() << "accepted:\n" << text;
    } catch (const vi::InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.substr(0, prefix.size()), prefix) << "full message: " << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(CaseReader, ReadsThePaperCantilever) {
    const vi::Case c = vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/cantilever.toml");
    EXPECT_EQ(c.name, "paper-cantilever");
    EXPECT_NEAR(c.beam.length, 117e-6, 1e-20);
    EXPECT_NEAR(c.beam.width, 30e-6, 1e-20);
    EXPECT_NEAR(c.beam.thickness, 2e-6, 1e-20);
    EXPECT_EQ(c.beam.elements, 50);
    EXPECT_EQ(c.beam.left, vi::EndCondition::clamped);
    EXPECT_EQ(c.beam.right, vi::EndCondition::free);
    EXPECT_DOUBLE_EQ(c.material.youngs_modulus, 207e9);
    EXPECT_DOUBLE_EQ(c.material.density, 8902.0);
    EXPECT_DOUBLE_EQ(c.material.poisson_ratio, 0.31);
    EXPECT_FALSE(c.material.plate_modulus);
    ASSERT_EQ(c.supports.size(), 1u);
    EXPECT_DOUBLE_EQ(c.supports[0].position, 1.0);
    EXPECT_EQ(c.supports[0].side, vi::Side::below);
    EXPECT_EQ(c.supports[0].surface, 0.0);
    EXPECT_DOUBLE_EQ(c.supports[0].stiffness, 1000.0);
    EXPECT_EQ(c.supports[0].damping, 0.0);
    ASSERT_TRUE(c.supports[0].damping_ratio.has_value());
    EXPECT_DOUBLE_EQ(*c.supports[0].damping_ratio, 0.2);
    EXPECT_FALSE(c.damping.from_ratios);
    EXPECT_EQ(c.damping.alpha, 0.0);
    EXPECT_EQ(c.damping.beta, 0.0);
    // The modal example has no [initial] or [solver]: rest, and no horizon.
    EXPECT_EQ(c.initial.kind, vi::InitialState::Kind::rest);
    EXPECT_EQ(c.solver.method, vi::SolverSettings::Method::automatic);
    EXPECT_EQ(c.solver.horizon, 0.0);
}

TEST(CaseReader, ReadsTheFreeImpactExample) {
    const vi::Case c = vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
    EXPECT_TRUE(c.damping.from_ratios);
    EXPECT_DOUBLE_EQ(c.damping.ratio1, 0.005);
    EXPECT_EQ(c.initial.kind, vi::InitialState::Kind::displacement);
    EXPECT_DOUBLE_EQ(c.initial.position, 1.0);
    EXPECT_DOUBLE_EQ(c.initial.displacement, 1e-6);
    EXPECT_EQ(c.initial.velocity_kind, vi::InitialState::Velocity::none);
    EXPECT_DOUBLE_EQ(c.solver.horizon, 150e-6);
    EXPECT_DOUBLE_EQ(c.solver.output_step, 10e-9);
}

TEST(CaseReader, NameDefaultsToTheFileStem) {
    const std::string path = ::testing::TempDir() + "/vi_stem_case.toml";
    std::ofstream(path) << with_line(1, "");
    EXPECT_EQ(vi::read_case_file(path).name, "vi_stem_case");
    EXPECT_EQ(read_case_text(with_line(1, ""), "dir/other.toml").name, "other");
}

TEST(CaseReader, ClampedClampedWithSupportsOfEveryKind) {
    const std::string text = insert_line(7, "left = \"clamped\"\nright = \"clamped\"") +
                             "plate_modulus = true\n"
                             "[[supports]]\nposition = 0.5\nside = \"above\"\nprestress = \"0.1 um\"\n"
                             "stiffness = \"2 kN/m\"\ndamping = \"1e-7 N s/m\"\n"
                             "[[supports]]\nposition = \"0.5\"\ngap = \"0.25 um\"\nstiffness = 50\n"
                             "damping_ratio = 0.05\n"
                             "[[supports]]\nposition = 0.75\nside = \"below\"\nstiffness = 30.5\n";
    const vi::Case c = read_case_text(text, "cc.toml");
    EXPECT_EQ(c.beam.left, vi::EndCondition::clamped);
    EXPECT_EQ(c.beam.right, vi::EndCondition::clamped);
    EXPECT_TRUE(c.material.plate_modulus);
    ASSERT_EQ(c.supports.size(), 3u);
    EXPECT_EQ(c.supports[0].side, vi::Side::above);
    EXPECT_DOUBLE_EQ(c.supports[0].surface, 1e-7);  // above: its surface at v = -0.1 um, over the one below
    EXPECT_DOUBLE_EQ(c.supports[0].stiffness, 2000.0);
    EXPECT_DOUBLE_EQ(c.supports[0].damping, 1e-7);
    EXPECT_EQ(c.supports[1].side, vi::Side::below);  // same place, other side: allowed
    EXPECT_DOUBLE_EQ(c.supports[1].position, 0.5);
    EXPECT_DOUBLE_EQ(c.supports[1].surface, -0.25e-6);
    EXPECT_DOUBLE_EQ(*c.supports[1].damping_ratio, 0.05);
    EXPECT_EQ(c.supports[2].surface, 0.0);
    EXPECT_DOUBLE_EQ(c.supports[2].stiffness, 30.5);
}

TEST(CaseReader, InlineTablesAndPinnedEnds) {
    const std::string text =
        "beam = { length = 1e-4, width = 3e-5, thickness = 2e-6, elements = 10, "
        "left = \"pinned\", right = \"pinned\" }\n"
        "material = { youngs_modulus = 2e11, density = 8900, poisson_ratio = 0 }\n"
        "supports = [ { position = 0.25, stiffness = 10 } ]\n";
    const vi::Case c = read_case_text(text, "inline.toml");
    EXPECT_EQ(c.beam.left, vi::EndCondition::pinned);
    EXPECT_DOUBLE_EQ(c.beam.length, 1e-4);
    EXPECT_EQ(c.beam.elements, 10);
    ASSERT_EQ(c.supports.size(), 1u);
    EXPECT_DOUBLE_EQ(c.supports[0].position, 0.25);
}

TEST(CaseReader, DampingByRatios) {
    vi::Case c = read_case_text(kBase + "[damping]\nratios = [0.01, 0.02]\nmodes = [1, 3]\n", "d.toml");
    EXPECT_TRUE(c.damping.from_ratios);
    EXPECT_DOUBLE_EQ(c.damping.ratio1, 0.01);
    EXPECT_DOUBLE_EQ(c.damping.ratio2, 0.02);
    EXPECT_EQ(c.damping.mode1, 1);
    EXPECT_EQ(c.damping.mode2, 3);
    c = read_case_text(kBase + "[damping]\nratios = [0, \"0.5\"]\n", "d.toml");
    EXPECT_EQ(c.damping.mode1, 1);
    EXPECT_EQ(c.damping.mode2, 2);
    EXPECT_DOUBLE_EQ(c.damping.ratio2, 0.5);
}

TEST(CaseReader, DampingByAlphaAndBeta) {
    vi::Case c = read_case_text(kBase + "[damping]\nalpha = \"100 1/s\"\nbeta = \"1e-10 s\"\n", "d.toml");
    EXPECT_FALSE(c.damping.from_ratios);
    EXPECT_DOUBLE_EQ(c.damping.alpha, 100.0);
    EXPECT_DOUBLE_EQ(c.damping.beta, 1e-10);
    c = read_case_text(kBase + "[damping]\nbeta = 2e-9\n", "d.toml");
    EXPECT_EQ(c.damping.alpha, 0.0);
    EXPECT_DOUBLE_EQ(c.damping.beta, 2e-9);
}

TEST(CaseReaderErrors, FileNotReadable) {
    try {
        vi::read_case_file("/nonexistent/dir/case.toml");
        ADD_FAILURE();
    } catch (const vi::InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/dir/case.toml: cannot read file", 0), 0u) << e.what();
    }
}

TEST(CaseReaderErrors, TomlSyntax) {
    expect_error(with_line(3, "length = "), "bad.toml:3: TOML syntax: ");
    expect_error(kBase + "[beam]\n", "bad.toml:11: TOML syntax: ");
}

TEST(CaseReaderErrors, UnknownKeys) {
    expect_error(with_line(1, "nmae = \"t\""), "bad.toml:1: nmae: unknown key 'nmae' (did you mean 'name'?)");
    expect_error(with_line(1, "zzzz = \"t\""), "bad.toml:1: zzzz: unknown key (accepted here: name, beam,");
    expect_error(kBase + "[output]\ntip = \"1 um\"\n", "bad.toml:11: output: unknown key");
    expect_error(kBase + "[initial]\nkind = \"rest\"\ntip = \"1 um\"\n", "bad.toml:13: initial.tip: unknown key");
    expect_error(insert_line(6, "colour = \"red\""), "bad.toml:6: beam.colour: unknown key");
    expect_error(kBase + support("1.0", "foo = 1\n"), "bad.toml:14: supports[0].foo: unknown key");
    expect_error(kBase + support("0.5") + support("1.0", "\"a\\nb\" = 1\n"),
                 "bad.toml:17: supports[1].\"a\\nb\": unknown key");
    expect_error(kBase + "[damping]\nratio = [0.01, 0.02]\n", "bad.toml:12: damping.ratio: unknown key");
}

// A misspelled key is reported as such at its own line, not as the required key it stands for
// (which would point at the table's first line and leave the user searching).
TEST(CaseReaderErrors, MisspelledKeyIsNamedWithTheKeyItMeans) {
    expect_error(kBase + "[[supports]]\nposition = 1.0\nstifness = 1e3\n",
                 "bad.toml:13: supports[0].stifness: unknown key 'stifness' (did you mean 'stiffness'?)");
    expect_error(with_line(3, "lenght = \"100 um\""), "bad.toml:3: beam.lenght: unknown key 'lenght' (did you mean 'length'?)");
    const std::string no_beam = kBase.substr(0, kBase.find("[beam]")) + "[bem]" + kBase.substr(kBase.find("[beam]") + 6);
    expect_error(no_beam, "bad.toml:2: bem: unknown key 'bem' (did you mean 'beam'?)");
    // A key already present is not suggested again: a second "stiffness" would be a duplicate.
    expect_error(kBase + "[[supports]]\nposition = 1.0\nstiffness = 1e3\nstifness = 1e3\n",
                 "bad.toml:14: supports[0].stifness: unknown key (accepted here:");
}

TEST(CaseReaderErrors, MissingRequired) {
    expect_error(with_line(4, ""), "bad.toml:2: beam.width: missing required key");
    expect_error(with_line(10, ""), "bad.toml:7: material.poisson_ratio: missing required key");
    expect_error(kBase + "[[supports]]\nposition = 1.0\n", "bad.toml:11: supports[0].stiffness: missing required key");
    expect_error(kBase.substr(0, kBase.find("[material]")), "bad.toml:1: material: missing required table [material]");
    expect_error("", "bad.toml:1: beam: missing required table [beam]");
}

TEST(CaseReaderErrors, WrongType) {
    expect_error(with_line(3, "length = true"), "bad.toml:3: beam.length: expected a number (SI) or a string");
    expect_error(with_line(6, "elements = 50.0"), "bad.toml:6: beam.elements: expected an integer, got a floating");
    expect_error(with_line(6, "elements = \"50\""), "bad.toml:6: beam.elements: expected an integer, got a string");
    expect_error(with_line(10, "poisson_ratio = [0.3]"), "bad.toml:10: material.poisson_ratio: expected a number");
    const std::string beam_array =
        with_line(2, "beam = [1, 2]", kBase.substr(0, kBase.find("length"))) + kBase.substr(kBase.find("[material]"));
    expect_error(beam_array, "bad.toml:2: beam: expected a table, got an array");
    expect_error(kBase + "[supports]\nposition = 1.0\n", "bad.toml:11: supports: expected an array of tables");
    expect_error(insert_line(1, "supports = [1]"), "bad.toml:1: supports[0]: expected a table");
    expect_error(kBase + support("1.0", "side = 1\n"), "bad.toml:14: supports[0].side: expected one of");
    expect_error(insert_line(7, "left = \"fixed\""), "bad.toml:7: beam.left: must be one of \"clamped\"");
    expect_error(kBase + "plate_modulus = 1\n", "bad.toml:11: material.plate_modulus: expected true or false");
    expect_error(kBase + "[damping]\nratios = [0.01]\n", "bad.toml:12: damping.ratios: expected an array of 2 numbers");
    expect_error(kBase + "[damping]\nratios = [0.01,\n  \"x\"]\n", "bad.toml:13: damping.ratios[1]: expected a number");
    expect_error(kBase + "[damping]\nratios = [0.1, 0.2]\nmodes = [1, 2.0]\n", "bad.toml:13: damping.modes[1]: ");
    expect_error(with_line(1, "name = 3"), "bad.toml:1: name: expected a string");
}

TEST(CaseReaderErrors, Units) {
    expect_error(with_line(3, "length = \"100 uM\""), "bad.toml:3: beam.length: unknown unit \"uM\"");
    expect_error(with_line(3, "length = \"100\""), "bad.toml:3: beam.length: missing unit");
    expect_error(with_line(3, "length = \"\""), "bad.toml:3: beam.length: empty value");
    expect_error(with_line(3, "length = \"100 GPa\""), "bad.toml:3: beam.length: unit \"GPa\" is a pressure");
    expect_error(with_line(9, "density = \"8.9 g/cm3\""), "bad.toml:9: material.density: unknown unit");
    expect_error(kBase + support("\"1 um\""), "bad.toml:12: supports[0].position: a dimensionless value takes no unit");
}

TEST(CaseReaderErrors, NotFinite) {
    expect_error(with_line(3, "length = nan"), "bad.toml:3: beam.length: must be a finite number, got nan");
    expect_error(with_line(9, "density = inf"), "bad.toml:9: material.density: must be a finite number, got inf");
    expect_error(with_line(10, "poisson_ratio = -inf"), "bad.toml:10: material.poisson_ratio: must be a finite");
    expect_error(with_line(3, "length = \"inf um\""), "bad.toml:3: beam.length: infinite and NaN");
    expect_error(with_line(3, "length = \"1e999 um\""), "bad.toml:3: beam.length: number \"1e999\" is out of range");
}

TEST(CaseReaderErrors, NonPositiveSizesAndMaterial) {
    expect_error(with_line(3, "length = 0"), "bad.toml:3: beam.length: must be positive");
    expect_error(with_line(3, "length = \"-1 um\""), "bad.toml:3: beam.length: must be positive");
    expect_error(with_line(5, "thickness = \"0 um\""), "bad.toml:5: beam.thickness: must be positive");
    expect_error(with_line(9, "density = \"-1 kg/m^3\""), "bad.toml:9: material.density: must be positive");
    expect_error(with_line(8, "youngs_modulus = 0"), "bad.toml:8: material.youngs_modulus: must be positive");
    expect_error(with_line(10, "poisson_ratio = 0.5"), "bad.toml:10: material.poisson_ratio: must lie in");
}

TEST(CaseReaderErrors, Elements) {
    expect_error(with_line(6, "elements = 0"), "bad.toml:6: beam.elements: must be at least 1");
    expect_error(with_line(6, "elements = -3"), "bad.toml:6: beam.elements: must be at least 1");
    expect_error(with_line(6, "elements = 9223372036854775807"), "bad.toml:6: beam.elements: must be at most");
}

TEST(CaseReaderErrors, SupportPosition) {
    for (const char* position : {"0", "1.5", "-0.1"}) {
        expect_error(kBase + support(position), "bad.toml:12: supports[0].position: must lie in (0, 1]");
    }
    expect_error(kBase + support("0.5") + support("0.5"),
                 "bad.toml:15: supports[1].position: two supports at the same");
    // (the support below leaves room under the ones above: see CaseReaderTablesErrors for overlaps)
    expect_error(kBase + support("0.5", "side = \"above\"\n") + support("0.5", "gap = \"1 um\"\n") +
                     support("0.5", "side = \"above\"\n"),
                 "bad.toml:20: supports[2].position: two supports at the same place and side (supports[0])");
}

TEST(CaseReaderErrors, FreeFreeBeam) {
    expect_error(insert_line(7, "left = \"free\"\nright = \"free\""), "bad.toml:8: beam.right: the end conditions");
    expect_error(insert_line(7, "left = \"free\""), "bad.toml:2: beam.right: the end conditions");  // right defaulted
}

TEST(CaseReaderErrors, MutuallyExclusiveKeysNameTheLaterOne) {
    expect_error(kBase + "[damping]\nratios = [0.01, 0.02]\nalpha = \"100 1/s\"\n",
                 "bad.toml:13: damping.alpha: cannot be combined with damping.ratios");
    expect_error(kBase + "[damping]\nbeta = 1e-10\nratios = [0.01, 0.02]\n",
                 "bad.toml:13: damping.ratios: cannot be combined with damping.beta");
    expect_error(kBase + support("1.0", "prestress = \"1 um\"\ngap = \"1 um\"\n"),
                 "bad.toml:15: supports[0].gap: cannot be combined with supports[0].prestress");
    expect_error(kBase + support("1.0", "damping = 0\ndamping_ratio = 0.1\n"),
                 "bad.toml:15: supports[0].damping_ratio: cannot be combined with supports[0].damping");
    expect_error(kBase + "[damping]\nmodes = [1, 2]\n", "bad.toml:12: damping.modes: needs damping.ratios");
}

TEST(CaseReaderErrors, SupportValues) {
    expect_error(kBase + "[[supports]]\nposition = 1.0\nstiffness = \"-50 N/m\"\n",
                 "bad.toml:13: supports[0].stiffness: must be positive");
    expect_error(kBase + support("1.0", "gap = \"-1 um\"\n"), "bad.toml:14: supports[0].gap: must not be negative");
    expect_error(kBase + support("1.0", "damping = \"-1 N s/m\"\n"), "bad.toml:14: supports[0].damping: must not be");
    expect_error(kBase + "[damping]\nratios = [0.01, -0.02]\n", "bad.toml:12: damping.ratios: must not be negative");
    expect_error(kBase + "[damping]\nratios = [0.01, 0.02]\nmodes = [2, 2]\n", "bad.toml:13: damping.modes: ");
}

TEST(CaseReaderErrors, FirstProblemInFileOrder) {
    // The wrong type (line 3) comes before the unknown key (line 8), though [material] sorts after [beam]...
    expect_error(with_line(8, "youngs = 1", with_line(3, "length = false")), "bad.toml:3: beam.length:");
    // ...and problems with the text come before problems with values.
    expect_error(with_line(3, "length = 0") + "extra = 1\n", "bad.toml:11: material.extra: unknown key");
    // Among value problems, the earliest line wins whatever order check_case uses.
    expect_error(with_line(9, "density = 0", with_line(5, "thickness = 0")), "bad.toml:5: beam.thickness:");
}

TEST(CaseReaderErrors, NeverCrashesOnMutatedInput) {
    const std::string good = kBase + support("1.0", "gap = \"0.5 um\"\n") + "[damping]\nratios = [0.01, 0.02]\n";
    std::mt19937 rng(12345);
    const char kChars[] = "[]{}=\"'.,#\n 0123456789eE+-_abmuGPa/\\\0\xC2\xB5";
    const std::string alphabet(kChars, sizeof kChars - 1);
    for (int trial = 0; trial < 3000; ++trial) {
        std::string text = good;
        const int edits = 1 + static_cast<int>(rng() % 4);
        for (int e = 0; e < edits; ++e) {
            const std::size_t at = rng() % (text.size() + 1);
            const char ch = alphabet[rng() % alphabet.size()];
            switch (rng() % 3) {
                case 0: text.insert(at, 1, ch); break;
                case 1: if (at < text.size()) text.erase(at, 1); break;
                default: if (at < text.size()) text[at] = ch; break;
            }
        }
        try {
            read_case_text(text, "fuzz.toml");
        } catch (const vi::InputError& e) {
            const std::string what = e.what();
            ASSERT_EQ(what.rfind("fuzz.toml:", 0), 0u) << what;
            ASSERT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}

}  // namespace
