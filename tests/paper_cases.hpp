#pragma once
// Cases built in code for tests: the paper's nickel cantilever and a clamped-clamped variant.

#include "model/case.hpp"

namespace vi::test {

// l = 117 um, w = 30 um, t = 2 um, nickel; optionally one support below at x0/l = support_at.
inline Case paper_cantilever(int elements, double support_at = -1.0) {
    Case c;
    c.name = "test-cantilever";
    c.beam = {117e-6, 30e-6, 2e-6, elements, EndCondition::clamped, EndCondition::free};
    c.material = {207e9, 8902.0, 0.31, false};
    if (support_at > 0) {
        Support s;
        s.position = support_at;
        s.stiffness = 50.0;
        c.supports.push_back(s);
    }
    return c;
}

inline Case clamped_clamped(int elements) {
    Case c = paper_cantilever(elements);
    c.beam.right = EndCondition::clamped;
    return c;
}

}  // namespace vi::test
