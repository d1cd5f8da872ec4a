// docs/validation.md sections 7 and 8: the default example through both solvers, and its mesh
// convergence.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>
#include <sstream>

#include "model/run_control.hpp"
#include "impacts/simulation.hpp"
#include "validation/report.hpp"

namespace vi::validation_detail {
namespace {

using Clock = std::chrono::steady_clock;



std::string opt_rel(const std::optional<double>& a, const std::optional<double>& b) {
    return a && b ? err(rel(*a, *b)) : "n/a";
}

// Largest sampled tip displacement above the final equilibrium after the first contact begins: the
// y_max of the time history at the output step (CVODE reports no root-found extremes).
std::optional<double> sampled_y_max(const SimulationRun& run) {
    if (run.result.episodes.empty() || run.built.problem.tip_dof < 0) return std::nullopt;
    const double t_on = run.result.episodes.front().t_on;
    const auto& h = run.result.history;
    std::optional<double> best;
    for (std::size_t i = 0; i < h.t.size(); ++i) {
        if (h.t[i] < t_on) continue;
        if (!best || h.tip_v[i] > *best) best = h.tip_v[i];
    }
    if (!best) return std::nullopt;
    return *best - run.built.start.q_equilibrium[run.built.problem.tip_dof];
}

}  // namespace

std::string section_exact_vs_cvode(const ValidationOptions& o) {
    std::ostringstream s;
    s << "## 7. Exact vs CVODE on the default example\n\n";
    if (o.quick) {
        s << "Skipped with `--quick`.\n\n";
        return s.str();
    }
    const Case& c = o.example;
    s << "`" << o.example_path << "` as it is (m = " << c.beam.elements << ", horizon "
      << us(c.solver.horizon, 1) << " us, output step " << us(c.solver.output_step, 3)
      << " us), run with `solver.method = \"exact\"` and with `\"cvode\"` (rtol " << num(c.solver.rtol, 2)
      << "). The two solvers share only the problem builder: the exact one propagates modal exponentials "
         "and finds events by certified root search, CVODE integrates with BDF steps (in the coordinates of "
         "every bending mode, docs/model.md section 13) and its own root "
         "finding. Relative differences are |CVODE - exact| / |exact|.\n\n";
    Case ce = c, cc = c;
    ce.solver.method = SolverSettings::Method::exact;
    cc.solver.method = SolverSettings::Method::cvode;
    auto t0 = Clock::now();
    const SimulationRun ex = run_simulation(ce);
    report_progress(o, "section 7: exact run (" + fixed(seconds_since(t0), 1) + " s)");
    t0 = Clock::now();
    std::optional<SimulationRun> cv;
    std::string failure;
    try {
        cv = run_simulation(cc);
    } catch (const std::exception& e) {
        failure = e.what();
    }
    report_progress(o, "section 7: CVODE run (" + fixed(seconds_since(t0), 1) + " s)");
    if (!cv) {
        s << "**CVODE failed:** " << failure << "\n\n";
        return s.str();
    }
    const ImpactSummary& a = ex.summary;
    const ImpactSummary& b = cv->summary;
    Table t{{"impact", "onset t_on, exact [us]", "onset, CVODE [us]", "rel. difference"}, {}};
    const std::size_t n = std::min<std::size_t>({10, a.impacts.size(), b.impacts.size()});
    double worst = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double d = rel(b.impacts[i].t_on, a.impacts[i].t_on);
        worst = std::max(worst, d);
        t.add({std::to_string(i + 1), num(a.impacts[i].t_on * 1e6, 10), num(b.impacts[i].t_on * 1e6, 10), err(d)});
    }
    s << "**Impact onsets** (impacts as grouped with the default gap):\n\n" << t.str() << "\n";

    Table q{{"quantity", "exact", "CVODE", "rel. difference"}, {}};
    q.add({"max rel. difference of the first " + std::to_string(n) + " onsets", "-", "-", err(worst)});
    q.add({"contact episodes (impacts)",
           std::to_string(ex.result.episodes.size()) + " (" + std::to_string(a.impacts.size()) + ")",
           std::to_string(cv->result.episodes.size()) + " (" + std::to_string(b.impacts.size()) + ")", "-"});
    q.add({"T, first cycle [us]", opt_us(a.T_first), opt_us(b.T_first), opt_rel(b.T_first, a.T_first)});
    q.add({"T1, first cycle [us]", opt_us(a.T1_first), opt_us(b.T1_first), opt_rel(b.T1_first, a.T1_first)});
    q.add({"T2, first cycle [us]", opt_us(a.T2_first), opt_us(b.T2_first), opt_rel(b.T2_first, a.T2_first)});
    q.add({"T_p [us]", opt_us(a.Tp) + " (" + a.Tp_reason + ")", opt_us(b.Tp) + " (" + b.Tp_reason + ")",
           opt_rel(b.Tp, a.Tp)});
    const std::optional<double> ya = sampled_y_max(ex), yb = sampled_y_max(*cv);
    auto nm = [](const std::optional<double>& v) { return v ? num(*v * 1e9, 6) : std::string("n/a"); };
    q.add({"y_max [nm] (summary)", nm(a.y_max), b.y_max ? nm(b.y_max) : "not reported", opt_rel(b.y_max, a.y_max)});
    q.add({"y_max [nm] sampled at the output step", nm(ya), nm(yb), opt_rel(yb, ya)});
    if (a.y_max && ya) q.add({"exact: sampled vs root-found y_max", nm(ya), nm(a.y_max) + " (root-found)", opt_rel(ya, a.y_max)});
    s << q.str() << "\n";
    if (!b.y_max) {
        s << "CVODE does not fill the root-found extremes (`TransientResult::extremes`), so its summary has no "
             "y_max; the sampled row compares both solvers' time histories at the same output step.\n\n";
    }
    return s.str();
}

