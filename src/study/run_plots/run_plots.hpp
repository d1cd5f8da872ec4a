#pragma once
// The figures of a run folder: what `vibroimpact plot DIR` draws from the files a simulate, modes or
// sweep command wrote, found by the files present.

#include <string>
#include <vector>

#include "plot/figure_gnuplot.hpp"

namespace vi {

enum class RunKind { transient, modes, sweep };

// "simulate", "modes" or "sweep": the command that writes such a folder.
const char* run_kind_name(RunKind k);

// The kind of run folder `dir` is: sweep.csv -> sweep, history.csv -> transient, shapes_*.csv -> modes.
// Throws InputError naming dir when it is not a folder or holds none of them.
RunKind run_kind(const std::string& dir);

struct RunPlots {
    RunKind kind = RunKind::transient;
    std::vector<FigureSpec> figures;  // 2400 px wide, with units on every axis
    std::vector<std::string> skipped; // columns not drawn and why: "status (text)", "Tp_s (no finite value)"
};

// Reads the folder and builds its figures (not yet rendered). Throws InputError("FILE:LINE: reason")
// for a file that is missing, unreadable or not what the command writes.
RunPlots run_plots(const std::string& dir);

}  // namespace vi
