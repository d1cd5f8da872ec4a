#pragma once
// The journal of an optimisation: every computed design, appended and flushed as it finishes, so
// that a stopped search resumes without computing them again (docs/optimization.md, "Resume").

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "design/design_problem.hpp"
#include "design/design_store.hpp"
#include "sweep/folder_lock.hpp"

namespace vi {

// Everything that decides a design's outcome and what the search makes of it, as text: the case
// file's contents (not its path), the variables with their bounds, the objective and its sense,
// the constraints and the analysis. The search's budget (--max-evals, --global-evals), the threads
// and the point timeout are left out: a design's outcome does not depend on them (a design that
// timed out stays so, as in a sweep).
std::string design_identity_text(std::string_view case_text, const DesignProblem& p);

// An open journal file, appended to one design at a time.
//
// Format: "# vibroimpact optimize journal 1", "# problem <16 hex digits>", the line
// "x,<objective>,<constrained quantities...>,status", then one line per design: its variables as
// the 16 hex digits of each double's bits separated by ':', its objective and constrained
// quantities (shortest round-trip decimals, empty where the run reports none), its status.
class DesignJournal {
public:
    // The file name inside the output folder.
    static constexpr const char* kFileName = "optimize.journal";

    // The journal of folder `dir` (created if needed), locked for this run (sweep/folder_lock.hpp)
    // until the journal is destroyed. A journal there is read with `resume` (its designs in
    // designs()) and is an InputError without it; with `resume` and no journal a new one starts.
    // Throws InputError when another run holds the folder, and naming the file (and line) for a
    // journal of another problem or a damaged line (a refusal leaves nothing behind); a last line
    // without its newline (a killed process) is dropped. std::runtime_error when the file cannot
    // be written.
    DesignJournal(const std::string& dir, bool resume, const std::string& identity, const DesignProblem& p);

    [[nodiscard]] const std::vector<ComputedDesign>& designs() const { return designs_; }
    [[nodiscard]] const std::string& path() const { return path_; }
    // Designs in the file: those read and those appended since.
    [[nodiscard]] std::size_t size() const { return lines_; }

    // Appends one design and flushes it to the operating system (it survives a killed process, not
    // a power cut). Throws std::runtime_error when the write fails.
    void append(const ComputedDesign& d);

    // Closes the file and deletes it (once the final files are written, or when a run that started
    // it is refused: it then leaves nothing).
    void remove();
    // Whether this run started the journal (rather than resuming one).
    [[nodiscard]] bool started_here() const { return started_here_; }

private:
    struct Closer {
        void operator()(std::FILE* f) const { std::fclose(f); }
    };
    void read(const std::string& identity);
    const DesignProblem& p_;
    std::string path_;
    std::string header_;
    std::vector<ComputedDesign> designs_;
    std::size_t complete_bytes_ = 0;
    std::size_t lines_ = 0;
    bool started_here_ = false;
    std::optional<FolderLock> lock_;  // before the file: released after it is closed
    std::unique_ptr<std::FILE, Closer> file_;
};

}  // namespace vi
