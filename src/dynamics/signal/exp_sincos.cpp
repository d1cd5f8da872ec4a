#include "dynamics/signal/exp_sincos.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace vi {
namespace {

// Round to the nearest integer (ties to even) for |v| < 2^51, without a library call.
constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52

// ln 2 in two parts, the first with trailing zero bits so that n * kLn2Hi is exact for |n| < 2^11.
constexpr double kLn2Hi = 6.93147180369123816490e-01;
constexpr double kLn2Lo = 1.90821492927058770002e-10;
constexpr double kLog2e = 1.44269504088896338700e+00;

// pi / 2 in three parts, the first two with trailing zero bits: k * part exact for |k| < 2^29.
constexpr double kPio2A = 1.57079625129699707031e+00;
constexpr double kPio2B = 7.54978941586159635336e-08;
constexpr double kPio2C = 5.39030285815811905290e-15;
constexpr double kTwoOverPi = 6.36619772367581382433e-01;

// Taylor coefficients 1/k!: on |r| <= ln2/2 (exp, to r^13) and |r| <= pi/4 (sin to r^17, cos to
// r^16) the first omitted term is below 1e-17 of the result.
constexpr double inv_factorial(int k) {
    double f = 1.0;
    for (int i = 2; i <= k; ++i) f *= i;
    return 1.0 / f;
}

constexpr double f2 = inv_factorial(2), f3 = inv_factorial(3), f4 = inv_factorial(4), f5 = inv_factorial(5),
                 f6 = inv_factorial(6), f7 = inv_factorial(7), f8 = inv_factorial(8), f9 = inv_factorial(9),
                 f10 = inv_factorial(10), f11 = inv_factorial(11), f12 = inv_factorial(12), f13 = inv_factorial(13),
                 f14 = inv_factorial(14), f15 = inv_factorial(15), f16 = inv_factorial(16), f17 = inv_factorial(17);

// Horner's scheme written out (loops here would keep the caller's loop from vectorising).
inline double exp_reduced(double r) {
    double p = f13 * r + f12;
    p = p * r + f11;
    p = p * r + f10;
    p = p * r + f9;
    p = p * r + f8;
    p = p * r + f7;
    p = p * r + f6;
    p = p * r + f5;
    p = p * r + f4;
    p = p * r + f3;
    p = p * r + f2;
    p = p * r + 1.0;
    return p * r + 1.0;
}

inline double sin_reduced(double r) {
    const double r2 = r * r;
    double p = f17 * r2 - f15;
    p = p * r2 + f13;
    p = p * r2 - f11;
    p = p * r2 + f9;
    p = p * r2 - f7;
    p = p * r2 + f5;
    p = p * r2 - f3;
    return r + r * r2 * p;
}

inline double cos_reduced(double r) {
    const double r2 = r * r;
    double p = f16 * r2 - f14;
    p = p * r2 + f12;
    p = p * r2 - f10;
    p = p * r2 + f8;
    p = p * r2 - f6;
    p = p * r2 + f4;
    return 1.0 - 0.5 * r2 + r2 * r2 * p;
}

}  // namespace

