#include "study/paper/study.hpp"

#include <time.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <mutex>
#include <stdexcept>

#include "model/allocator_reuse.hpp"
#include "model/parallel_for.hpp"
#include "model/run_control.hpp"
#include "study/paper/scans.hpp"
#include "problem/beam_model.hpp"
#include "fem/system.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

using Clock = std::chrono::steady_clock;


// CPU time of the calling thread [s]: unlike wall time per job, it does not grow when other work
// shares the machine.
double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

void check_options(const PaperStudyOptions& o) {
    if (o.positions < 2) throw InputError("--positions: at least 2 support positions");
    if (!(o.position_min > 0.0 && o.position_min < 1.0)) throw InputError("position_min: must lie in (0, 1)");
    if (o.modal_positions < 2) throw InputError("modal_positions: at least 2");
    if (o.prestress_points < 2 || !(o.prestress_max > 0.0)) throw InputError("prestress: at least 2 points over a positive range");
    if (o.meshes.empty()) throw InputError("meshes: at least one mesh");
    for (int m : o.meshes) {
        if (m < 1) throw InputError("meshes: every m must be positive");
    }
    for (double x : o.force_positions) {
        if (!(x > 0.0 && x <= 1.0)) throw InputError("force_positions: every x0/l must lie in (0, 1]");
    }
    if (o.modes < 1 || o.free_modes < 3) throw InputError("modes: at least 1 supported and 3 free modes");
}

double first_omega(const Case& c) { return analyse_modes(build_system(c, SupportModel::none), 1).bending.at(0).omega; }

// A part of the study: its jobs report here, and the part's line goes out when the last one ends.
struct Part {
    std::string name;
    std::atomic<int> left{0};
    std::atomic<long long> cpu_us{0};
};

// The parts of the study, each reported when its last job ends.
enum PartId { typical, forces, scans, prestress, modes, part_count };
struct Parts : std::array<Part, part_count> {
    Parts() {
        (*this)[typical].name = "Fig. 3 transient";
        (*this)[forces].name = "Fig. 11 impact forces";
        (*this)[scans].name = "Figs. 4, 5, 10 support-position transients";
        (*this)[prestress].name = "Fig. 9 prestress transients";
        (*this)[modes].name = "Figs. 6-8 supported modes";
    }
};

struct Job {
    PartId part;
    std::function<void()> run;
};

// What a job that must not fail said (the scans keep each point's error in the point).
struct JobErrors {
    std::string typical;
    std::vector<std::string> forces;
};

// The study's points before any run: each transient scan's positions (moving: the free-impact case
// with its support's damper fixed), the prestress values, the modal positions, the force slots.
void lay_out_points(PaperStudy& st, const Case& moving, const std::vector<double>& positions) {
    const PaperStudyOptions& options = st.options;
    for (int m : options.meshes) {
        Case base = moving;
        base.beam.elements = m;
        TransientScan scan;
        scan.elements = m;
        scan.omega1 = first_omega(base);
        scan.horizon = options.position_horizon;
        for (double x : positions) {
            TransientPoint pt;
            pt.x = x;
            scan.points.push_back(pt);
        }
        st.position_scans.push_back(std::move(scan));
    }
    st.prestress.elements = options.cases.prestress.beam.elements;
    st.prestress.omega1 = first_omega(options.cases.prestress);
    st.prestress.horizon = options.cases.prestress.solver.horizon;
    for (int i = 0; i < options.prestress_points; ++i) {
        TransientPoint pt;
        pt.x = options.prestress_max * i / (options.prestress_points - 1);
        st.prestress.points.push_back(pt);
    }
    for (int i = 1; i <= options.modal_positions; ++i) {
        ModalPoint pt;
        pt.x0 = static_cast<double>(i) / options.modal_positions;
        st.modal.push_back(pt);
    }
    st.forces.resize(options.force_positions.size());
}

// Every transient of every figure, the longest first so that no thread is left with a long run at
// the end. Each job writes only its own slot of st.
std::vector<Job> transient_jobs(PaperStudy& st, const Case& moving, const std::vector<double>& positions, JobErrors& errors) {
    const PaperStudyOptions& options = st.options;
    std::vector<Job> jobs;
    jobs.push_back({typical, [&] {
                        try {
                            st.typical = run_typical_transient(options.cases.free_impact);
                        } catch (const std::exception& e) {
                            errors.typical = e.what();
                        }
                    }});
    for (std::size_t i = 0; i < options.force_positions.size(); ++i) {
        jobs.push_back({forces, [&, i] {
                            try {
                                st.forces[i] = run_impact_force(moving, options.force_positions[i]);
                            } catch (const std::exception& e) {
                                errors.forces[i] = e.what();
                            }
                        }});
    }
    for (std::size_t s = 0; s < st.position_scans.size(); ++s) {
        for (std::size_t i = 0; i < positions.size(); ++i) {
            jobs.push_back({scans, [&, s, i] {
                                Case c = moving;
                                c.beam.elements = st.position_scans[s].elements;
                                c.solver.horizon = st.position_scans[s].horizon;
                                c.supports.front().position = positions[i];
                                st.position_scans[s].points[i] = run_transient_point(c, positions[i]);
                            }});
        }
    }
    for (std::size_t i = 0; i < st.prestress.points.size(); ++i) {
        jobs.push_back({prestress, [&, i] {
                            Case c = options.cases.prestress;
                            const double d = st.prestress.points[i].x;
                            c.supports.front().surface = d * c.beam.length;
                            c.supports.front().surface_key = "prestress";
                            st.prestress.points[i] = run_transient_point(c, d);
                        }});
    }
    return jobs;
}

