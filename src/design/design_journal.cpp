#include "design/design_journal.hpp"

#include <bit>
#include <cerrno>
#include <cinttypes>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "io/number_text.hpp"
#include "io/text_file.hpp"
#include "model/input_error.hpp"
#include "sweep/identity.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {

constexpr std::string_view kMagic = "# vibroimpact optimize journal 1";

std::string exact(double v) { return significant(v, 17); }

std::string cell(const std::optional<double>& v) { return v ? round_trip_text(*v) : ""; }

// "x,<objective>,<constrained quantities>,status".
std::string header_of(const DesignProblem& p) {
    std::string h = "x," + p.columns.at(p.objective).name;
    for (const DesignConstraint& c : p.constraints) h += "," + p.columns.at(c.column).name;
    return h + ",status";
}

// The 16 hex digits of each variable's bits, separated by ':'.
std::string key_text(const std::vector<double>& x) {
    std::string t;
    char buf[20];
    for (const std::uint64_t bits : design_key(x)) {
        std::snprintf(buf, sizeof buf, "%016" PRIx64, bits);
        if (!t.empty()) t += ':';
        t += buf;
    }
    return t;
}

std::optional<std::vector<double>> parse_key(std::string_view text, std::size_t n) {
    std::vector<double> x;
    while (x.size() < n) {
        const std::string_view part = text.substr(0, 16);
        if (part.size() != 16 || part.find_first_not_of("0123456789abcdef") != std::string_view::npos) return std::nullopt;
        const std::uint64_t bits = std::strtoull(std::string(part).c_str(), nullptr, 16);
        x.push_back(std::bit_cast<double>(bits));
        text.remove_prefix(16);
        if (x.size() < n) {
            if (text.empty() || text.front() != ':') return std::nullopt;
            text.remove_prefix(1);
        }
    }
    if (!text.empty()) return std::nullopt;
    return x;
}

// An empty cell is no value; otherwise the whole cell must be a number.
bool parse_value(std::string_view text, std::optional<double>& out) {
    out.reset();
    if (text.empty()) return true;
    const std::string s(text);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return false;
    out = v;
    return true;
}

// One design line: the key, 1 + constraints values, then the status (the rest of the line; a
// status is one line and may hold commas).
std::optional<ComputedDesign> parse_line(std::string_view line, const DesignProblem& p) {
    std::vector<std::string_view> cells;
    const std::size_t fixed = 2 + p.constraints.size();
    while (cells.size() < fixed) {
        const std::size_t comma = line.find(',');
        if (comma == std::string_view::npos) return std::nullopt;
        cells.push_back(line.substr(0, comma));
        line.remove_prefix(comma + 1);
    }
    if (line.empty()) return std::nullopt;
    ComputedDesign d;
    const auto x = parse_key(cells[0], p.variables.size());
    if (!x) return std::nullopt;
    d.x = *x;
    d.outcome.status = std::string(line);
    if (!parse_value(cells[1], d.outcome.objective)) return std::nullopt;
    d.outcome.constraints.resize(p.constraints.size());
    for (std::size_t k = 0; k < p.constraints.size(); ++k) {
        if (!parse_value(cells[2 + k], d.outcome.constraints[k])) return std::nullopt;
    }
    return d;
}

}  // namespace

std::string design_identity_text(std::string_view case_text, const DesignProblem& p) {
    std::string t = "vibroimpact optimize identity 1\n";
    // The case text is hashed on its own so that no text inside it can mimic the lines below.
    t += "case " + fingerprint_of(case_text) + " " + std::to_string(case_text.size()) + "\n";
    for (const DesignVariable& v : p.variables) t += "vary " + v.path.text() + " " + exact(v.low) + " " + exact(v.high) + "\n";
    t += std::string(p.maximize ? "maximize " : "minimize ") + p.columns.at(p.objective).name + "\n";
    for (const DesignConstraint& c : p.constraints) {
        t += "constraint " + p.columns.at(c.column).name + (c.upper ? " <= " : " >= ") + exact(c.bound) + "\n";
    }
    t += std::string("analysis ") + sweep_analysis_name(p.settings.analysis);
    if (p.settings.analysis == SweepAnalysis::modes) t += " " + std::to_string(p.settings.modes);
    t += "\n";
    return t;
}

