// Generated from the schema's list of keys: every number a case file takes, set to 1e300, 1e-300, 0
// and -1 (a whole number to a float, the largest integer, 0 and -1), is refused by `simulate` with exit
// 2, one line naming the file, the line and the key, and nothing written, exactly where the key's
// range or the magnitude window (1e-100 .. 1e100 for nonzero numbers) says so; every other value reads.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "io/case_writer.hpp"
#include "model/case_schema.hpp"
#include "model/input_error.hpp"
#include "model/run_estimate.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "support/text_checks.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

// Two cases that between them put every key of the built-in schema in effect: a stressed bridge on
// CVODE with every kind of support, load, waveform, layer, air and film; a cantilever with alpha and
// beta damping, a force step, a ramp and the penetration rule.
const char* const kBridge = R"(name = "refusals-bridge"
[beam]
length = "200 um"
width = "20 um"
thickness = "2 um"
elements = 20
left = "clamped"
right = "clamped"
residual_stress = "10 MPa"
[material]
youngs_modulus = "170 GPa"
density = "2330 kg/m^3"
poisson_ratio = 0.28
[[supports]]
position = 0.5
gap = "1 um"
stiffness = "100 N/m"
damping = "1e-7 N s/m"
[[supports]]
position = 0.3
side = "above"
gap = "2 um"
stiffness = "100 N/m"
damping_ratio = 0.1
adhesion = "dmt"
work_of_adhesion = "0.1 J/m^2"
contact_radius = "1 um"
adhesion_range = "3 nm"
[[supports]]
position = 0.7
prestress = "0.01 um"
stiffness = "100 N/m"
[damping]
ratios = [0.01, 0.02]
modes = [1, 2]
[initial]
kind = "displacement"
position = 0.5
displacement = "0.1 um"
velocity_shape = "mode"
velocity = "0.01 m/s"
velocity_mode = 1
[[loads]]
position = 0.4
amplitude = "1 uN"
kind = "step"
t_on = "1 us"
[[loads]]
position = 0.6
amplitude = "1 uN"
kind = "harmonic"
frequency = "100 kHz"
phase = 0.1
offset = 0.2
[[electrodes]]
from = 0.1
to = 0.2
gap = "2 um"
dielectric_thickness = "0.1 um"
dielectric_permittivity = 7
dielectric_modulus = "200 GPa"
work_of_adhesion = "0.01 J/m^2"
adhesion_range = "2 nm"
width = "10 um"
voltage = "5 V"
waveform = "pulse"
t_on = "1 us"
rise = "1 us"
hold = "1 us"
fall = "1 us"
[[electrodes]]
from = 0.25
to = 0.35
gap = "2 um"
voltage = "5 V"
waveform = "two_step"
rise = "10 ns"
level = 0.5
hold = "1 us"
[[electrodes]]
from = 0.8
to = 0.9
gap = "2 um"
voltage = "1 V"
waveform = "sine"
frequency = "1 kHz"
phase = 0.1
bias = "1 V"
[air]
pressure = "1 kPa"
temperature = "300 K"
viscosity = "1.8e-5 Pa s"
mean_free_path = "70 nm"
[[films]]
from = 0.42
to = 0.45
gap = "1 um"
[solver]
method = "cvode"
horizon = "2 us"
output_step = "10 ns"
field_step = "0.1 us"
group_gap = "0.1 us"
settle_rule = "velocity"
settle_velocity = "0.01 m/s"
rtol = 1e-8
reduced_modes = 5
min_search_step = 1e-9
max_events = 100000
max_steps = 1000000
max_static_iterations = 100
)";

const char* const kCantilever = R"(name = "refusals-cantilever"
[beam]
length = "117 um"
width = "30 um"
thickness = "2 um"
elements = 20
[material]
youngs_modulus = "207 GPa"
density = "8902 kg/m^3"
poisson_ratio = 0.31
[[supports]]
position = 1.0
gap = "0.5 um"
stiffness = "1000 N/m"
[damping]
alpha = "100 1/s"
beta = "1e-10 s"
[initial]
kind = "force"
force = "1 uN"
[[electrodes]]
from = 0.1
to = 0.9
gap = "2 um"
voltage = "5 V"
waveform = "ramp"
rise = "1 us"
[solver]
horizon = "10 us"
settle_tolerance = 0.02
[[beam.sections]]
from = 0
to = 1
width = "30 um"
thickness = "2 um"
[[materials]]
name = "gold"
youngs_modulus = "79 GPa"
density = "19300 kg/m^3"
poisson_ratio = 0.42
residual_stress = "10 MPa"
stress_gradient = 1e12
)";

// A base case as case_to_toml writes it (every key in effect on a line of its own) and the line of
// every key, by dotted path.
struct Base {
    Case c;
    std::vector<std::string> lines;
    std::map<std::string, std::size_t> line_of;  // 0-based
};

