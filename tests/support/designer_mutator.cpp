#include "support/designer_mutator.hpp"

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <vector>

namespace vi::test {
namespace {

using Lines = std::vector<std::string>;
constexpr std::size_t kNone = static_cast<std::size_t>(-1);

class DesignRng {
public:
    // A stream of its own, apart from the garbage mutator's for the same index.
    DesignRng(std::uint64_t seed, std::uint64_t index) : engine_((seed ^ 0xD1B54A32D192ED03ULL) * 0x9E3779B97F4A7C15ULL + index) {}
    std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(engine_() % n); }
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
    template <class T>
    const T& pick(const std::vector<T>& v) { return v[below(v.size())]; }

private:
    std::mt19937_64 engine_;
};

std::string trimmed(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    const auto b = s.find_last_not_of(" \t\r");
    return s.substr(a, b - a + 1);
}

Lines lines_in(const std::string& text) {
    Lines lines;
    std::string line;
    std::istringstream in(text);
    while (std::getline(in, line)) lines.push_back(line);
    return lines;
}

std::string text_of(const Lines& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

// A table of the case: its header line (none for the top level) and the lines up to the next header.
struct Block {
    std::string name;  // "beam", "electrodes", ...; empty for the top level
    std::size_t begin = 0, end = 0;  // [begin, end): the header line and its keys
};

std::vector<Block> blocks_of(const Lines& lines) {
    std::vector<Block> out{Block{"", 0, lines.size()}};
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string t = trimmed(lines[i]);
        if (t.empty() || t[0] != '[') continue;
        const auto open = t.find_first_not_of('[');
        const auto close = t.find(']');
        if (open == std::string::npos || close == std::string::npos || close < open) continue;
        out.back().end = i;
        out.push_back(Block{trimmed(t.substr(open, close - open)), i, lines.size()});
    }
    return out;
}

std::vector<Block> named(const Lines& lines, const std::string& name) {
    std::vector<Block> out;
    for (const Block& b : blocks_of(lines)) {
        if (b.name == name) out.push_back(b);
    }
    return out;
}

std::size_t key_line(const Lines& lines, const Block& b, const std::string& key) {
    for (std::size_t i = b.name.empty() ? b.begin : b.begin + 1; i < b.end; ++i) {
        const std::string t = trimmed(lines[i]);
        if (t.compare(0, key.size(), key) != 0) continue;
        const std::string rest = trimmed(t.substr(key.size()));
        if (!rest.empty() && rest[0] == '=') return i;
    }
    return kNone;
}

// The value's text, its comment dropped (no value here holds a '#').
std::string value_of(const Lines& lines, const Block& b, const std::string& key) {
    const std::size_t i = key_line(lines, b, key);
    if (i == kNone) return "";
    std::string v = lines[i].substr(lines[i].find('=') + 1);
    return trimmed(v.substr(0, v.find('#')));
}

void set_key(Lines& lines, const Block& b, const std::string& key, const std::string& value) {
    const std::size_t i = key_line(lines, b, key);
    if (i != kNone) {
        lines[i] = key + " = " + value;
    } else {
        lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(b.name.empty() ? 0 : b.begin + 1), key + " = " + value);
    }
}

void remove_key(Lines& lines, const Block& b, const std::string& key) {
    const std::size_t i = key_line(lines, b, key);
    if (i != kNone) lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
}

// Keys of a table copied out on its own (its header on the first line).
void set_in(Lines& block, const std::string& key, const std::string& value) {
    set_key(block, Block{"table", 0, block.size()}, key, value);
}
void remove_in(Lines& block, const std::string& key) { remove_key(block, Block{"table", 0, block.size()}, key); }
std::string value_in(const Lines& block, const std::string& key) {
    return value_of(block, Block{"table", 0, block.size()}, key);
}