DesignJournal::DesignJournal(const std::string& dir, bool resume, const std::string& identity, const DesignProblem& p)
    : p_(p), header_(header_of(p)) {
    namespace fs = std::filesystem;
    path_ = (fs::path(dir) / kFileName).string();
    lock_.emplace(dir);
    std::error_code ec;
    const bool exists = fs::exists(path_, ec);
    if (exists && !resume) {
        throw InputError(path_ +
                         ": a stopped optimisation left this journal; pass --resume to go on with it, or remove the "
                         "file to start over");
    }
    if (exists) {
        read(identity);
        if (complete_bytes_ < fs::file_size(path_, ec) && !ec) fs::resize_file(path_, complete_bytes_, ec);
        if (ec) throw std::runtime_error(path_ + ": cannot cut the torn last line (" + ec.message() + ")");
        file_.reset(std::fopen(path_.c_str(), "ab"));
        if (!file_) throw std::runtime_error(path_ + ": cannot open the journal (" + std::strerror(errno) + ")");
        return;
    }
    file_.reset(std::fopen(path_.c_str(), "wbx"));
    if (!file_) throw std::runtime_error(path_ + ": cannot create the journal (" + std::strerror(errno) + ")");
    started_here_ = true;
    const std::string head = std::string(kMagic) + "\n# problem " + fingerprint_of(identity) + "\n" + header_ + "\n";
    if (std::fwrite(head.data(), 1, head.size(), file_.get()) != head.size() || std::fflush(file_.get()) != 0) {
        throw std::runtime_error(path_ + ": cannot write the journal (" + std::strerror(errno) + ")");
    }
}

void DesignJournal::read(const std::string& identity) {
    std::string reason;
    const auto text = file_text(path_, reason);
    if (!text) throw InputError(one_line(path_ + ": cannot read file (" + reason + ")"));
    std::vector<std::string_view> lines;
    std::string_view rest = *text;
    for (std::size_t nl = rest.find('\n'); nl != std::string_view::npos; nl = rest.find('\n')) {
        lines.push_back(rest.substr(0, nl));
        rest.remove_prefix(nl + 1);
    }
    complete_bytes_ = text->size() - rest.size();
    if (lines.size() < 3 || lines[0] != kMagic) {
        throw InputError(path_ + ": not an optimize journal (or its header was cut short); remove it to start over");
    }
    if (lines[1] != "# problem " + fingerprint_of(identity) || lines[2] != header_) {
        throw InputError(path_ +
                         ": belongs to another optimisation (the case file, the --vary bounds, the quantity or the "
                         "constraints differ); run that one again with --resume, or remove the journal to start over");
    }
    for (std::size_t n = 3; n < lines.size(); ++n) {
        std::optional<ComputedDesign> d = parse_line(lines[n], p_);
        if (!d) {
            throw InputError(path_ + ":" + std::to_string(n + 1) +
                             ": not a journal line \"<x>,<values>,<status>\"; remove the journal to start over");
        }
        designs_.push_back(std::move(*d));
    }
    lines_ = designs_.size();
}

void DesignJournal::append(const ComputedDesign& d) {
    std::string line = key_text(d.x);
    line.append(",").append(cell(d.outcome.objective));
    for (const auto& c : d.outcome.constraints) line.append(",").append(cell(c));
    line.append(",").append(one_line(d.outcome.status)).append("\n");
    if (!file_ || std::fwrite(line.data(), 1, line.size(), file_.get()) != line.size() || std::fflush(file_.get()) != 0) {
        throw std::runtime_error(path_ + ": cannot write the journal (" + std::strerror(errno) + ")");
    }
    ++lines_;
}

void DesignJournal::remove() {
    file_.reset();
    std::error_code ec;
    std::filesystem::remove(path_, ec);
}

}  // namespace vi
