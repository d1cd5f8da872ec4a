#pragma once
// The paper's numerical study (Ostasevicius et al. 2009, section 3, Figs. 2-11) as plain results:
// the modes of the free cantilever, a typical free-impact transient, the transients and the modes as
// the support moves along the beam, and the transients as the support is prestressed.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "impacts/impact_summary.hpp"
#include "report/field_output.hpp"
#include "study/paper/cases.hpp"
#include "modal/modal_analysis.hpp"
#include "modal/shape_sampling.hpp"

namespace vi {

// What to compute. The ranges are documented in docs/paper-reproduction.md.
struct PaperStudyOptions {
    PaperCases cases;
    int positions = 50;                // support positions x0/l of the transient scans (Figs. 4, 5, 10)
    double position_min = 0.30;        // ... evenly from here to 1; 0.67, 0.78 and 0.87 are always added
    double position_horizon = 500e-6;  // horizon of those transients [s] (longer than the Fig. 3 case's:
                                       // away from the free end the bouncing decays more slowly)
    int modal_positions = 100;         // support positions of the modal scans (Figs. 6-8), (0, 1]
    int prestress_points = 26;         // Delta/l of Fig. 9, evenly over [0, prestress_max]
    double prestress_max = 0.05;
    std::vector<int> meshes = {50, 10};          // m of the support-position transient scans
    std::vector<double> force_positions = {0.87, 1.0};  // Fig. 11
    int modes = 3;                     // supported modes of Figs. 6-8
    int free_modes = 5;                // unsupported modes of Fig. 2
    int threads = 0;                   // 0: every CPU this process may use
    // Called with one line as each part finishes (the command prints it); may be empty.
    std::function<void(const std::string&)> progress;
    // Called with (0, jobs) before the computations start and (done, jobs) as each ends, one call
    // at a time; may be empty.
    std::function<void(std::size_t done, std::size_t jobs)> jobs_done;
};

// One impact of a transient as the figures need it.
struct ImpactBrief {
    double t_on = 0.0, t_off = 0.0;  // [s]
    double v_in = 0.0;               // velocity of the contact point at onset [m/s] (negative: falling)
    double peak_force = 0.0;         // [N]
};

// One transient of a scan. Values are empty where the run does not define them: no T_p when the
// horizon ended before the impacts had settled (tp_reason = "horizon"), nothing when it failed.
struct TransientPoint {
    double x = 0.0;                  // x0/l (support scans) or Delta/l (prestress scan)
    std::string error;               // empty when the run succeeded
    std::optional<double> z_max;     // largest free-end rise above the final equilibrium / l
    std::optional<double> z_min;     // deepest free-end deflection while in contact / l (< 0: below the axis)
    std::optional<double> z_equilibrium;  // free end at the final static equilibrium / l
    std::optional<double> tau_p, tau, tau1, tau2;  // omega_1 T_p, omega_1 T, ... (first cycle)
    std::string tp_reason;           // as ImpactSummary::Tp_reason
    std::vector<ImpactBrief> impacts;  // the first three impacts (fewer if fewer happened)
    int episodes = 0;                // contact episodes and impacts up to the end of the run, which stops
    int impact_count = 0;            // once the values above are settled (impacts/settled_stop.hpp)
    double seconds = 0.0;            // wall time of this run
    [[nodiscard]] bool ok() const { return error.empty(); }
};

// A series of transients of one case with one value changed.
struct TransientScan {
    int elements = 0;                // m
    double omega1 = 0.0;             // first circular frequency of the unsupported beam [rad/s]
    double horizon = 0.0;            // [s]
    std::vector<TransientPoint> points;  // in increasing x
};

// Supported modes (the support as a pin) at one support position.
struct ModalPoint {
    double x0 = 0.0;                 // x0/l
    std::string error;
    std::vector<double> ratio;       // omega_i / omega_in, i = 1..modes
    std::vector<double> frequency_hz;  // supported f_i [Hz]
    std::vector<ShapeFeatures> features;  // nodal points and peaks of supported mode i
};

// The unsupported cantilever's modes with their shapes sampled along the beam (Fig. 2).
struct FreeModes {
    ModalResult result;
    std::vector<SampledShape> shapes;   // one per bending mode
    double amplitude_scale = 0.0;       // sqrt(rho A l) [sqrt(kg)]: Y = |v| scale, Phi = |theta| l scale
    double length = 0.0;                // l [m]
};

// The typical free-impact transient of Fig. 3 (support at the case's own position).
struct TypicalTransient {
    std::vector<double> t, tip;         // time [s], free-end displacement [m]
    ImpactSummary summary;
    double omega1 = 0.0;
    double tip_equilibrium = 0.0;       // [m]
    double y0 = 0.0;                    // lift [m]
    double support_damping = 0.0;       // Cc [N s/m]
    double rayleigh_alpha = 0.0;        // [1/s]
    double rayleigh_beta = 0.0;         // [s]
    double output_step = 0.0;           // sampling step of t, tip [s]
    BeamField field;                    // the whole beam at horizon / 200 (the report's animated beam)
    std::vector<std::pair<double, double>> surfaces;  // each support's [x (m), surface height (m)]
};

// Contact force during the first impact (Fig. 11).
struct ImpactForce {
    double x0 = 0.0;                    // x0/l
    std::vector<double> t, force;       // time since the impact's onset [s], contact force [N]
    Impact impact;                      // the first impact (episodes grouped)
    double omega1 = 0.0;
};

// Where omega_1(supported) / omega_1(unsupported) is largest (golden-section search).
struct RatioPeak {
    double x0 = 0.0;
    double ratio = 0.0;
};

// CPU seconds spent per part (summed over threads; thread CPU time, so other work on the machine
// does not inflate them) and the wall time of the whole study.
struct StudyTiming {
    double wall_s = 0.0;
    int threads = 1;
    int transients = 0;
    double modes_s = 0.0, typical_s = 0.0, position_scans_s = 0.0, prestress_s = 0.0, forces_s = 0.0;
};

struct PaperStudy {
    PaperStudyOptions options;          // as run (cases included)
    double support_damping = 0.0;       // Cc held fixed while the support moves [N s/m]
    FreeModes free_modes;
    TypicalTransient typical;
    std::vector<TransientScan> position_scans;  // one per mesh, in options.meshes order
    TransientScan prestress;
    std::vector<ImpactForce> forces;
    std::vector<ModalPoint> modal;      // in increasing x0
    RatioPeak ratio_peak;
    double pinned_tip_omega1 = 0.0;     // first circular frequency with the free end pinned [rad/s]
    StudyTiming timing;
};

// Runs the whole study, every transient and modal point in one parallel batch. A point that fails
// keeps its error and the study goes on; throws InputError for unusable options or cases and
// std::runtime_error when a part every figure needs (the free modes, Fig. 3) fails.
PaperStudy run_paper_study(const PaperStudyOptions& options);

// The x0/l of the transient scans: `count` evenly over [lo, 1] with 0.67, 0.78, 0.87 merged in.
std::vector<double> scan_positions(int count, double lo);

}  // namespace vi