// The modal jobs: the ratio peak (bracketed on a coarse grid, then refined) and each modal position.
void add_modal_jobs(std::vector<Job>& jobs, PaperStudy& st, const std::vector<double>& free_omega) {
    const PaperStudyOptions& options = st.options;
    jobs.push_back({modes, [&] {
                        const double w1 = free_omega.at(0);
                        double best = 0.05, best_ratio = 0.0;
                        for (int i = 1; i <= 20; ++i) {
                            const double x = 0.05 * i;
                            const double r = pinned_first_omega(options.cases.cantilever, x) / w1;
                            if (r > best_ratio) {
                                best_ratio = r;
                                best = x;
                            }
                        }
                        st.ratio_peak = find_ratio_peak(options.cases.cantilever, w1, best - 0.05, std::min(1.0, best + 0.05));
                        st.pinned_tip_omega1 = pinned_first_omega(options.cases.free_impact, 1.0);
                    }});
    for (std::size_t i = 0; i < st.modal.size(); ++i) {
        jobs.push_back({modes, [&, i] {
                            st.modal[i] = run_modal_point(options.cases.cantilever, st.modal[i].x0, options.modes, free_omega);
                        }});
    }
}

// Runs the jobs on `threads` threads, each part's CPU time summed and its line reported as it ends.
void run_jobs(const std::vector<Job>& jobs, Parts& parts, int threads, const PaperStudyOptions& options,
              Clock::time_point t_start) {
    for (const Job& j : jobs) ++parts[j.part].left;
    std::mutex report_mutex;
    auto report = [&](const std::string& line) {
        if (!options.progress) return;
        const std::lock_guard<std::mutex> lock(report_mutex);
        options.progress(line);
    };
    std::size_t jobs_ended = 0;  // under report_mutex
    if (options.jobs_done) options.jobs_done(0, jobs.size());
    parallel_for(jobs.size(), threads, [&](std::size_t k) {
        const double start = thread_cpu_seconds();
        jobs[k].run();
        Part& p = parts[jobs[k].part];
        p.cpu_us += static_cast<long long>(1e6 * (thread_cpu_seconds() - start));
        if (options.jobs_done) {
            const std::lock_guard<std::mutex> lock(report_mutex);
            options.jobs_done(++jobs_ended, jobs.size());
        }
        if (--p.left == 0) {
            char buf[160];
            std::snprintf(buf, sizeof buf, "%s: done (%.2f s of CPU), %.2f s since start", p.name.c_str(), p.cpu_us.load() * 1e-6,
                          seconds_since(t_start));
            report(buf);
        }
    });
}

}  // namespace

std::vector<double> scan_positions(int count, double lo) {
    std::vector<double> x;
    for (int i = 0; i < count; ++i) x.push_back(lo + (1.0 - lo) * i / (count - 1));
    x.back() = 1.0;
    for (double p : {0.67, 0.78, 0.87}) {
        if (p < lo) continue;
        const bool present = std::any_of(x.begin(), x.end(), [&](double v) { return std::abs(v - p) < 1e-9; });
        if (!present) x.push_back(p);
    }
    std::sort(x.begin(), x.end());
    return x;
}

PaperStudy run_paper_study(const PaperStudyOptions& options) {
    check_options(options);
    keep_freed_memory_for_reuse();
    const auto t_start = Clock::now();
    PaperStudy st;
    st.options = options;
    const PaperCases& cases = options.cases;

    // Serial set-up, a few milliseconds: the free modes, and the support's damper. Cc may be given
    // as a damping ratio, which the builder turns into Cc at the support's own position; the support
    // is the same piece of hardware wherever it sits, so the scans keep that Cc (and Kc).
    auto t0 = Clock::now();
    st.free_modes = run_free_modes(cases.cantilever, options.free_modes);
    std::vector<double> free_omega;
    for (const Mode& m : st.free_modes.result.bending) free_omega.push_back(m.omega);
    st.support_damping = build_beam_model(cases.free_impact).contact_damping.at(0);
    Case moving = cases.free_impact;
    moving.supports.front().damping = st.support_damping;
    moving.supports.front().damping_ratio.reset();
    const double setup_s = seconds_since(t0);

    const std::vector<double> positions = scan_positions(options.positions, options.position_min);
    lay_out_points(st, moving, positions);
    Parts parts;
    JobErrors errors;
    errors.forces.resize(options.force_positions.size());
    std::vector<Job> jobs = transient_jobs(st, moving, positions, errors);
    add_modal_jobs(jobs, st, free_omega);
    const int threads = resolve_thread_count(options.threads);
    run_jobs(jobs, parts, threads, options, t_start);
    if (!errors.typical.empty()) throw std::runtime_error("Fig. 3 transient: " + errors.typical);
    for (std::size_t i = 0; i < errors.forces.size(); ++i) {
        if (!errors.forces[i].empty()) {
            throw std::runtime_error("Fig. 11 impact at x0/l = " + std::to_string(options.force_positions[i]) + ": " + errors.forces[i]);
        }
    }

    st.timing.threads = threads;
    st.timing.transients = static_cast<int>(positions.size() * options.meshes.size() + st.prestress.points.size()) + 1 +
                           2 * static_cast<int>(options.force_positions.size());
    st.timing.modes_s = setup_s + parts[modes].cpu_us * 1e-6;
    st.timing.typical_s = parts[typical].cpu_us * 1e-6;
    st.timing.position_scans_s = parts[scans].cpu_us * 1e-6;
    st.timing.prestress_s = parts[prestress].cpu_us * 1e-6;
    st.timing.forces_s = parts[forces].cpu_us * 1e-6;
    st.timing.wall_s = seconds_since(t_start);
    return st;
}

}  // namespace vi
