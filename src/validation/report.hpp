#pragma once
// The validation documents of `vibroimpact validate`: docs/validation.md (the FE model and both
// transient solvers against closed forms and against each other) and docs/paper-parameters.md (what
// the paper leaves out, and the contact-stiffness scan). Every number is computed when the document
// is generated; nothing depends on the date or on timing, so a regeneration is reproducible.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "validation/reference_problems.hpp"
#include "dynamics/piecewise_linear_problem.hpp"
#include "model/case.hpp"

namespace vi {

struct ValidationOptions {
    // Skips section 7 (CVODE on the whole example) and the m = 200 row of section 8, and runs the
    // undamped CVODE energy check on m = 2 instead of m = 10: a document in seconds, for tests.
    bool quick = false;
    Case example;                // the default example, examples/paper/free_impact_tip.toml
    std::string example_path;    // how the document names it
    // Called with one line after each step that takes noticeable time (the command prints it on
    // stderr); may be empty.
    std::function<void(const std::string&)> progress;
    // Called with (0, sections) before the document's sections start and (done, sections) as each
    // ends, one call at a time; may be empty.
    std::function<void(std::size_t done, std::size_t sections)> sections_done;
    int threads = 0;             // worker threads for the sections (0: every usable CPU)
};

// docs/validation.md.
std::string validation_report(const ValidationOptions& o);

// docs/paper-parameters.md.
std::string paper_parameters_report(const ValidationOptions& o);

// Pieces shared by the report's source files (validation_*.cpp); not a stable interface.
namespace validation_detail {

// Circular frequency of a bending mode with the given beta l on the case's beam [rad/s].
double closed_omega(const Case& c, double beta_l);

// |a - b| / |b|.
double rel(double a, double b);

// Number formats: `sig` significant digits; errors with two digits ("3.1e-09", "0" when exact).
std::string num(double v, int sig = 6);
std::string err(double v);
std::string fixed(double v, int decimals);
std::string us(double seconds, int decimals = 4);   // "5.4497"
std::string opt_us(const std::optional<double>& seconds, int decimals = 4);  // us, or "n/a" when none

// A Markdown table.
struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    void add(std::vector<std::string> row) { rows.push_back(std::move(row)); }
    [[nodiscard]] std::string str() const;
};

// Sections of docs/validation.md, each a Markdown fragment starting with its "## N." heading.
std::string section_static(const ValidationOptions& o);
std::string section_frequencies(const ValidationOptions& o);
std::string section_shapes(const ValidationOptions& o);
std::string section_supported(const ValidationOptions& o);
std::string section_single_dof(const ValidationOptions& o);
std::string section_energy(const ValidationOptions& o);
std::string section_exact_vs_cvode(const ValidationOptions& o);
std::string section_mesh(const ValidationOptions& o);
std::string section_loads(const ValidationOptions& o);
std::string section_electrostatics(const ValidationOptions& o);
// Section 11: the checks that run in the test suite only, with their references (static text).
std::string section_elsewhere();

void report_progress(const ValidationOptions& o, const std::string& line);

}  // namespace validation_detail
}  // namespace vi