// A value in SI ("2 um" -> 2e-6, 0.5 -> 0.5); nothing when it is not a number with a known unit.
std::optional<double> parse_si(const std::string& value) {
    std::string v = value;
    if (!v.empty() && v.front() == '"') v = v.substr(1, v.find('"', 1) - 1);
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (end == v.c_str()) return std::nullopt;
    static const std::map<std::string, double> kScale = {
        {"", 1.0},     {"m", 1.0},    {"mm", 1e-3},  {"um", 1e-6}, {"nm", 1e-9}, {"V", 1.0},   {"mV", 1e-3},
        {"kV", 1e3},   {"s", 1.0},    {"ms", 1e-3},  {"us", 1e-6}, {"ns", 1e-9}, {"Hz", 1.0},  {"kHz", 1e3},
        {"MHz", 1e6},  {"Pa", 1.0},   {"kPa", 1e3},  {"MPa", 1e6}, {"GPa", 1e9}, {"N/m", 1.0}, {"kN/m", 1e3}};
    const auto unit = kScale.find(trimmed(end));
    if (unit == kScale.end()) return std::nullopt;
    return x * unit->second;
}

std::string quantity(double v, const char* unit) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "\"%.6g %s\"", v, unit);
    return buf;
}

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    std::string s = buf;
    // A TOML float needs a point or an exponent where the key takes a float.
    if (s.find_first_of(".e") == std::string::npos && s.find("inf") == std::string::npos) s += ".0";
    return s;
}

// One edit under way: the lines, the dice, and what the mutant brings beside the case.
struct Edit {
    Lines lines;
    DesignRng& rng;
    const DesignerSource& source;
    Mutant& mutant;
    std::string step;

    std::optional<Block> pick_block(const std::string& name) {
        const std::vector<Block> b = named(lines, name);
        if (b.empty()) return std::nullopt;
        return b[rng.below(b.size())];
    }
    // The block again after an edit inside it changed its end (its header stays on its line).
    Block again(const Block& b) const {
        for (const Block& x : named(lines, b.name)) {
            if (x.begin == b.begin) return x;
        }
        return b;
    }
    // Sets each key in turn, finding the block again after every insertion.
    void set_keys(const Block& b, const std::vector<std::pair<std::string, std::string>>& kv) {
        for (const auto& [k, v] : kv) set_key(lines, again(b), k, v);
    }
    // V_PI of the case, or a stand-in from its first electrode's voltage (the examples step to 1.2 V_PI).
    double pullin_voltage() {
        if (source.pullin_voltage > 0.0) return source.pullin_voltage;
        for (const Block& b : named(lines, "electrodes")) {
            if (const auto v = parse_si(value_of(lines, b, "voltage"))) return *v / 1.2;
        }
        return 50.0;
    }
    void append(const Lines& block) {
        lines.push_back("");
        lines.insert(lines.end(), block.begin(), block.end());
    }
};

const std::vector<std::string> kWaveformKeys = {"waveform", "t_on", "rise", "hold", "fall", "level",
                                                "frequency", "phase", "bias", "table"};

