#pragma once
// Independent references for electrostatic pull-in (docs/electrostatics.md §7).

#include <memory>

#include "statics/pullin.hpp"

namespace vi {

// An electrode `gap` [m] below a rigid plate of area width x length whose DOF 0 is v (up positive):
// one quadrature point of weight `length` and shape value 1, at `voltage` [V] times time(t).
std::shared_ptr<const ElectrostaticPad> parallel_plate_pad(double gap, double width, double length, double voltage,
                                                          TimeFunction time);

// A rigid plate of area width x length on a spring k [N/m] with mass [kg], across `gap` [m] from an
// electrode below it: one DOF, one quadrature point of weight `length` and shape value 1; its
// parallel-plate pull-in is V_PI = sqrt(8 k g^3 / (27 eps0 A)) at a travel of g/3.
PullinModel parallel_plate_model(double k, double mass, double gap, double width, double length);

// Pull-in parameter lambda_PI = eps0 w V_PI^2 l^4 / (2 EI g^3) of a cantilever under a full-length
// electrode without fringing: u'''' = lambda / (1 - u)^2, u(0) = u'(0) = u''(1) = u'''(1) = 0,
// solved by shooting (RK4, 4000 steps, Newton on u''(0), u'''(0), lambda at a prescribed tip
// deflection) and maximised over the tip deflection. Shares no code with the FE model.
double cantilever_pullin_lambda_shooting();

}  // namespace vi
