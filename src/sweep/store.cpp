#include "sweep/store.hpp"

#include <filesystem>
#include <stdexcept>

#include "model/input_error.hpp"
#include "sweep/table.hpp"

namespace vi {

SweepStore::SweepStore(const std::string& out_dir, bool resume, std::size_t points, const std::string& fingerprint,
                       std::string csv_header, bool retry_failed)
    : csv_header_(std::move(csv_header)), rows_(points), failed_(points, false) {
    if (out_dir.empty()) return;
    namespace fs = std::filesystem;
    journal_path_ = (fs::path(out_dir) / SweepJournal::kFileName).string();
    // Locked before the journal is looked at: a journal another run is writing is not an
    // interrupted sweep's, and two resumes must not compute the same points.
    lock_.emplace(out_dir);
    std::error_code ec;
    const bool exists = fs::exists(journal_path_, ec);
    if (exists && !resume) {
        throw InputError(journal_path_ +
                         ": an interrupted sweep left this journal; pass --resume to finish it, or remove the file "
                         "to start over");
    }
    if (exists) {
        const JournalContents contents = SweepJournal::read(journal_path_, fingerprint, points, csv_header_);
        for (const auto& [index, row] : contents.rows) {
            const std::string status = sweep_row_status(row);
            if (retry_failed && status != "ok") continue;
            add({index, status, row});
        }
        from_journal_ = done_;
        journal_.emplace(SweepJournal::reopen(journal_path_, contents));
        return;
    }
    journal_.emplace(SweepJournal::create(journal_path_, fingerprint, points, csv_header_));
}

std::vector<std::size_t> SweepStore::todo() const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        if (!rows_[i]) out.push_back(i);
    }
    return out;
}

void SweepStore::add(const FinishedPoint& p) {
    if (p.index >= rows_.size()) throw std::out_of_range("sweep: point index out of range");
    if (rows_[p.index]) return;
    // Journal first: a point counts as done only once it would survive an interruption.
    if (journal_) journal_->append(p.index, p.row);
    rows_[p.index] = p.row;
    failed_[p.index] = p.status != "ok";
    ++done_;
}

std::vector<std::pair<std::size_t, std::string>> SweepStore::failures() const {
    std::vector<std::pair<std::size_t, std::string>> out;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        if (failed_[i]) out.emplace_back(i, sweep_row_status(*rows_[i]));
    }
    return out;
}

std::string SweepStore::csv() const {
    if (!complete()) throw std::logic_error("sweep: the CSV of an incomplete sweep");
    std::string out = csv_header_ + "\n";
    for (const auto& row : rows_) out += *row + "\n";
    return out;
}

void SweepStore::finish(const std::string& out_dir, const std::string& summary_json) {
    finish_with(out_dir, {{kCsvName, csv()}, {kJsonName, summary_json}});
}

void SweepStore::finish_with(const std::string& out_dir, const OutputFiles& files) {
    write_output_files(out_dir, files);
    if (journal_) journal_->remove();
    journal_.reset();
}

}  // namespace vi