// A second electrode: a copy of one beside it, over it, on the other side or the whole length; a
// first one under a beam without.
bool second_electrode(Edit& e) {
    const std::optional<Block> b = e.pick_block("electrodes");
    if (!b) {
        const std::vector<double> gaps = {0.3e-6, 1e-6, 2e-6, 3e-6, 10e-6};
        const double from = e.rng.pick(std::vector<double>{0.0, 0.1, 0.5}), to = e.rng.pick(std::vector<double>{0.6, 0.9, 1.0});
        const double gap = e.rng.pick(gaps), v = e.rng.pick(std::vector<double>{1.0, 10.0, 50.0, 100.0, 300.0});
        e.append({"[[electrodes]]", "from = " + number(from), "to = " + number(to), "side = \"below\"",
                  "gap = " + quantity(gap, "m"), "voltage = " + quantity(v, "V"), "waveform = \"step\"", "t_on = \"0 us\""});
        e.step = "a first electrode under x/l " + number(from) + ".." + number(to) + ", gap " + number(gap) + " m, " +
                 number(v) + " V step";
        return true;
    }
    Lines copy(e.lines.begin() + static_cast<std::ptrdiff_t>(b->begin), e.lines.begin() + static_cast<std::ptrdiff_t>(b->end));
    const double from = parse_si(value_in(copy, "from")).value_or(0.1);
    const double to = parse_si(value_in(copy, "to")).value_or(0.9);
    const double span = to - from;
    switch (e.rng.below(4)) {
        case 0:  // beside it: after its end, or before its start when it reaches x = l
            if (to < 0.999) {
                set_in(copy, "from", number(to));
                set_in(copy, "to", number(std::min(1.0, to + 0.5 * span)));
            } else {
                set_in(copy, "from", number(std::max(0.0, from - 0.5 * span)));
                set_in(copy, "to", number(from));
            }
            e.step = "a second electrode beside the first";
            break;
        case 1:
            e.step = "a second electrode over the same span";
            break;
        case 2: {
            const std::string side = value_in(copy, "side") == "\"above\"" ? "\"below\"" : "\"above\"";
            set_in(copy, "side", side);
            e.step = "a second electrode on the other side (" + side + ")";
            break;
        }
        default:
            set_in(copy, "from", "0.0");
            set_in(copy, "to", "1.0");
            e.step = "a second electrode over the whole length";
    }
    e.append(copy);
    return true;
}

bool remove_stop(Edit& e) {
    const std::optional<Block> b = e.pick_block("supports");
    if (!b) return false;
    e.step = "the support at line " + std::to_string(b->begin + 1) + " removed";
    e.lines.erase(e.lines.begin() + static_cast<std::ptrdiff_t>(b->begin), e.lines.begin() + static_cast<std::ptrdiff_t>(b->end));
    return true;
}

bool electrode_to_ends(Edit& e) {
    const std::optional<Block> b = e.pick_block("electrodes");
    if (!b) return false;
    const std::size_t which = e.rng.below(3);
    if (which != 1) set_key(e.lines, *b, "to", "1.0");
    if (which != 0) set_key(e.lines, e.again(*b), "from", "0.0");
    e.step = std::string("the electrode at line ") + std::to_string(b->begin + 1) + " runs to " +
             (which == 0 ? "x = l" : which == 1 ? "x = 0" : "both ends");
    return true;
}

// The electrode's gap below the stop's, or the stop's beyond the electrode's.
bool cross_gaps(Edit& e) {
    const std::optional<Block> el = e.pick_block("electrodes");
    const std::optional<Block> st = e.pick_block("supports");
    if (!el || !st) return false;
    const std::optional<double> ge = parse_si(value_of(e.lines, *el, "gap"));
    const std::optional<double> gs = parse_si(value_of(e.lines, *st, "gap"));
    if (gs && *gs > 0.0 && e.rng.below(2) == 0) {
        const double f = e.rng.pick(std::vector<double>{0.25, 0.5, 0.9, 0.99, 1.0});
        set_key(e.lines, *el, "gap", quantity(f * *gs, "m"));
        e.step = "electrode gap " + number(f) + " x the stop's gap";
        return true;
    }
    if (!ge) return false;
    remove_key(e.lines, *st, "prestress");
    const double f = e.rng.pick(std::vector<double>{1.0, 1.01, 1.5, 3.0});
    set_key(e.lines, e.again(*st), "gap", quantity(f * *ge, "m"));
    e.step = "stop gap " + number(f) + " x the electrode's gap";
    return true;
}

// A voltage from 0 to 3 V_PI: the thresholds and their neighbours, or anywhere in the range.
bool voltage(Edit& e) {
    const std::optional<Block> b = e.pick_block("electrodes");
    if (!b) return false;
    const std::vector<double> kNear = {0.0, 0.5, 0.9, 0.99, 1.0, 1.01, 1.1, 1.5, 2.0, 2.5, 3.0};
    const double u = e.rng.below(2) == 0 ? e.rng.pick(kNear) : e.rng.uniform(0.0, 3.0);
    const double v = u * e.pullin_voltage();
    if (value_of(e.lines, *b, "waveform") == "\"table\"") return false;
    set_key(e.lines, *b, "voltage", quantity(v, "V"));
    e.step = "voltage " + number(u) + " V_PI (" + number(v) + " V)";
    return true;
}