std::string section_mesh(const ValidationOptions& o) {
    std::ostringstream s;
    s << "## 8. Mesh convergence of the default example\n\n";
    std::vector<int> meshes = {10, 20, 50, 100, 200};
    if (o.quick) meshes = {10, 20, 50};
    const int ref_m = meshes.back();
    s << "`" << o.example_path << "` with the exact solver and `beam.elements` = m; every other setting as "
      << "in the file (group gap and settle tolerance included). Changes are relative to m = " << ref_m
      << (o.quick ? " (m = 100 and 200 skipped with `--quick`)" : "") << ".\n\n";
    struct Row {
        int m = 0;
        std::optional<ImpactSummary> summary;
        std::size_t episodes = 0;
        std::string failure;
    };
    std::vector<Row> rows;
    const Row* ref = nullptr;  // the finest mesh that ran
    for (int m : meshes) {
        Case c = o.example;
        c.beam.elements = m;
        c.solver.method = SolverSettings::Method::exact;
        SimulationOptions so;
        so.history = false;
        so.energy = false;
        const auto t0 = Clock::now();
        Row row{m, std::nullopt, 0, ""};
        try {
            const SimulationRun run = run_simulation(c, so);
            row.summary = run.summary;
            row.episodes = run.result.episodes.size();
        } catch (const std::exception& e) {
            row.failure = e.what();
        }
        rows.push_back(row);
        report_progress(o, "section 8: m = " + std::to_string(m) + " (" + fixed(seconds_since(t0), 1) + " s)" +
                               (row.failure.empty() ? "" : ": " + row.failure));
    }
    for (const Row& row : rows) {
        if (row.summary) ref = &row;
    }
    if (ref == nullptr) {
        s << "Every mesh failed: " << rows.back().failure << "\n\n";
        return s.str();
    }
    if (ref->m != ref_m) {
        s << "**m = " << ref_m << " did not run, so the changes are relative to m = " << ref->m << ".**\n\n";
    }
    const ImpactSummary& r = *ref->summary;
    Table t{{"m", "episodes (impacts)", "T [us]", "change", "T2 [us]", "change", "y_max [nm]", "change", "T_p [us]",
             "change"},
            {}};
    for (const Row& row : rows) {
        if (!row.summary) {
            t.add({std::to_string(row.m), "exact solver failed (below)", "-", "-", "-", "-", "-", "-", "-", "-"});
            continue;
        }
        const ImpactSummary& x = *row.summary;
        const std::string y = x.y_max ? num(*x.y_max * 1e9, 6) : "n/a";
        t.add({std::to_string(row.m), std::to_string(row.episodes) + " (" + std::to_string(x.impacts.size()) + ")",
               opt_us(x.T_first), opt_rel(x.T_first, r.T_first), opt_us(x.T2_first), opt_rel(x.T2_first, r.T2_first), y,
               opt_rel(x.y_max, r.y_max), opt_us(x.Tp) + " (" + x.Tp_reason + ")", opt_rel(x.Tp, r.Tp)});
    }
    s << t.str() << "\n";
    // The largest change of the four quantities on each mesh, in words.
    for (const Row& row : rows) {
        if (!row.summary || &row == ref) continue;
        const ImpactSummary& x = *row.summary;
        double worst = 0.0;
        bool all = true;
        auto take = [&](const std::optional<double>& a, const std::optional<double>& b) {
            if (a && b) {
                worst = std::max(worst, rel(*a, *b));
            } else {
                all = false;
            }
        };
        take(x.T_first, r.T_first);
        take(x.T2_first, r.T2_first);
        take(x.y_max, r.y_max);
        take(x.Tp, r.Tp);
        s << "- m = " << row.m << (row.m == o.example.beam.elements ? " (the example's mesh)" : "")
          << ": the four quantities lie within " << err(worst) << " of m = " << ref->m
          << (all ? "" : " (where both are defined)") << ".\n";
    }
    s << "\n";
    // Failures, the meshes with the same message together.
    std::vector<std::pair<std::string, std::string>> failures;  // message, meshes
    for (const Row& row : rows) {
        if (row.summary) continue;
        auto it = std::find_if(failures.begin(), failures.end(), [&](const auto& f) { return f.first == row.failure; });
        if (it == failures.end()) {
            failures.emplace_back(row.failure, "m = " + std::to_string(row.m));
        } else {
            it->second += " and " + std::to_string(row.m);
        }
    }
    for (const auto& [message, which] : failures) {
        s << which << " could not run: the exact solver stopped with \"" << message << "\".\n\n";
    }
    return s.str();
}

}  // namespace vi::validation_detail
