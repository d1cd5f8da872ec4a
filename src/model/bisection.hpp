#pragma once
// Bisection: where a function of one variable changes sign on an interval.

#include <functional>

namespace vi {

// A root of f in [a, b], f(a) and f(b) of opposite signs: the bracket is halved until its midpoint
// is one of its ends (machine precision) or f is exactly 0 there, at most 200 times (enough for any
// bracket of doubles). Returns the midpoint of the last bracket, or the point where f is 0.
double bisect_sign_change(const std::function<double(double)>& f, double a, double b);

}  // namespace vi
