#include "support/case_mutator.hpp"

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace vi::test {
namespace {

// Values a key may be set to: the extremes (zero, -1, overflow, subnormal, non-finite),
// integers at the ends of int64, and units far off their scale. Strings carry a unit.
const std::vector<std::string> kValues = {
    "0", "-1", "1e308", "-1e308", "1e-320", "-1e-320", "nan", "inf", "-inf", "-0.0", "0.0",
    "9223372036854775807", "-9223372036854775808", "4294967297", "1e15", "1e-15", "3.15e7", "0.5", "1.0", "2",
    "\"1e308 GPa\"", "\"1e-320 m\"", "\"0 um\"", "\"-1 um\"", "\"1e999 m\"", "\"nan um\"", "\"inf s\"", "\"1e-15 s\"",
    "\"1e-320 s\"", "\"3.15e7 s\"", "\"1 yr\"", "\"1e308 N/m\"", "\"1e-320 N s/m\"", "\"1e15 kN/m\"", "\"0x10 um\"",
    "\"1e308\"", "\"\"", "\" \"", "\"1e-300 Hz\"", "\"1e300 MHz\"", "\"-0 s\"", "\"1e100 m/s\"", "\"1e100 N\"",
};

// Values of the wrong type for any key.
const std::vector<std::string> kWrongTypes = {
    "\"text\"", "{ a = 1 }", "{}", "[1, 2, 3]", "[]", "[[1], [2]]", "true", "false", "1979-05-27T07:32:00Z",
    "07:32:00", "[\"1 um\", \"2 um\"]", "{ value = \"1 um\" }", "[0.005]", "[0.005, 0.005, 0.005]", "[1e308, -1]",
};

const std::vector<std::string> kUnits = {"m",  "mm",  "um",   "nm", "Pa",  "GPa", "kg/m^3", "g/cm^3", "N/m", "kN/m",
                                         "N s/m", "kg/s", "s", "ms", "us", "ns", "Hz",  "MHz",    "1/s",    "N",
                                         "uN", "m/s", "",   "uM", "µm", "μs", "yr",  "%"};

// Whole tables and entries a mutant may gain.
const std::vector<std::string> kSnippets = {
    "\n[[supports]]\nposition = 1.0\nside = \"above\"\ngap = \"0 um\"\nstiffness = \"1000 N/m\"\n",
    "\n[[supports]]\nposition = 0.5\nside = \"below\"\ngap = \"1e-320 m\"\nstiffness = \"1e308 N/m\"\n",
    "\n[[supports]]\nposition = 0.99999\nstiffness = \"1000 N/m\"\n",
    "\n[[supports]]\nposition = 1e-300\nstiffness = \"1000 N/m\"\ndamping_ratio = 1e300\n",
    "\n[[loads]]\nposition = 1.0\namplitude = \"1 uN\"\nkind = \"harmonic\"\nfrequency = \"1e300 MHz\"\n",
    "\n[[loads]]\nposition = 0.5\namplitude = \"1e308 N\"\nkind = \"step\"\nt_on = \"1e-320 s\"\n",
    "\n[[loads]]\nposition = 0.5\namplitude = \"1 uN\"\nkind = \"table\"\ntable = \"/dev/zero\"\n",
    "\n[[loads]]\nposition = 0.5\namplitude = \"1 uN\"\nkind = \"table\"\ntable = \"/\"\n",
    "\n[[loads]]\nposition = 0.5\namplitude = \"1 uN\"\nkind = \"table\"\ntable = \"missing.csv\"\n",
    "\n[output]\nfolder = \"x\"\n",
    "\n[damping]\nalpha = \"1e308 1/s\"\n",
    "\n[solver]\nmax_events = 1\nmax_steps = 1000\n",
    "\n[[supports]]\n",
    "\n[[loads]]\n",
    "\n[beam]\n",
    "\nsupports = 1\n",
    "\n[initial]\nkind = \"force\"\nforce = \"1e308 N\"\nvelocity_shape = \"mode\"\nvelocity = \"1e300 m/s\"\n"
    "velocity_mode = 2147483647\n",
};

// Bytes worth inserting: syntax characters, control bytes, invalid UTF-8.
const char kByteList[] = "\0\x01\x7f\x80\xff\xc3\xa9\n\r\t\"'[]{}=#.,\\-+e0123456789 ";
const std::string kBytes(kByteList, sizeof kByteList - 1);

class Rng {
public:
    Rng(std::uint64_t seed, std::uint64_t index) : engine_(seed * 0x9E3779B97F4A7C15ULL + index) {}
    std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(engine_() % n); }
    template <class T>
    const T& pick(const std::vector<T>& v) { return v[below(v.size())]; }

private:
    std::mt19937_64 engine_;
};

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::string line;
    std::istringstream in(text);
    while (std::getline(in, line)) lines.push_back(line);
    return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

// Indices of lines "key = value" (not comments or headers).
std::vector<std::size_t> assignments(const std::vector<std::string>& lines) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const auto start = lines[i].find_first_not_of(" \t");
        if (start == std::string::npos || lines[i][start] == '#' || lines[i][start] == '[') continue;
        if (lines[i].find('=') != std::string::npos) out.push_back(i);
    }
    return out;
}

// The line's value replaced (its comment dropped).
std::string with_value(const std::string& line, const std::string& value) {
    return line.substr(0, line.find('=')) + "= " + value;
}

