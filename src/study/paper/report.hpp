#pragma once
// The paper-reproduction report (report.html and its Markdown twin report.md) and every file of the
// `vibroimpact paper` output folder.

#include <string>
#include <vector>

#include "study/paper/claims.hpp"
#include "study/paper/study.hpp"
#include "io/output_files.hpp"
#include "plot/figure_gnuplot.hpp"
#include "plot/report_document.hpp"

namespace vi {

// How the report was made, for its "what was run" and timing sections.
struct ReportRun {
    std::string version;       // e.g. "vibroimpact 0.1.0"
    std::string command;       // the command line, for the reader to rerun
    double figures_s = 0.0;    // wall time of drawing the figures with gnuplot [s]
    double total_s = 0.0;      // wall time from start to the report, files not yet written [s]
};

// The report's content: what was run, the claims table, every figure with its caption, the
// parameters the paper does not give (value and why), and the timing.
ReportDocument paper_report(const PaperStudy& study, const std::vector<Claim>& claims, const std::vector<FigureSpec>& figures,
                            const ReportRun& run);

// The parameters the paper does not give, each with the value used and why: rows of
// {parameter, value, why}.
std::vector<std::vector<std::string>> unstated_parameters(const PaperStudy& study);

// The claims as JSON: [{"id", "where", "paper", "ours", "verdict", "note", "values": {...}}].
std::string claims_json(const std::vector<Claim>& claims);

// Every file of the output folder: per figure <name>.png, .svg, .gp and its CSVs; report.html,
// report.md and claims.json. `rendered` is in the order of `figures`.
OutputFiles paper_output_files(const PaperStudy& study, const std::vector<Claim>& claims, const std::vector<FigureSpec>& figures,
                               const std::vector<RenderedFigure>& rendered, const ReportRun& run);

}  // namespace vi