// A voltage table of `rows` rows `dt` apart, alternating between 0 and the peak.
std::string voltage_table(std::size_t rows, double dt, double peak) {
    std::string t = "t_s,V_V\n";
    char buf[80];
    for (std::size_t i = 0; i < rows; ++i) {
        std::snprintf(buf, sizeof buf, "%.17g,%.9g\n", static_cast<double>(i) * dt, i % 2 == 0 ? 0.0 : peak);
        t += buf;
    }
    return t;
}

// The waveform replaced by one at an extreme rate (or an ordinary one).
bool waveform(Edit& e) {
    const std::optional<Block> b = e.pick_block("electrodes");
    if (!b) return false;
    Lines block(e.lines.begin() + static_cast<std::ptrdiff_t>(b->begin), e.lines.begin() + static_cast<std::ptrdiff_t>(b->end));
    for (const std::string& k : kWaveformKeys) remove_in(block, k);
    const double vpi = e.pullin_voltage();
    if (value_in(block, "voltage").empty()) set_in(block, "voltage", quantity(1.2 * vpi, "V"));
    const std::vector<std::string> times = {"\"1e-15 s\"", "\"1e-12 s\"", "\"1 ns\"", "\"100 ns\"", "\"1 us\"",
                                            "\"10 us\"",   "\"1 ms\"",    "\"1 s\""};
    std::string what;
    switch (e.rng.below(7)) {
        case 0:
            what = "step at " + e.rng.pick(times);
            set_in(block, "waveform", "\"step\"");
            set_in(block, "t_on", e.rng.pick(times));
            break;
        case 1: {
            const std::string rise = e.rng.pick(times);
            what = "ramp over " + rise;
            set_in(block, "waveform", "\"ramp\"");
            set_in(block, "t_on", "\"0 s\"");
            set_in(block, "rise", rise);
            break;
        }
        case 2: {
            const std::string rise = e.rng.pick(times), hold = e.rng.pick(times), fall = e.rng.pick(times);
            what = "pulse rise " + rise + " hold " + hold + " fall " + fall;
            set_in(block, "waveform", "\"pulse\"");
            set_in(block, "t_on", "\"0 s\"");
            set_in(block, "rise", rise);
            set_in(block, "hold", hold);
            set_in(block, "fall", fall);
            break;
        }
        case 3: {
            const std::string level = number(e.rng.pick(std::vector<double>{0.0, 0.5, 0.9, 1.0, 2.0}));
            const std::string rise = e.rng.pick(times), hold = e.rng.pick(times);
            what = "two_step level " + level + " rise " + rise + " hold " + hold;
            set_in(block, "waveform", "\"two_step\"");
            set_in(block, "t_on", "\"0 s\"");
            set_in(block, "rise", rise);
            set_in(block, "level", level);
            set_in(block, "hold", hold);
            break;
        }
        case 4: {
            const std::vector<std::string> freqs = {"\"1e-6 Hz\"", "\"1 Hz\"", "\"1 kHz\"", "\"50 kHz\"", "\"100 kHz\"",
                                                    "\"1 MHz\"",   "\"100 MHz\"", "\"10000 MHz\"", "1e12"};
            const std::string f = e.rng.pick(freqs);
            what = "sine at " + f;
            set_in(block, "waveform", "\"sine\"");
            set_in(block, "frequency", f);
            if (e.rng.below(2) == 0) set_in(block, "bias", quantity(e.rng.uniform(0.0, 1.5) * vpi, "V"));
            break;
        }
        case 5: {
            const std::size_t rows = e.rng.pick(std::vector<std::size_t>{1, 2, 3, 50, 1000, 5000});
            const double dt = e.rng.pick(std::vector<double>{1e-15, 1e-12, 1e-9, 1e-7, 1e-6});
            const double peak = e.rng.uniform(0.0, 3.0) * vpi;
            what = "table of " + std::to_string(rows) + " rows " + number(dt) + " s apart, 0 / " + number(peak) + " V";
            remove_in(block, "voltage");
                    set_in(block, "waveform", "\"table\"");
            set_in(block, "table", "\"volts.csv\"");
            e.mutant.files.emplace_back("volts.csv", voltage_table(rows, dt, peak));
            break;
        }
        default:
            what = "constant";
            set_in(block, "waveform", "\"constant\"");
    }
    e.lines.erase(e.lines.begin() + static_cast<std::ptrdiff_t>(b->begin), e.lines.begin() + static_cast<std::ptrdiff_t>(b->end));
    e.lines.insert(e.lines.begin() + static_cast<std::ptrdiff_t>(b->begin), block.begin(), block.end());
    e.step = "waveform of the electrode at line " + std::to_string(b->begin + 1) + ": " + what;
    return true;
}