Base make_base(const char* text) {
    Base b;
    b.c = read_case_text(text, "base.toml");
    std::istringstream in(case_to_toml(b.c));
    std::map<std::string, std::size_t> entries;
    std::string entry;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("[[", 0) == 0) {
            const std::string name = line.substr(2, line.find("]]") - 2);
            entry = name + "[" + std::to_string(entries[name]++) + "]";
        } else if (line.rfind("[", 0) == 0) {
            entry = line.substr(1, line.find(']') - 1);
        } else if (const auto eq = line.find(" = "); eq != std::string::npos && line[0] != '#') {
            b.line_of[(entry.empty() ? "" : entry + ".") + line.substr(0, eq)] = b.lines.size();
        }
        b.lines.push_back(line);
    }
    return b;
}

// The values tried on a key: as TOML text, and as the number the table judges.
struct Trial {
    std::string text;
    double value;
    bool integer_text;  // a TOML integer (false: a float, which a whole-number key refuses outright)
};

std::vector<Trial> trials(const KeySpec& k) {
    if (k.kind == KeyKind::integer || k.kind == KeyKind::integer_pair) {
        return {{"1e300", 1e300, false}, {"9223372036854775807", 9223372036854775807.0, true},
                {"0", 0.0, true}, {"-1", -1.0, true}};
    }
    return {{"1e300", 1e300, false}, {"1e-300", 1e-300, false}, {"0", 0.0, false}, {"-1", -1.0, false}};
}

// What the schema says of v for key k: refused outside its range, or (a nonzero number) outside the
// magnitude window; a whole-number key refuses a float.
bool table_refuses(const KeySpec& k, const Trial& t) {
    const bool whole = k.kind == KeyKind::integer || k.kind == KeyKind::integer_pair;
    if (whole) return !t.integer_text || !k.range.contains(t.value);
    const double a = std::abs(t.value);
    const bool window = t.value == 0.0 || (a >= 1.0 / kMagnitudeLimit && a <= kMagnitudeLimit);
    return !k.range.contains(t.value) || (k.magnitude_checked && !window);
}

// The base's text with key `path`'s value (a pair's first element) replaced by `value`.
std::string with_value(const Base& b, std::size_t line, const KeySpec& k, const std::string& value) {
    std::string text;
    for (std::size_t i = 0; i < b.lines.size(); ++i) {
        std::string l = b.lines[i];
        if (i == line) {
            const std::string rest = is_pair(k.kind) ? l.substr(l.find(',')) : "";
            l = k.name + " = " + (is_pair(k.kind) ? "[" + value + rest : value);
        }
        text += l + "\n";
    }
    return text;
}

TEST(KeyRefusals, EveryNumberIsRefusedExactlyWhereItsRangeOrTheMagnitudeWindowSays) {
    const std::vector<Base> bases{make_base(kBridge), make_base(kCantilever)};
    const std::string dir = test::make_temp_dir();
    const std::string file = dir + "/case.toml";
    int refused = 0, accepted = 0;
    for (const SectionSpec& s : builtin_case_schema().sections) {
        for (const KeySpec& k : s.keys) {
            if (!is_numeric(k.kind)) continue;
            // The first entry of a base that has the key in effect.
            const Base* base = nullptr;
            std::string path;
            for (const Base& b : bases) {
                for (std::size_t i = 0; base == nullptr && i < s.count(b.c); ++i) {
                    if (key_in_effect(b.c, s, k, i) && b.line_of.count(key_path(s, i, k.name)) > 0) {
                        base = &b;
                        path = key_path(s, i, k.name);
                    }
                }
            }
            if (base == nullptr) {
                ADD_FAILURE() << s.form() << "." << k.name << ": no base case of this test has it; add it to one";
                continue;
            }
            const std::size_t line = base->line_of.at(path);
            for (const Trial& t : trials(k)) {
                SCOPED_TRACE(path + " = " + t.text);
                const std::string text = with_value(*base, line, k, t.text);
                if (!table_refuses(k, t)) {
                    // Accepted by the key's own description; a rule between keys may still refuse
                    // it, and then names this key.
                    try {
                        read_case_text(text, "case.toml");
                    } catch (const InputError& e) {
                        EXPECT_NE(std::string(e.what()).find(": " + path + ": "), std::string::npos) << e.what();
                    }
                    ++accepted;
                    continue;
                }
                test::write_text(file, text);
                const std::string out = dir + "/out";
                const auto r = test::run_vibroimpact({"simulate", file, "--out", out});
                EXPECT_EQ(r.exit_code, 2) << r.err;
                EXPECT_TRUE(test::is_one_error_line(r.err)) << r.err;
                const std::string where = "vibroimpact: error: " + file + ":" + std::to_string(line + 1) + ": " + path;
                EXPECT_EQ(r.err.rfind(where, 0), 0u) << "expected " << where << "..., got " << r.err;
                EXPECT_FALSE(fs::exists(out)) << "wrote output";
                fs::remove_all(out);
                ++refused;
            }
        }
    }
    std::printf("[ refusals ] %d values refused, %d accepted by the keys' ranges\n", refused, accepted);
    EXPECT_GT(refused, 200);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
