#include "model/case_checks.hpp"

#include <cmath>
#include <string>

namespace vi {
namespace {

std::string support_key(std::size_t i, const char* field) {
    return "supports[" + std::to_string(i) + "]." + field;
}

void require_positive(std::vector<CaseProblem>& out, const std::string& key, double value) {
    if (!std::isfinite(value)) {
        out.push_back({key, "must be a finite number"});
    } else if (!(value > 0.0)) {
        out.push_back({key, "must be positive"});
    }
}

void require_non_negative(std::vector<CaseProblem>& out, const std::string& key, double value) {
    if (!std::isfinite(value)) {
        out.push_back({key, "must be a finite number"});
    } else if (value < 0.0) {
        out.push_back({key, "must not be negative"});
    }
}

}  // namespace

bool bending_is_restrained(EndCondition left, EndCondition right) {
    // One clamp, or two pins, is the least that stops both rigid-body bending motions.
    if (left == EndCondition::clamped || right == EndCondition::clamped) return true;
    return left == EndCondition::pinned && right == EndCondition::pinned;
}

std::vector<CaseProblem> check_case(const Case& c) {
    std::vector<CaseProblem> out;
    require_positive(out, "beam.length", c.beam.length);
    require_positive(out, "beam.width", c.beam.width);
    require_positive(out, "beam.thickness", c.beam.thickness);
    if (c.beam.elements < 1) out.push_back({"beam.elements", "must be at least 1"});
    if (c.beam.elements > 100000) out.push_back({"beam.elements", "must be at most 100000"});
    if (!bending_is_restrained(c.beam.left, c.beam.right)) {
        out.push_back({"beam.right",
                       "the end conditions leave the beam free to move as a rigid body "
                       "(needs a clamped end or two pinned ends)"});
    }

    require_positive(out, "material.youngs_modulus", c.material.youngs_modulus);
    require_positive(out, "material.density", c.material.density);
    const double nu = c.material.poisson_ratio;
    if (!std::isfinite(nu)) {
        out.push_back({"material.poisson_ratio", "must be a finite number"});
    } else if (nu <= -1.0 || nu >= 0.5) {
        out.push_back({"material.poisson_ratio", "must lie in (-1, 0.5)"});
    }

    for (std::size_t i = 0; i < c.supports.size(); ++i) {
        const Support& s = c.supports[i];
        if (!std::isfinite(s.position)) {
            out.push_back({support_key(i, "position"), "must be a finite number"});
        } else if (!(s.position > 0.0 && s.position <= 1.0)) {
            out.push_back({support_key(i, "position"), "must lie in (0, 1] (x0/l)"});
        }
        const bool at_fixed_end = s.position == 1.0 && c.beam.right != EndCondition::free;
        if (at_fixed_end) out.push_back({support_key(i, "position"), "a support at a clamped or pinned end never moves"});
        if (!std::isfinite(s.surface)) out.push_back({support_key(i, "gap"), "must be a finite number"});
        require_positive(out, support_key(i, "stiffness"), s.stiffness);
        require_non_negative(out, support_key(i, "damping"), s.damping);
        if (s.damping_ratio) require_non_negative(out, support_key(i, "damping_ratio"), *s.damping_ratio);
        for (std::size_t j = 0; j < i; ++j) {
            const Support& o = c.supports[j];
            if (o.side == s.side && std::abs(o.position - s.position) <= 1e-12) {
                out.push_back({support_key(i, "position"),
                               "two supports at the same place and side (supports[" + std::to_string(j) + "])"});
            }
        }
    }

    const RayleighDamping& d = c.damping;
    if (d.from_ratios) {
        require_non_negative(out, "damping.ratios", d.ratio1);
        require_non_negative(out, "damping.ratios", d.ratio2);
        if (d.mode1 < 1 || d.mode2 < 1) out.push_back({"damping.modes", "mode numbers start at 1"});
        if (d.mode1 == d.mode2) out.push_back({"damping.modes", "the two modes must differ"});
    } else {
        require_non_negative(out, "damping.alpha", d.alpha);
        require_non_negative(out, "damping.beta", d.beta);
    }
    return out;
}

}  // namespace vi