// Also built for AVX2 (four lanes instead of two) and AVX-512 (eight), chosen at load time where
// the processor has them; without fused multiply-adds (-ffp-contract=off for this file), so that
// every build rounds alike.
__attribute__((target_clones("avx512f", "avx2", "default")))
void exp_sincos(const double* x, const double* y, double* e, double* c, double* s, int n) {
    // One pass of plain arithmetic over all k (no calls, no branches: vectorised), then the rare
    // arguments outside its range through the C library.
    for (int k = 0; k < n; ++k) {
        const double xk = x[k];
        // n = round(x / ln 2) sits in the low mantissa bits of the shifted sum (two's complement).
        const double shifted = xk * kLog2e + kRound;
        const double nd = shifted - kRound;
        const double r = (xk - nd * kLn2Hi) - nd * kLn2Lo;
        const std::uint64_t scale = (std::bit_cast<std::uint64_t>(shifted) + 1023) << 52;  // 2^n
        e[k] = exp_reduced(r) * std::bit_cast<double>(scale);

        const double yk = y[k];
        const double qs = yk * kTwoOverPi + kRound;
        const double q = qs - kRound;
        const double t = ((yk - q * kPio2A) - q * kPio2B) - q * kPio2C;
        const std::uint64_t quadrant = std::bit_cast<std::uint64_t>(qs);  // low two bits: q mod 4
        const double sr = sin_reduced(t), cr = cos_reduced(t);
        // An odd quadrant swaps them (a bit mask, which vectorises on every x86-64), q = 1, 2
        // negates the cosine, q = 2, 3 the sine (their sign bits).
        const std::uint64_t odd = std::uint64_t{0} - (quadrant & 1);
        const std::uint64_t sbits = std::bit_cast<std::uint64_t>(sr), cbits = std::bit_cast<std::uint64_t>(cr);
        const std::uint64_t cb = ((sbits & odd) | (cbits & ~odd)) ^ ((((quadrant + 1) >> 1) & 1) << 63);
        const std::uint64_t sb = ((cbits & odd) | (sbits & ~odd)) ^ (((quadrant >> 1) & 1) << 63);
        c[k] = std::bit_cast<double>(cb);
        s[k] = std::bit_cast<double>(sb);
    }
    for (int k = 0; k < n; ++k) {
        if (x[k] < -707.0) e[k] = 1e-307;
        if (!(x[k] <= 700.0) && !(x[k] < -707.0)) e[k] = std::exp(x[k]);
        if (!(std::abs(y[k]) <= 1e5)) {
            c[k] = std::cos(y[k]);
            s[k] = std::sin(y[k]);
        }
    }
}

__attribute__((target_clones("avx512f", "avx2", "default")))
void death_times(const double* re, const double* amp, double skip, int n, double* dead) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    constexpr std::uint64_t kMantissa = (std::uint64_t{1} << 52) - 1;
    const std::uint64_t sbits = std::bit_cast<std::uint64_t>(skip);
    const std::int64_t es = static_cast<std::int64_t>(sbits >> 52);  // skip > 0: no sign bit
    const std::uint64_t ms = sbits & kMantissa;
    for (int k = 0; k < n; ++k) {
        const double a = amp[k], r = re[k];
        // The exponent std::frexp gives a / skip, without the division: a / skip = (a' / s') 2^(ea - es)
        // with significands a', s' in [1, 2), and the rounded quotient of the significands stays in
        // [1, 2) when a' >= s', in [1/2, 1) otherwise (both are multiples of 2^-52, so the exact
        // quotient stays more than half an ulp away from 2 and from 1).
        const std::uint64_t abits = std::bit_cast<std::uint64_t>(a);
        const std::int64_t e = static_cast<std::int64_t>(abits >> 52) - es + ((abits & kMantissa) >= ms ? 1 : 0);
        const double t = static_cast<double>(static_cast<int>(e)) * std::numbers::ln2 / -r;
        // r > 0: inf; else a <= skip: 0; else r < 0: t; else inf. As bit masks: no branches.
        const std::uint64_t grows = std::uint64_t{0} - (r > 0.0 ? 1u : 0u);
        const std::uint64_t small = std::uint64_t{0} - (a <= skip ? 1u : 0u);
        const std::uint64_t decays = std::uint64_t{0} - (r < 0.0 ? 1u : 0u);
        const std::uint64_t inf = std::bit_cast<std::uint64_t>(kInf);
        const std::uint64_t later = (decays & std::bit_cast<std::uint64_t>(t)) | (~decays & inf);
        dead[k] = std::bit_cast<double>((grows & inf) | (~grows & ~small & later));
    }
}

}  // namespace vi
