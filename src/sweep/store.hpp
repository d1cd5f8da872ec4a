#pragma once
// The finished rows of a sweep, kept by the process that writes the files: in memory, in the
// journal of the output folder as they arrive, and at the end as the final CSV in grid order.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sweep/folder_lock.hpp"
#include "sweep/ranks.hpp"
#include "io/output_files.hpp"
#include "io/sweep_journal.hpp"

namespace vi {

// Where a sweep's rows go, and which points are still to compute.
class SweepStore {
public:
    // The CSV file and the JSON summary a finished sweep writes into its folder.
    static constexpr const char* kCsvName = "sweep.csv";
    static constexpr const char* kJsonName = "sweep.json";

    // out_dir empty: rows kept in memory only. Otherwise the folder is locked for this run
    // (sweep/folder_lock.hpp) and gets a journal: a new one, or with `resume` the one an
    // interrupted run left (whose points are then done). Throws InputError when another run holds
    // the folder, when a journal is there without `resume`, when it belongs to another sweep, or
    // when the folder cannot be made (a refusal leaves nothing behind); std::runtime_error when the
    // journal cannot be written. With
    // `retry_failed`, the journal's failed points (error or timeout) are left to compute again.
    SweepStore(const std::string& out_dir, bool resume, std::size_t points, const std::string& fingerprint,
               std::string csv_header, bool retry_failed = false);

    // Grid indices not done yet, ascending.
    [[nodiscard]] std::vector<std::size_t> todo() const;
    // Records a finished point (the first time it is seen) and appends it to the journal.
    void add(const FinishedPoint& p);

    [[nodiscard]] std::size_t points() const { return rows_.size(); }
    [[nodiscard]] std::size_t done() const { return done_; }
    [[nodiscard]] std::size_t from_journal() const { return from_journal_; }
    [[nodiscard]] std::size_t computed() const { return done_ - from_journal_; }
    [[nodiscard]] bool complete() const { return done_ == rows_.size(); }
    // (grid index, status) of every failed point, in index order.
    [[nodiscard]] std::vector<std::pair<std::size_t, std::string>> failures() const;
    [[nodiscard]] const std::string& journal_path() const { return journal_path_; }

    // Header and every row in grid order; only for a complete sweep.
    [[nodiscard]] std::string csv() const;
    // Writes the CSV and summary_json into the folder together (write_output_files) and removes
    // the journal. Throws std::runtime_error when the files cannot be written.
    void finish(const std::string& out_dir, const std::string& summary_json);
    // The same with files of the caller's choosing (the CSV among them under its own name).
    void finish_with(const std::string& out_dir, const OutputFiles& files);

private:
    std::string csv_header_;
    std::vector<std::optional<std::string>> rows_;
    std::vector<bool> failed_;
    std::size_t done_ = 0;
    std::size_t from_journal_ = 0;
    std::string journal_path_;
    std::optional<FolderLock> lock_;  // before the journal: released after it is closed
    std::optional<SweepJournal> journal_;
};

}  // namespace vi
