#include "dynamics/signal/signal_scan.hpp"

#include "dynamics/signal/exp_sincos.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace vi {
namespace {

// Per point, one record per prefix of its live modes (index J = number of slow modes, 0..live):
// f0 (upper bound of the slow modes' value), f1 (of their slope), mag (sum |v_k|), b2
// (sum |v_k| |lambda_k|^2), and the |lambda| of live mode J (for the split by |lambda| h <= 2).
constexpr int kF0 = 0, kF1 = 1, kMag = 2, kB2 = 3, kLambda = 4;

// A mode is not evaluated once |v_k| falls below this fraction of the signal's size: its exact
// magnitude still bounds it, so nothing is lost but a contribution far below roundoff of the sum.
constexpr double kSkipFraction = 1e-18;

// Largest s >= 0 with c0 + c1 s + c2 s^2 / 2 < 0 on [0, s), given c0 < 0 and c2 >= 0 (inf if none).
double quadratic_reach(double c0, double c1, double c2) {
    const double disc = c1 * c1 - 2.0 * c2 * c0;  // > c1^2 since c0 < 0
    const double root = std::sqrt(disc);
    if (c1 <= 0.0) return c2 > 0.0 ? (root - c1) / c2 : std::numeric_limits<double>::infinity();
    return -2.0 * c0 / (c1 + root);  // the same root without cancellation
}

double magnitude(cd z) { return std::sqrt(std::norm(z)); }  // no hypot: nothing here nears overflow

// The exponent std::frexp gives x, read from the bits of a normal x (no library call).
int frexp_exponent(double x) {
    if (!std::isnormal(x)) {
        int e = 0;
        std::frexp(x, &e);
        return e;
    }
    return static_cast<int>((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff) - 1022;
}

// The spare buffers of this thread: a scan takes them and gives them back when done.
struct SpareStore {
    std::unique_ptr<double[]> data;
    std::size_t capacity = 0;
    std::vector<double> dead, blocks;
    std::vector<int> live;
    std::vector<ExpTerm> terms;
};

// Gives v to spare when it holds more room than spare has (the next scan takes the larger).
template <class V>
void give_back(V& v, V& spare_v) {
    if (v.capacity() > spare_v.capacity()) spare_v = std::move(v);
}
thread_local SpareStore spare;

}  // namespace

// What a scan needs of the exponents alone, kept for the last few sets seen on this thread: the
// pieces of one contact state share them, and each piece scans several signals.
struct PoleSet {
    std::vector<double> key;         // the exponents as given (real and imaginary parts)
    std::vector<int> order;          // ascending |lambda| (empty: already so)
    std::vector<SignalScanPole> poles;  // in that order
    std::vector<double> mags;        // |lambda|, in that order, contiguous
    std::vector<double> res;         // Re lambda, in that order, contiguous
    double gamma = 0.0;              // largest Re lambda > 0, else 0
};

namespace {

std::shared_ptr<const PoleSet> make_pole_set(const Eigen::VectorXcd& lam) {
    auto set = std::make_shared<PoleSet>();
    const int m = static_cast<int>(lam.size());
    const double* lp = reinterpret_cast<const double*>(lam.data());
    set->key.assign(lp, lp + 2 * m);
    // Decompositions come sorted; signals built by hand may not be.
    bool sorted = true;
    for (int k = 1; k < m && sorted; ++k) sorted = std::norm(lam[k - 1]) <= std::norm(lam[k]);
    if (!sorted) {
        set->order.resize(static_cast<std::size_t>(m));
        std::iota(set->order.begin(), set->order.end(), 0);
        std::stable_sort(set->order.begin(), set->order.end(),
                         [&](int a, int b) { return std::norm(lam[a]) < std::norm(lam[b]); });
    }
    set->poles.resize(static_cast<std::size_t>(m));
    set->mags.resize(static_cast<std::size_t>(m));
    set->res.resize(static_cast<std::size_t>(m));
    for (int j = 0; j < m; ++j) {
        const std::size_t k = static_cast<std::size_t>(sorted ? j : set->order[static_cast<std::size_t>(j)]);
        const double lr = lp[2 * k], li = lp[2 * k + 1];
        SignalScanPole& pl = set->poles[static_cast<std::size_t>(j)];
        pl.re = lr;
        pl.im = li;
        pl.mag2 = lr * lr + li * li;  // std::norm's own formula
        pl.mag = std::sqrt(pl.mag2);
        set->mags[static_cast<std::size_t>(j)] = pl.mag;
        set->res[static_cast<std::size_t>(j)] = lr;
        set->gamma = std::max(set->gamma, lr);
    }
    return set;
}

// The pole set of lam: one of the last kKept built on this thread when its exponents are the same
// to the last bit (compared whole, so a vector freed and another allocated in its place cannot be
// taken for it), else a new one.
std::shared_ptr<const PoleSet> pole_set(const Eigen::VectorXcd& lam) {
    constexpr int kKept = 4;
    thread_local std::shared_ptr<const PoleSet> kept[kKept];
    thread_local int next = 0;
    const std::size_t n = static_cast<std::size_t>(2 * lam.size());
    for (const auto& set : kept) {
        if (set && set->key.size() == n && std::memcmp(set->key.data(), lam.data(), n * sizeof(double)) == 0) return set;
    }
    auto set = make_pole_set(lam);
    kept[next] = set;
    next = (next + 1) % kKept;
    return set;
}

}  // namespace

SignalScan::~SignalScan() {
    if (capacity_ > spare.capacity) {
        spare.data = std::move(store_);
        spare.capacity = capacity_;
    }
    if (modes_.capacity() > spare_modes().capacity()) spare_modes() = std::move(modes_);
    give_back(dead_, spare.dead);
    give_back(blocks_, spare.blocks);
    give_back(live_, spare.live);
    give_back(terms_, spare.terms);
}

std::vector<SignalScan::Mode>& SignalScan::spare_modes() {
    thread_local std::vector<Mode> modes;
    return modes;
}

SignalScan::SignalScan(const ExpSignal& f, double sign, double t_end) {
    store_ = std::move(spare.data);
    capacity_ = spare.capacity;
    spare.capacity = 0;
    dead_ = std::move(spare.dead);
    blocks_ = std::move(spare.blocks);
    live_ = std::move(spare.live);
    terms_ = std::move(spare.terms);
    terms_.clear();
    m_ = static_cast<int>(f.A.size());
    std::shared_ptr<const PoleSet> set = pole_set(*f.lambda);
    poles_ = set->poles.data();
    mags_ = set->mags.data();
    gamma_ = set->gamma;
    const bool sorted = set->order.empty();
    // The thread's spare array: every field of every mode is written below.
    modes_ = std::move(spare_modes());
    modes_.resize(static_cast<std::size_t>(m_));
    // Real and imaginary parts read as doubles (std::complex is laid out as double[2]): a complex
    // copied through the stack in halves and read back whole stalls the store forwarding.
    const double* ap = reinterpret_cast<const double*>(f.A.data());
    // |A|^2 into the contiguous array first, the square roots in one vectorised pass (sqrt is
    // correctly rounded either way), then into the modes.
    dead_.resize(static_cast<std::size_t>(m_));
    thread_local std::vector<double> amps;
    amps.resize(static_cast<std::size_t>(m_));
    double* amp = amps.data();
    for (int j = 0; j < m_; ++j) {
        const std::size_t k = static_cast<std::size_t>(sorted ? j : set->order[static_cast<std::size_t>(j)]);
        const double ar = ap[2 * k], ai = ap[2 * k + 1];
        modes_[static_cast<std::size_t>(j)].A = cd(sign * ar, sign * ai);
        amp[j] = ar * ar + ai * ai;
    }
    for (int j = 0; j < m_; ++j) amp[j] = std::sqrt(amp[j]);
    double size = 0.0;  // in a register: the member would be stored and read back per mode
    for (int j = 0; j < m_; ++j) {
        modes_[static_cast<std::size_t>(j)].amp = amp[j];
        size += amp[j];
    }
    size_ = size;
    for (const ExpTerm& t : f.terms) {
        terms_.push_back({sign * t.coef, t.s, t.power});
        size_ += magnitude(t.coef);
    }
    if (!terms_.empty()) terms_b2_ = terms_bound(f.terms, 0.0, t_end, 2);
    skip_ = kSkipFraction * size_;
    // amp e^(re t) <= skip once t >= ln(amp / skip) / -re; ln x <= e ln 2 for x = mant 2^e, mant < 1,
    // so the exponent of frexp gives a time that is never early.
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (std::isnormal(skip_) && std::isfinite(size_)) {
        death_times(set->res.data(), amp, skip_, m_, dead_.data());
    } else {
        for (int k = 0; k < m_; ++k) {
            const double re = poles_[k].re, a = amp[k];
            double& dk = dead_[static_cast<std::size_t>(k)];
            if (re > 0.0) {
                dk = kInf;  // roundoff of an undamped mode: may grow
            } else if (a <= skip_) {
                dk = 0.0;
            } else if (re < 0.0) {
                dk = frexp_exponent(a / skip_) * std::numbers::ln2 / -re;
            } else {
                dk = kInf;
            }
        }
    }
    pole_set_ = std::move(set);
    // Per block of kBlock modes: its earliest and latest death time and its modes' sum of |lambda|.
    blocks_.resize(static_cast<std::size_t>(3 * ((m_ + kBlock - 1) / kBlock)));
    for (int k0 = 0, b = 0; k0 < m_; k0 += kBlock, ++b) {
        const int k1 = std::min(m_, k0 + kBlock);
        double lo = kInf, hi = -kInf, sum = 0.0;
        for (int k = k0; k < k1; ++k) {
            lo = std::min(lo, dead_[static_cast<std::size_t>(k)]);
            hi = std::max(hi, dead_[static_cast<std::size_t>(k)]);
            sum += mags_[k];
        }
        blocks_[static_cast<std::size_t>(3 * b)] = lo;
        blocks_[static_cast<std::size_t>(3 * b + 1)] = hi;
        blocks_[static_cast<std::size_t>(3 * b + 2)] = sum;
    }
}

void SignalScan::update_live(double t) const {
    if (t >= live_from_ && t < live_until_) return;
    // Mode k is live while t < dead_k: the set holds between the death times around t. Block by
    // block: a block whose modes are all dead or all live at t (most are, as the fast overdamped
    // modes die in about the order of their |lambda|) takes one test; inside a mixed block, no
    // branches: which modes are dead varies from one point to the next in ways a branch predictor
    // cannot follow.
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const double* dead = dead_.data();
    const double* mag = mags_;
    const double* block = blocks_.data();
    live_.resize(static_cast<std::size_t>(m_));
    int* out = live_.data();
    int n = 0;
    double dead_mag = 0.0, from = -kInf, until = kInf;
    for (int k0 = 0, b = 0; k0 < m_; k0 += kBlock, ++b) {
        const int k1 = std::min(m_, k0 + kBlock);
        const double lo = block[3 * b], hi = block[3 * b + 1];
        if (t >= hi) {  // all dead
            dead_mag += block[3 * b + 2];
            from = std::max(from, hi);
        } else if (t < lo) {  // all live
            for (int k = k0; k < k1; ++k) out[n++] = k;
            until = std::min(until, lo);
        } else {
            for (int k = k0; k < k1; ++k) {
                const double dk = dead[k];
                const bool alive = t < dk;
                out[n] = k;
                n += alive ? 1 : 0;
                dead_mag += alive ? 0.0 : mag[k];
                from = std::max(from, alive ? -kInf : dk);
                until = std::min(until, alive ? dk : kInf);
            }
        }
    }
    live_.resize(static_cast<std::size_t>(n));
    live_from_ = from;
    live_until_ = until;
    dead_count_ = m_ - n;
    dead_abs1_ = skip_ * dead_mag;
}

const double* SignalScan::exponentials(double t) const {
    const std::size_t n = live_.size();
    // The thread's scratch: each evaluation reads it before any other scan of the thread writes it.
    thread_local std::vector<double> scratch;
    if (scratch.size() < 5 * n) scratch.resize(5 * n);
    double* x = scratch.data();
    double* y = x + n;
    for (std::size_t i = 0; i < n; ++i) {
        const SignalScanPole& pl = poles_[live_[i]];
        x[i] = pl.re * t;
        y[i] = pl.im * t;
    }
    exp_sincos(x, y, y + n, y + 2 * n, y + 3 * n, static_cast<int>(n));
    return y + n;
}

ScanPoint SignalScan::evaluate(double t) {
    ScanPoint p;
    p.t = t;
    const std::size_t need = static_cast<std::size_t>(kRecord * (m_ + 1));
    if (used_ + need > capacity_) {
        const std::size_t cap = std::max(2 * capacity_, used_ + 64 * need);
        std::unique_ptr<double[]> bigger(new double[cap]);
        std::copy(store_.get(), store_.get() + used_, bigger.get());
        store_ = std::move(bigger);
        capacity_ = cap;
    }
    update_live(t);
    const std::size_t n = live_.size();
    // At t = 0 every factor is 1.
    const double* ex = t != 0.0 ? exponentials(t) : nullptr;
    const double* co = ex ? ex + n : nullptr;
    const double* si = ex ? ex + 2 * n : nullptr;
    p.offset = used_;
    double* rec = store_.get() + p.offset;
    rec[kF0] = rec[kF1] = rec[kMag] = rec[kB2] = 0.0;
    // The dead modes: below skip_ for good, bounded by it, always among the fast ones, never evaluated.
    double value = 0.0, slope = 0.0, abs1 = dead_abs1_;
    for (std::size_t i = 0; i < n; ++i) {
        const Mode& md = modes_[static_cast<std::size_t>(live_[i])];
        const SignalScanPole& pl = poles_[live_[i]];
        double vre = 0.0, lre = 0.0, unc = 0.0;
        // |v_k| exactly (or, below exp(-707), an upper bound) before deciding whether to evaluate it.
        const double e = ex ? ex[i] : 1.0;
        const double mk = md.amp * e;
        if (mk <= skip_) {
            unc = mk;  // Re v and Re(lambda v) lie within +-|v| and +-|lambda||v|
        } else if (pl.im == 0.0) {
            vre = md.A.real() * e;
            lre = pl.re * vre;
        } else {
            const cd v = ex ? md.A * cd(e * co[i], e * si[i]) : md.A;
            vre = v.real();
            lre = pl.re * v.real() - pl.im * v.imag();
        }
        value += vre;
        slope += lre;
        abs1 += mk * pl.mag;
        rec[kLambda] = pl.mag;
        double* next = rec + kRecord;
        next[kF0] = rec[kF0] + vre + unc;
        next[kF1] = rec[kF1] + lre + unc * pl.mag;
        next[kMag] = rec[kMag] + mk;
        next[kB2] = rec[kB2] + mk * pl.mag2;
        rec = next;
    }
    rec[kLambda] = std::numeric_limits<double>::infinity();
    const int live = static_cast<int>(n);
    used_ += static_cast<std::size_t>(kRecord * (live + 1));
    p.live = live;
    p.dead_mag = dead_count_ * skip_;
    p.abs0 = rec[kMag] + p.dead_mag;
    for (const ExpTerm& term : terms_) {
        const cd v0 = term_derivative(term, t, 0), v1 = term_derivative(term, t, 1);
        p.p0 += v0.real();
        p.p1 += v1.real();
        p.abs0 += magnitude(v0);
        abs1 += magnitude(v1);
    }
    p.value = value + p.p0;
    p.slope = slope + p.p1;
    p.abs1 = abs1;
    return p;
}

double SignalScan::value(double t) const {
    update_live(t);
    const std::size_t n = live_.size();
    const double* ex = t != 0.0 ? exponentials(t) : nullptr;
    const double* co = ex ? ex + n : nullptr;
    const double* si = ex ? ex + 2 * n : nullptr;
    double v = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Mode& md = modes_[static_cast<std::size_t>(live_[i])];
        const SignalScanPole& pl = poles_[live_[i]];
        const double e = ex ? ex[i] : 1.0;
        if (pl.re * t < -707.0 || md.amp * e <= skip_) continue;
        if (pl.im == 0.0) {
            v += md.A.real() * e;
            continue;
        }
        v += (ex ? md.A * cd(e * co[i], e * si[i]) : md.A).real();
    }
    for (const ExpTerm& term : terms_) v += term_derivative(term, t, 0).real();
    return v;
}