// The line's number (bare, or leading a quoted "<number> <unit>") times factor; unchanged without one.
std::string scaled(const std::string& line, double factor) {
    const auto eq = line.find('=');
    if (eq == std::string::npos) return line;
    std::size_t at = line.find_first_not_of(" \t", eq + 1);
    if (at == std::string::npos) return line;
    const bool quoted = line[at] == '"';
    if (quoted) ++at;
    char* end = nullptr;
    const double v = std::strtod(line.c_str() + at, &end);
    if (end == line.c_str() + at) return line;
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.6g", v * factor);
    return line.substr(0, at) + buf + std::string(end);
}

std::string mutate_once(std::string text, Rng& rng, std::string& step) {
    std::vector<std::string> lines = split_lines(text);
    const std::vector<std::size_t> keys = assignments(lines);
    switch (rng.below(11)) {
        case 10: {  // a number scaled within a few decades: runs that reach the solvers
            if (keys.empty()) break;
            const std::size_t i = rng.pick(keys);
            static const std::vector<double> kFactors = {1e-3, 0.1, 0.5, 0.99, 1.01, 2.0, 10.0};
            const double f = rng.pick(kFactors);
            step = "line " + std::to_string(i + 1) + " number x " + std::to_string(f);
            lines[i] = scaled(lines[i], f);
            return join_lines(lines);
        }
        case 0:
        case 1: {  // a value to an extreme (twice as likely: the main point of the fuzz)
            if (keys.empty()) break;
            const std::size_t i = rng.pick(keys);
            const std::string& v = rng.pick(kValues);
            step = "line " + std::to_string(i + 1) + " value -> " + v;
            lines[i] = with_value(lines[i], v);
            return join_lines(lines);
        }
        case 2: {  // the unit of a "<number> <unit>" value swapped
            if (keys.empty()) break;
            const std::size_t i = rng.pick(keys);
            const auto q1 = lines[i].find('"'), sp = lines[i].find(' ', q1 + 1), q2 = lines[i].find('"', q1 + 1);
            if (q1 == std::string::npos || q2 == std::string::npos || sp == std::string::npos || sp > q2) break;
            const std::string& u = rng.pick(kUnits);
            step = "line " + std::to_string(i + 1) + " unit -> \"" + u + "\"";
            lines[i] = lines[i].substr(0, sp + 1) + u + lines[i].substr(q2);
            return join_lines(lines);
        }
        case 3: {  // a line removed
            if (lines.empty()) break;
            const std::size_t i = rng.below(lines.size());
            step = "line " + std::to_string(i + 1) + " removed";
            lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
            return join_lines(lines);
        }
        case 4: {  // a line duplicated, in place or elsewhere
            if (lines.empty()) break;
            const std::size_t i = rng.below(lines.size()), j = rng.below(lines.size() + 1);
            step = "line " + std::to_string(i + 1) + " copied before line " + std::to_string(j + 1);
            lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(j), lines[i]);
            return join_lines(lines);
        }
        case 5: {  // a key (or table name) misspelled
            std::vector<std::size_t> named = keys;
            for (std::size_t i = 0; i < lines.size(); ++i) {
                if (!lines[i].empty() && lines[i][0] == '[') named.push_back(i);
            }
            if (named.empty()) break;
            const std::size_t i = rng.pick(named);
            const auto first = lines[i].find_first_not_of(" \t[");
            const auto end = lines[i].find_first_of(" =]", first);
            if (first == std::string::npos || end == std::string::npos || end <= first) break;
            const std::size_t at = first + rng.below(end - first);
            lines[i][at] = static_cast<char>(lines[i][at] == 'x' ? 'y' : 'x');
            step = "line " + std::to_string(i + 1) + " misspelled -> " + lines[i];
            return join_lines(lines);
        }
        case 6: {  // a value of the wrong type, or a value turned into a table
            if (keys.empty()) break;
            const std::size_t i = rng.pick(keys);
            if (rng.below(4) == 0) {
                const std::string key = lines[i].substr(0, lines[i].find('='));
                step = "line " + std::to_string(i + 1) + " -> table [" + key + "]";
                lines[i] = "[" + key + "]";
            } else {
                const std::string& v = rng.pick(kWrongTypes);
                step = "line " + std::to_string(i + 1) + " value -> " + v;
                lines[i] = with_value(lines[i], v);
            }
            return join_lines(lines);
        }
        case 7: {  // truncated at a random byte
            const std::size_t at = rng.below(text.size() + 1);
            step = "cut at byte " + std::to_string(at);
            return text.substr(0, at);
        }
        case 8: {  // random bytes inserted, or bits flipped
            if (text.empty()) break;
            const std::size_t count = 1 + rng.below(6);
            if (rng.below(2) == 0) {
                for (std::size_t k = 0; k < count; ++k) {
                    const std::size_t at = rng.below(text.size() + 1);
                    text.insert(at, 1, kBytes[rng.below(kBytes.size())]);
                }
                step = std::to_string(count) + " random bytes inserted";
            } else {
                for (std::size_t k = 0; k < count; ++k) {
                    const std::size_t at = rng.below(text.size());
                    text[at] = static_cast<char>(text[at] ^ (1 << rng.below(8)));
                }
                step = std::to_string(count) + " bits flipped";
            }
            return text;
        }
        default: {  // a table or entry appended
            const std::size_t k = rng.below(kSnippets.size());
            step = "snippet " + std::to_string(k) + " appended";
            return text + kSnippets[k];
        }
    }
    step = "unchanged";
    return text;
}

}  // namespace

Mutant mutate_case(const std::string& text, std::uint64_t seed, std::uint64_t index) {
    Rng rng(seed, index);
    Mutant m;
    m.text = text;
    const std::size_t count = 1 + rng.below(3);
    for (std::size_t k = 0; k < count; ++k) {
        std::string step;
        m.text = mutate_once(std::move(m.text), rng, step);
        m.steps.push_back(step);
    }
    return m;
}

}  // namespace vi::test
