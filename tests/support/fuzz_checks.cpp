#include "support/fuzz_checks.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>

#include "support/text_checks.hpp"

namespace vi::test {
namespace {

namespace fs = std::filesystem;

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

long env_number(const char* name, long fallback) {
    const char* v = std::getenv(name);
    if (v == nullptr || *v == '\0') return fallback;
    char* end = nullptr;
    const long n = std::strtol(v, &end, 10);
    return end != v && *end == '\0' && n >= 0 ? n : fallback;
}

FuzzSettings fuzz_settings() {
    FuzzSettings f;
    f.seed = static_cast<std::uint64_t>(env_number("VI_FUZZ_SEED", static_cast<long>(kFuzzSeed)));
    f.seconds = env_number("VI_FUZZ_SECONDS", 0);
    f.mutants = f.seconds > 0 ? kMaxFuzzMutants : std::min(env_number("VI_FUZZ_MUTANTS", kFuzzMutants), kMaxFuzzMutants);
    f.only = env_number("VI_FUZZ_ONLY", -1);
    f.verbose = env_number("VI_FUZZ_VERBOSE", 0) > 0;
    return f;
}

std::string FuzzSettings::describe() const {
    return "seed " + std::to_string(seed) + ", " +
           (seconds > 0 ? "for " + std::to_string(seconds) + " s" : std::to_string(mutants) + " mutants");
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < text.size()) {
        const auto end = text.find('\n', start);
        out.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return out;
}

bool names_file_line_and_key(const std::string& message, const FuzzRun& run) {
    const std::string dir = run.case_dir + "/";
    // A value an option of the command derives from the case (pullin --dynamic's default horizon) is
    // blamed on the option first, then on the case's key it came from.
    if (starts_with(message, "--")) {
        const std::size_t at = message.find(dir);
        return at != std::string::npos && names_file_line_and_key(message.substr(at), run);
    }
    if (!starts_with(message, dir)) return false;
    const std::size_t colon = message.find(':', dir.size());
    if (colon == std::string::npos || colon == dir.size()) return false;
    const std::string file = message.substr(0, colon);
    std::size_t at = colon + 1;
    const std::size_t digits = at;
    while (at < message.size() && std::isdigit(static_cast<unsigned char>(message[at])) != 0) ++at;
    if (at == digits || message.compare(at, 2, ": ") != 0) return false;
    at += 2;
    // A file the case refers to (a voltage table) is reported at its own line, with or without a column.
    if (file != run.case_path) return true;
    if (message.compare(at, 12, "TOML syntax:") == 0) return true;
    // The key: a dotted path, its parts bare words or quoted; it ends at ": " outside quotes.
    bool quoted = false;
    for (std::size_t i = at; i < message.size(); ++i) {
        const char c = message[i];
        if (c == '"') quoted = !quoted;
        if (quoted) continue;
        if (c == ':' && i + 1 < message.size() && message[i + 1] == ' ') return i > at;
        if (c == ' ') return false;
    }
    return false;
}

std::string run_defect(const CommandResult& r, const FuzzRun& run) {
    if (r.hung) return "no end within " + run.limit + " (killed: a hang)";
    for (const char* marker : {"runtime error:", "AddressSanitizer", "LeakSanitizer", "UndefinedBehaviorSanitizer"}) {
        if (r.err.find(marker) != std::string::npos) return std::string("sanitizer report (") + marker + ")";
    }
    if (r.exit_code < 0 || r.exit_code > 2) return "exit code " + std::to_string(r.exit_code);
    const std::vector<std::string> err = lines_of(r.err);
    if (r.exit_code == 2) {
        if (!is_one_error_line(r.err)) return "exit 2 without exactly one error line";
        if (!names_file_line_and_key(err.front().substr(20), run)) return "exit 2 without file:line: key: " + err.front();
        if (fs::exists(run.out_dir)) return "exit 2 wrote " + run.out_dir;
        if (!r.out.empty()) return "exit 2 printed on stdout";
        return "";
    }
    // Warnings may come first; then, for exit 1, exactly one line saying what failed.
    std::size_t warnings = 0;
    for (const std::string& l : err) warnings += starts_with(l, "vibroimpact: warning: ") ? 1 : 0;
    if (r.exit_code == 1) {
        if (err.size() != warnings + 1) return "exit 1 without exactly one failure line";
        const std::string& last = err.back();
        if (!starts_with(last, "vibroimpact: failure: ") && !starts_with(last, "vibroimpact: error: ")) {
            return "exit 1 with a last line that is not a failure: " + last;
        }
        if (last.size() < 30) return "exit 1 with an empty reason";
        if (fs::exists(run.out_dir)) return "exit 1 wrote " + run.out_dir;
        return "";
    }
    if (err.size() != warnings) return "exit 0 with stderr other than warnings";
    if (!fs::exists(run.expected_file)) return "exit 0 without " + run.expected_file;
    return "";
}

}  // namespace vi::test