double SignalScan::growth(double h) const { return gamma_ > 0.0 ? std::exp(gamma_ * h) : 1.0; }

int SignalScan::slow_count(const ScanPoint& p, double h) const {
    // Modes with |lambda| h <= 2 change little over h: Taylor bounds them well; faster ones do better
    // by their amplitude alone. Live modes are in ascending |lambda|: bisect their records.
    if (!(h > 0.0)) return p.live;
    const double* rec = record(p, 0);
    const double limit = 2.0 / h;
    int lo = 0, hi = p.live;  // the first J with |lambda_J| > limit lies in [lo, hi]
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (rec[kRecord * mid + kLambda] <= limit) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return lo;
}

void SignalScan::keep_only(ScanPoint& p) {
    const std::size_t n = static_cast<std::size_t>(kRecord * (p.live + 1));
    // The destination starts before the source: a forward copy is safe where they overlap.
    if (p.offset > 0) std::copy(store_.get() + p.offset, store_.get() + p.offset + n, store_.get());
    p.offset = 0;
    used_ = n;
}

double SignalScan::roundoff(const ScanPoint& p) {
    return (p.live + 16) * std::numeric_limits<double>::epsilon() * p.abs0;
}

double SignalScan::certified_step(const ScanPoint& p, double H, double value_used) const {
    // For slow modes k < J: f_slow(t + s) <= f0 + f1 s + G b2 s^2 / 2 (Taylor, |v_k| not growing by more
    // than G = exp(gamma H)); for fast ones, dead ones included, |f_fast| <= G sum |v_k|. Any J gives a
    // valid bound; the step is the longest any of them proves.
    const double G = growth(H);
    const double* rec = record(p, 0);
    const double mag_all = rec[kRecord * p.live + kMag] + p.dead_mag;
    const double shift = value_used - p.value;
    // The computed sums may be off by their rounding error: bounds are raised by it.
    const double err0 = roundoff(p);
    const double err1 = (p.live + 16) * std::numeric_limits<double>::epsilon() * p.abs1;
    double best = 0.0;
    for (int J = p.live; J >= 0; --J) {
        const double* r = rec + kRecord * J;
        const double c0 = p.p0 + r[kF0] + G * (mag_all - r[kMag]) + shift + err0;
        if (!(c0 < 0.0)) continue;
        const double c1 = p.p1 + r[kF1] + err1;
        const double c2 = terms_b2_ + G * r[kB2];
        best = std::max(best, quadratic_reach(c0, c1, c2));
        if (best >= H) return H;
    }
    return std::min(best, H);
}

