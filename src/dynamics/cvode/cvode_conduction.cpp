#include "dynamics/cvode/cvode_conduction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/golden_section.hpp"

namespace vi::cvode_detail {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

}  // namespace

ConductionRecorder::ConductionRecorder(const ModalSystem& system, TransientResult& result) : sys_(system), r_(result) {
    const std::vector<double> zeros(static_cast<std::size_t>(sys_.size()), 0.0);
    for (std::size_t j = 0; j < sys_.contacts().size(); ++j) {
        const int e = sys_.contacts()[j];
        // A resistance model answers with a number (+inf at no penetration), an element without one NaN.
        if (std::isnan(sys_.resistance(e, 0.0, zeros.data()))) continue;
        ContactConduction c;
        c.contact = static_cast<int>(j);
        c.r_on = sys_.element(e).on_resistance();
        r_.conduction.push_back(c);
        if (!std::isnan(c.r_on)) tracks_.push_back({e, r_.conduction.size() - 1, false, 0.0});
    }
}

bool ConductionRecorder::conducting(const Track& k, double t, const double* y, const std::vector<int>& modes) const {
    if (modes[static_cast<std::size_t>(k.element)] != sys_.element(k.element).contact_mode()) return false;
    return sys_.resistance(k.element, t, y) < r_.conduction[k.record].r_on;
}

void ConductionRecorder::change(Track& k, double t, double resistance) {
    ContactConduction& c = r_.conduction[k.record];
    if (k.on) {
        c.stretches.back().t_off = t;
    } else {
        c.stretches.push_back({t, t, resistance, false});
    }
    k.on = !k.on;
}

void ConductionRecorder::start(const double* y, const std::vector<int>& modes) {
    for (Track& k : tracks_) {
        if (conducting(k, 0.0, y, modes)) change(k, 0.0, sys_.resistance(k.element, 0.0, y));
        k.t_last = 0.0;
    }
}

double ConductionRecorder::crossing(const Track& k, double lo, double hi, bool want, const std::vector<int>& modes,
                                   const DenseOutput& at) const {
    // Bisection to a few ulps of hi: 200 halvings cover any interval of doubles.
    for (int it = 0; it < 200 && hi - lo > 4.0 * kEps * std::max(std::abs(hi), 1e-300); ++it) {
        const double mid = 0.5 * (lo + hi);
        (conducting(k, mid, at(mid), modes) == want ? hi : lo) = mid;
    }
    return hi;
}

void ConductionRecorder::dip(Track& k, double lo, double t, const double* y, const std::vector<int>& modes,
                             const DenseOutput& at) {
    const double span = t - lo;
    if (!(span > 4.0 * kEps * std::max(std::abs(t), 1e-300))) return;
    const auto depth = [&](double s) { return sys_.reading(k.element, s, s == t ? y : at(s)).penetration; };
    const double h = 1e-6 * span;
    // Falling at the start and rising at the end: one minimum inside (no maximum between returns).
    if (!(depth(lo + h) < depth(lo) && depth(t - h) < depth(t))) return;
    // The penetration is unimodal on [lo, t]: its minimum is the deepest sag of the closure.
    const double t_min =
        golden_section_max([&](double s) { return -depth(s); }, lo, t, 4.0 * kEps * std::max(std::abs(t), 1e-300)).x;
    if (conducting(k, t_min, at(t_min), modes)) return;
    change(k, crossing(k, lo, t_min, false, modes, at), 0.0);
    const double t_on = crossing(k, t_min, t, true, modes, at);
    change(k, t_on, sys_.resistance(k.element, t_on, t_on == t ? y : at(t_on)));
}

void ConductionRecorder::advance(double t, const double* y, const std::vector<int>& modes, double step_start,
                                 const DenseOutput& at) {
    for (Track& k : tracks_) {
        const bool now = conducting(k, t, y, modes);
        const double lo = std::max(k.t_last, step_start);
        if (now != k.on) {
            const double hi = crossing(k, lo, t, now, modes, at);
            change(k, hi, sys_.resistance(k.element, hi, hi == t ? y : at(hi)));
        } else if (now) {
            dip(k, lo, t, y, modes, at);
        }
        if (k.on) {
            ConductionStretch& s = r_.conduction[k.record].stretches.back();
            s.min_resistance = std::min(s.min_resistance, sys_.resistance(k.element, t, y));
        }
        k.t_last = t;
    }
}

void ConductionRecorder::switched(double t, const double* y, const std::vector<int>& modes) {
    for (Track& k : tracks_) {
        if (conducting(k, t, y, modes) != k.on) change(k, t, sys_.resistance(k.element, t, y));
        k.t_last = t;
    }
}

void ConductionRecorder::finish(double t_end, const double* y, const std::vector<int>& modes) {
    for (Track& k : tracks_) {
        if (!k.on) continue;
        ConductionStretch& s = r_.conduction[k.record].stretches.back();
        s.t_off = t_end;
        s.on_at_end = true;
    }
    for (ContactConduction& c : r_.conduction) {
        const int e = sys_.contacts()[static_cast<std::size_t>(c.contact)];
        const bool closed = modes[static_cast<std::size_t>(e)] == sys_.element(e).contact_mode();
        c.end_resistance = closed ? sys_.resistance(e, t_end, y) : std::numeric_limits<double>::infinity();
    }
}

}  // namespace vi::cvode_detail