bool damping(Edit& e) {
    const std::optional<Block> b = e.pick_block("damping");
    if (b && e.rng.below(2) == 0) {
        e.lines.erase(e.lines.begin() + static_cast<std::ptrdiff_t>(b->begin), e.lines.begin() + static_cast<std::ptrdiff_t>(b->end));
        e.step = "[damping] removed";
        return true;
    }
    if (b) e.lines.erase(e.lines.begin() + static_cast<std::ptrdiff_t>(b->begin), e.lines.begin() + static_cast<std::ptrdiff_t>(b->end));
    const double r = e.rng.pick(std::vector<double>{1e-6, 1e-3, 0.05, 0.5, 1.0, 3.0});
    e.append({"[damping]", "ratios = [" + number(r) + ", " + number(r) + "]", "modes = [1, 2]"});
    e.step = "damping ratios " + number(r);
    return true;
}

bool air(Edit& e) {
    const std::optional<Block> b = e.pick_block("air");
    if (b && e.rng.below(3) == 0) {
        e.lines.erase(e.lines.begin() + static_cast<std::ptrdiff_t>(b->begin), e.lines.begin() + static_cast<std::ptrdiff_t>(b->end));
        e.step = "[air] removed";
        return true;
    }
    if (b) e.lines.erase(e.lines.begin() + static_cast<std::ptrdiff_t>(b->begin), e.lines.begin() + static_cast<std::ptrdiff_t>(b->end));
    const std::string p = e.rng.pick(std::vector<std::string>{"\"101325 Pa\"", "\"1 Pa\"", "\"0.001 Pa\"", "\"10 MPa\""});
    Lines block = {"[air]", "pressure = " + p};
    if (e.rng.below(3) == 0) block.push_back("mean_free_path = " + e.rng.pick(std::vector<std::string>{"\"1 nm\"", "\"68 nm\"", "\"10 um\""}));
    if (e.rng.below(3) == 0) block.push_back("temperature = " + e.rng.pick(std::vector<std::string>{"\"1 K\"", "\"300 K\"", "\"2000 K\""}));
    e.append(block);
    e.step = "[air] at " + p;
    if (e.rng.below(2) == 0) {
        const std::string gap = e.rng.pick(std::vector<std::string>{"\"0.1 um\"", "\"1 um\"", "\"5 um\""});
        e.append({"[[films]]", "from = 0.0", "to = 1.0", "side = \"below\"", "gap = " + gap});
        e.step += " and a film under the whole beam, gap " + gap;
    }
    return true;
}

bool dielectric(Edit& e) {
    const std::optional<Block> b = e.pick_block("electrodes");
    if (!b) return false;
    const double gap = parse_si(value_of(e.lines, *b, "gap")).value_or(2e-6);
    const double f = e.rng.pick(std::vector<double>{0.01, 0.1, 0.5, 0.99});
    const double eps = e.rng.pick(std::vector<double>{1.0, 7.5, 1000.0});
    e.set_keys(*b, {{"dielectric_thickness", quantity(f * gap, "m")}, {"dielectric_permittivity", number(eps)}});
    e.step = "dielectric " + number(f) + " of the gap, eps_r " + number(eps);
    return true;
}