double SignalScan::upper_bound(const ScanPoint& a, const ScanPoint& b) const {
    // Live at b means live at a (b is later and magnitudes only fall below skip_ for good), so the
    // slow set at a (live, |lambda| h <= 2) is the slow set at b plus ja - jb modes dead at b.
    const double h = b.t - a.t;
    const int ja = slow_count(a, h), jb = slow_count(b, h);
    const double G = growth(h);
    const double* ra = record(a, ja);
    const double* rb = record(b, jb);
    const double mag_all = record(a, a.live)[kMag] + a.dead_mag;
    // Fast modes: at most their size at a (decaying) times G. Slow ones: |f''| <= B over [a, b].
    const double fast = G * (mag_all - ra[kMag]);
    const double B = terms_b2_ + G * ra[kB2];
    const double ya = a.p0 + ra[kF0];
    const double yb = b.p0 + rb[kF0] + (ja - jb) * skip_;
    const double taylor = ya + std::max(0.0, (a.p1 + ra[kF1]) * h + 0.5 * B * h * h);
    double interp = std::max(ya, yb);
    if (B > 0.0 && h > 0.0) {
        // max over s in [0, h] of ya + (yb - ya) s / h + B s (h - s) / 2
        const double s = std::clamp(0.5 * h + (yb - ya) / (B * h), 0.0, h);
        interp = ya + (yb - ya) * (s / h) + 0.5 * B * s * (h - s);
    }
    return std::min(taylor, interp) + fast;
}

}  // namespace vi
