#pragma once
// The parts of the Python module _vibroimpact, each bound by its own file, and the helpers they share.

#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "fem/system.hpp"
#include "io/progress_report.hpp"
#include "io/output_files.hpp"
#include "model/case.hpp"

namespace vi::python {

namespace py = pybind11;

// errors.cpp: the exception classes InputError (file, line, key, reason) and SolverError, and the
// translation of the library's exceptions into them.
void bind_errors(py::module_& m);
// case_binding.cpp: the class Case (from a file, a TOML string or a dict; get and set by path).
void bind_case(py::module_& m);
// analyses.cpp: modes, simulate, pullin.
void bind_analyses(py::module_& m);
// sweep_binding.cpp: sweep.
void bind_sweep(py::module_& m);
// uq_binding.cpp: uq.
void bind_uq(py::module_& m);
// design_binding.cpp: fit and optimize.
void bind_design(py::module_& m);
// paper_binding.cpp: paper.
void bind_paper(py::module_& m);

// convert.cpp: a CSV text as written by the command line -> dict of numpy arrays, one per column
// in file order (read by io/csv_reader.hpp): int64 for integer_columns without a missing value,
// else float64 (NaN for the missing-value marker "nan", or an empty cell), str for a column holding text.
py::dict csv_columns(const std::string& csv, const std::set<std::string>& integer_columns = {});
// convert.cpp: a JSON text -> the same Python value json.loads would give.
py::object json_value(const std::string& json);
// convert.cpp: result files (name -> text) -> dict keyed by the name without extension: CSV as
// csv_columns, JSON as json_value.
py::dict files_dict(const OutputFiles& files);

// run_guard.cpp: runs work() on a worker thread with the GIL released; Ctrl-C (a pending
// KeyboardInterrupt) sets the library's stop flag, and the interrupt is raised once work() has
// stopped. Exceptions of work() are rethrown here. The stop flag is process-wide: a Ctrl-C stops
// every run under way. while_waiting (if given) is called with the GIL held every 50 ms while work()
// runs and once after it ends.
void run_released(const std::function<void()>& work, const std::function<void()>& while_waiting = {});

// progress_output.cpp: the progress report of a long run (io/progress_report.hpp) written to Python's
// sys.stderr, where a notebook, a log or pytest sees it. The workers queue the text; the interpreter's
// thread writes it as run_released waits (flush as while_waiting).
class PythonProgress {
public:
    // mode: the `progress` argument, "auto", "bar", "lines" or "none"; None: $VIBROIMPACT_PROGRESS,
    // else auto (a bar when sys.stderr is a terminal, lines otherwise). interval_s: seconds between
    // two lines, 0 for a line at every step. Throws InputError naming `progress` or
    // `progress_interval`. Needs the GIL.
    PythonProgress(const std::optional<std::string>& mode, double interval_s);
    [[nodiscard]] ProgressStyle style() const { return style_; }
    [[nodiscard]] double interval_s() const { return interval_s_; }
    // What Progress writes through: queues the text (any thread).
    [[nodiscard]] ProgressSink sink() const;
    // Writes the queued text to sys.stderr; needs the GIL. A failing write drops the text: the report
    // never stops a run.
    void flush() const;

private:
    struct Queue;
    ProgressStyle style_ = ProgressStyle::none;
    double interval_s_ = 10.0;
    std::shared_ptr<Queue> queue_;
};

// Finishes a progress report when the run ends, by an exception too (the bar's last line ended
// before the exception's message), on the run's thread so that the last flush writes it.
struct FinishProgress {
    Progress& progress;
    ~FinishProgress() { progress.finish(); }
};

// analyses.cpp: "pin" or "spring" (the --support-model option); InputError otherwise.
SupportModel support_model_of(const std::string& name);

}  // namespace vi::python