bool adhesion(Edit& e) {
    const std::optional<Block> b = e.pick_block("supports");
    if (!b) return false;
    const std::string w = e.rng.pick(std::vector<std::string>{"\"0.01 J/m^2\"", "\"0.2 J/m^2\"", "\"1 J/m^2\"", "\"100 J/m^2\""});
    const std::string r = e.rng.pick(std::vector<std::string>{"\"0.1 um\"", "\"5 um\"", "\"100 um\""});
    const std::string law = e.rng.below(2) == 0 ? "\"dmt\"" : "\"jkr\"";
    e.set_keys(*b, {{"adhesion", law}, {"work_of_adhesion", w}, {"contact_radius", r}});
    e.step = "adhesion " + law + " w " + w + " R " + r;
    return true;
}

bool mesh(Edit& e) {
    const std::optional<Block> b = e.pick_block("beam");
    if (!b) return false;
    const long m = e.rng.pick(std::vector<long>{1, 2, 3, 5, 10, 20, 50, 100, 200});
    set_key(e.lines, *b, "elements", std::to_string(m));
    e.step = "beam.elements = " + std::to_string(m);
    return true;
}

bool ends(Edit& e) {
    const std::optional<Block> b = e.pick_block("beam");
    if (!b) return false;
    const std::vector<std::string> conditions = {"\"clamped\"", "\"pinned\"", "\"free\""};
    switch (e.rng.below(3)) {
        case 0: {
            const std::string key = e.rng.below(2) == 0 ? "left" : "right";
            const std::string v = e.rng.pick(conditions);
            set_key(e.lines, *b, key, v);
            e.step = "beam." + key + " = " + v;
            break;
        }
        case 1: {
            const std::string v = e.rng.below(2) == 0 ? "true" : "false";
            set_key(e.lines, *b, "stretching", v);
            e.step = "beam.stretching = " + v;
            break;
        }
        default: {
            const std::string v = e.rng.pick(std::vector<std::string>{"\"-10 MPa\"", "\"0 Pa\"", "\"20 MPa\"", "\"1 GPa\""});
            set_key(e.lines, *b, "residual_stress", v);
            e.step = "beam.residual_stress = " + v;
        }
    }
    return true;
}

bool solver(Edit& e) {
    const std::optional<Block> b = e.pick_block("solver");
    if (!b) return false;
    switch (e.rng.below(4)) {
        case 0: {
            const std::string n = std::to_string(e.rng.pick(std::vector<long>{0, 1, 2, 4, 8, 20, 100}));
            set_key(e.lines, *b, "reduced_modes", n);
            e.step = "solver.reduced_modes = " + n;
            break;
        }
        case 1: {
            const std::string m = e.rng.pick(std::vector<std::string>{"\"auto\"", "\"exact\"", "\"cvode\""});
            set_key(e.lines, *b, "method", m);
            e.step = "solver.method = " + m;
            break;
        }
        case 2: {
            const std::string r = e.rng.pick(std::vector<std::string>{"1e-3", "1e-6", "1e-8", "1e-10", "1e-12"});
            set_key(e.lines, *b, "rtol", r);
            e.step = "solver.rtol = " + r;
            break;
        }
        default: {
            const std::optional<double> h = parse_si(value_of(e.lines, *b, "horizon"));
            if (!h) return false;
            const double f = e.rng.pick(std::vector<double>{0.01, 0.1, 2.0, 10.0});
            set_key(e.lines, *b, "horizon", quantity(f * *h, "s"));
            remove_key(e.lines, e.again(*b), "output_step");
            e.step = "solver.horizon x " + number(f) + " (output_step at its default)";
        }
    }
    return true;
}

