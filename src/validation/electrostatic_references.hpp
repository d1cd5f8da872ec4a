#pragma once
// Independent references for electrostatic pull-in (docs/electrostatics.md §5).

namespace vi {

// Pull-in parameter lambda_PI = eps0 w V_PI^2 l^4 / (2 EI g^3) of a cantilever under a full-length
// electrode without fringing: u'''' = lambda / (1 - u)^2, u(0) = u'(0) = u''(1) = u'''(1) = 0,
// solved by shooting (RK4, 4000 steps, Newton on u''(0), u'''(0), lambda at a prescribed tip
// deflection) and maximised over the tip deflection. Shares no code with the FE model.
double cantilever_pullin_lambda_shooting();

}  // namespace vi
