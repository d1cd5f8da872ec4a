#include "spelling_hints.hpp"

#include <string_view>
#include <vector>

#include "io/spelling.hpp"

namespace vi::cli {
namespace {

std::string hint(const std::string& written, const std::string& guess) {
    return "; '" + written + "' is unknown: did you mean '" + guess + "'?";
}

// The long names ("--json") of the options of a subcommand, its help included.
std::vector<std::string> long_names(const CLI::App& sub) {
    std::vector<std::string> out;
    for (const CLI::Option* o : sub.get_options()) {
        for (const std::string& n : o->get_lnames()) out.push_back("--" + n);
    }
    return out;
}

}  // namespace

std::string spelling_hint(const CLI::App& app, int argc, const char* const* argv) {
    if (argc < 2) return "";
    const std::string first = argv[1];
    std::vector<std::string> commands;
    const CLI::App* sub = nullptr;
    for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; })) {
        commands.push_back(s->get_name());
        if (s->get_name() == first) sub = s;
    }
    if (sub == nullptr) {
        if (first.empty() || first.front() == '-') return "";
        const auto guess = closest_spelling(first, std::vector<std::string_view>(commands.begin(), commands.end()));
        return guess ? hint(first, *guess) : "; '" + first + "' is not a command";
    }
    const std::vector<std::string> names = long_names(*sub);
    for (int i = 2; i < argc; ++i) {
        const std::string word = argv[i];
        if (word == "--") break;
        if (word.rfind("--", 0) != 0) continue;
        const std::string name = word.substr(0, word.find('='));
        bool known = false;
        for (const std::string& n : names) known = known || n == name;
        if (known) continue;
        const auto guess = closest_spelling(name, std::vector<std::string_view>(names.begin(), names.end()));
        if (guess) return hint(name, *guess);
    }
    return "";
}

}  // namespace vi::cli
