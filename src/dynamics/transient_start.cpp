#include "dynamics/transient_start.hpp"

#include "statics/initial_state.hpp"

namespace vi {

TransientStart transient_start(const Case& c, const BeamModel& m) {
    const bool mode_velocity = c.initial.velocity_kind == InitialState::Velocity::mode;
    const Eigen::VectorXd mode =
        mode_velocity ? Eigen::VectorXd(m.modes.shapes.col(c.initial.velocity_mode - 1)) : Eigen::VectorXd();
    // The static step: the time-dependent loads are not part of it (they act from t = 0 on).
    InitialConditions ic = initial_conditions(c.initial, m.K, m.forces, unit_point_load(m.system, c.initial.position),
                                              m.is_v, mode, c.solver.max_static_iterations);
    TransientStart s;
    s.q0 = std::move(ic.stepped.q);
    s.v0 = std::move(ic.v0);
    s.modes0 = std::move(ic.stepped.modes);
    s.q_equilibrium = std::move(ic.equilibrium.q);
    s.y0_m = ic.lift;
    s.static_force_n = ic.force;
    s.t_end = c.solver.horizon;
    s.output_step = c.solver.output_step > 0.0 ? c.solver.output_step : c.solver.horizon / 2000.0;
    return s;
}

TransientProblem transient_problem(const BeamModel& m, const TransientStart& s) {
    TransientProblem p;
    p.M = m.M;
    p.K = m.K;
    p.alpha = m.rayleigh.alpha;
    p.beta = m.rayleigh.beta;
    p.forces = m.forces;
    p.q0 = s.q0;
    p.v0 = s.v0;
    p.modes0 = s.modes0;
    p.tip_dof = m.watched.dof;
    p.t_end = s.t_end;
    p.output_step = s.output_step;
    return p;
}

BuiltProblem build_transient_problem(const Case& c) {
    BuiltProblem b;
    b.model = build_beam_model(c);
    b.start = transient_start(c, b.model);
    b.problem = transient_problem(b.model, b.start);
    return b;
}

}  // namespace vi
