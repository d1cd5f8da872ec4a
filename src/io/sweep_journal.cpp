#include "io/sweep_journal.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "model/input_error.hpp"
#include "io/text_file.hpp"

namespace vi {
namespace {

constexpr std::string_view kMagic = "# vibroimpact sweep journal 1";

std::vector<std::string_view> complete_lines(std::string_view text, std::size_t& complete_bytes) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    for (std::size_t nl = text.find('\n'); nl != std::string_view::npos; nl = text.find('\n', start)) {
        lines.push_back(text.substr(start, nl - start));
        start = nl + 1;
    }
    complete_bytes = start;
    return lines;
}

std::string header_text(const std::string& fingerprint, std::size_t points, const std::string& csv_header) {
    return std::string(kMagic) + "\n# fingerprint " + fingerprint + "\n# points " + std::to_string(points) +
           "\nindex," + csv_header + "\n";
}

}  // namespace

JournalContents SweepJournal::read(const std::string& path, const std::string& fingerprint, std::size_t points,
                                   const std::string& csv_header) {
    std::string reason;
    const auto text = file_text(path, reason);
    if (!text) throw InputError(one_line(path + ": cannot read file (" + reason + ")"));
    JournalContents out;
    const std::vector<std::string_view> lines = complete_lines(*text, out.complete_bytes);
    out.torn_tail = out.complete_bytes < text->size();
    if (lines.size() < 4 || lines[0] != kMagic) {
        throw InputError(path + ": not a sweep journal (or its header was cut short); remove it to start over");
    }
    if (lines[1] != "# fingerprint " + fingerprint || lines[2] != "# points " + std::to_string(points) ||
        lines[3] != "index," + csv_header) {
        throw InputError(path +
                         ": belongs to another sweep (the case file, the --set list or the analysis differ); "
                         "run that sweep again with --resume, or remove the journal to start over");
    }
    for (std::size_t n = 4; n < lines.size(); ++n) {
        const std::string_view line = lines[n];
        const std::size_t comma = line.find(',');
        const std::string_view digits = line.substr(0, comma);
        std::size_t index = 0;
        bool ok = comma != std::string_view::npos && comma + 1 < line.size() && !digits.empty() && digits.size() <= 18 &&
                  digits.find_first_not_of("0123456789") == std::string_view::npos;
        if (ok) {
            index = std::stoull(std::string(digits));
            ok = index < points;
        }
        if (!ok) {
            throw InputError(one_line(path + ":" + std::to_string(n + 1) +
                                      ": not a journal line \"<index>,<row>\"; remove the journal to start over"));
        }
        // The last line of a point wins: a failed point computed again after --retry-failed.
        out.rows[index] = std::string(line.substr(comma + 1));
    }
    return out;
}

SweepJournal SweepJournal::create(const std::string& path, const std::string& fingerprint, std::size_t points,
                                  const std::string& csv_header) {
    std::FILE* f = std::fopen(path.c_str(), "wbx");
    if (!f) throw std::runtime_error(path + ": cannot create the journal (" + std::strerror(errno) + ")");
    SweepJournal j(path, f);
    const std::string head = header_text(fingerprint, points, csv_header);
    if (std::fwrite(head.data(), 1, head.size(), f) != head.size() || std::fflush(f) != 0) {
        throw std::runtime_error(path + ": cannot write the journal (" + std::strerror(errno) + ")");
    }
    return j;
}

SweepJournal SweepJournal::reopen(const std::string& path, const JournalContents& contents) {
    std::error_code ec;
    if (contents.torn_tail) std::filesystem::resize_file(path, contents.complete_bytes, ec);
    if (ec) throw std::runtime_error(path + ": cannot cut the torn last line (" + ec.message() + ")");
    std::FILE* f = std::fopen(path.c_str(), "ab");
    if (!f) throw std::runtime_error(path + ": cannot open the journal (" + std::strerror(errno) + ")");
    return SweepJournal(path, f);
}

void SweepJournal::append(std::size_t index, const std::string& row) {
    const std::string line = std::to_string(index) + "," + row + "\n";
    if (!file_ || std::fwrite(line.data(), 1, line.size(), file_.get()) != line.size() || std::fflush(file_.get()) != 0) {
        throw std::runtime_error(path_ + ": cannot write the journal (" + std::strerror(errno) + ")");
    }
}

void SweepJournal::remove() {
    file_.reset();
    std::error_code ec;
    std::filesystem::remove(path_, ec);
}

}  // namespace vi