bool fringing(Edit& e) {
    const std::optional<Block> b = e.pick_block("electrodes");
    if (!b) return false;
    if (e.rng.below(2) == 0) {
        set_key(e.lines, *b, "fringing", "\"meijs-fokkema\"");
        e.step = "fringing meijs-fokkema";
    } else {
        const std::string w = e.rng.pick(std::vector<std::string>{"\"0.1 um\"", "\"1 um\"", "\"1 mm\""});
        set_key(e.lines, *b, "width", w);
        e.step = "electrode width " + w;
    }
    return true;
}

bool move_support(Edit& e) {
    const std::optional<Block> b = e.pick_block("supports");
    if (!b) return false;
    switch (e.rng.below(3)) {
        case 0: {
            const std::string p = number(e.rng.pick(std::vector<double>{0.05, 0.3, 0.5, 0.9, 1.0}));
            set_key(e.lines, *b, "position", p);
            e.step = "support position " + p;
            break;
        }
        case 1: {
            const std::string k = e.rng.pick(std::vector<std::string>{"\"0.001 N/m\"", "\"1 N/m\"", "\"100000 N/m\"", "\"1e9 N/m\""});
            set_key(e.lines, *b, "stiffness", k);
            e.step = "support stiffness " + k;
            break;
        }
        default: {
            const std::string side = value_of(e.lines, *b, "side") == "\"above\"" ? "\"below\"" : "\"above\"";
            set_key(e.lines, *b, "side", side);
            e.step = "support side " + side;
        }
    }
    return true;
}

// A number of the case set to the end of the accepted magnitudes (or past them, or to 0 or < 0), in
// its own unit, so that the value passes the parser and meets the checks.
bool magnitude(Edit& e) {
    std::vector<std::size_t> numeric;
    for (std::size_t i = 0; i < e.lines.size(); ++i) {
        const std::string t = trimmed(e.lines[i]);
        const auto eq = t.find('=');
        if (t.empty() || t[0] == '#' || t[0] == '[' || eq == std::string::npos) continue;
        std::string v = trimmed(t.substr(eq + 1));
        if (!v.empty() && v[0] == '"') v = v.substr(1);
        char* end = nullptr;
        std::strtod(v.c_str(), &end);
        if (end != v.c_str()) numeric.push_back(i);
    }
    if (numeric.empty()) return false;
    const std::size_t i = e.rng.pick(numeric);
    const std::string m = e.rng.pick(std::vector<std::string>{"1e300", "1e-300", "1e99", "1e-99", "1e101", "1e-101", "0", "-1", "-1e-300"});
    std::string& line = e.lines[i];
    const auto eq = line.find('=');
    auto at = line.find_first_not_of(" \t", eq + 1);
    const bool quoted = line[at] == '"';
    if (quoted) ++at;
    char* end = nullptr;
    std::strtod(line.c_str() + at, &end);
    const std::size_t stop = static_cast<std::size_t>(end - line.c_str());
    line = line.substr(0, at) + m + line.substr(stop);
    e.step = "line " + std::to_string(i + 1) + " magnitude -> " + trimmed(line);
    return true;
}

using Op = bool (*)(Edit&);
// The designer's edits (each listed as often as it should be picked) and the magnitudes.
const std::vector<Op> kOps = {second_electrode, second_electrode, remove_stop, remove_stop, electrode_to_ends,
                              electrode_to_ends, cross_gaps, cross_gaps, voltage, voltage, voltage, waveform,
                              waveform, waveform, damping, air, dielectric, adhesion, mesh, ends, solver,
                              fringing, move_support, magnitude, magnitude};

}  // namespace

Mutant mutate_design(const DesignerSource& source, std::uint64_t seed, std::uint64_t index) {
    DesignRng rng(seed, index);
    Mutant m;
    Edit e{lines_in(source.text), rng, source, m, ""};
    const std::size_t count = 1 + rng.below(3);
    // Bounded: an edit that does not apply to this case (no electrode to move) is tried again, at
    // most 20 times in all.
    for (std::size_t tries = 0; m.steps.size() < count && tries < 20; ++tries) {
        e.step.clear();
        if (rng.pick(kOps)(e)) m.steps.push_back(e.step);
    }
    m.text = text_of(e.lines);
    return m;
}

}  // namespace vi::test
