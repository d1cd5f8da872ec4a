#pragma once
// Points in the unit cube (0, 1)^d for sampling: plain Monte Carlo, Latin hypercube, or the Sobol
// sequence with a random digital shift; and the stream of random numbers behind them, the same on
// every machine (docs/uq.md).

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace vi {

enum class SamplingMethod { mc, lhs, sobol };

// "mc", "lhs", "sobol".
const char* sampling_method_name(SamplingMethod m);

// Random numbers that depend on the seed alone: std::mt19937_64's stream (its output is fixed by the
// C++ standard) turned into doubles and indices by this code, not by the library's distributions
// (whose algorithms the standard leaves to each implementation).
class UnitRandom {
public:
    explicit UnitRandom(std::uint64_t seed) : engine_(seed) {}
    // Uniform in (0, 1), never 0 or 1: a 53-bit grid point plus half a step.
    double uniform();
    // Uniform over 0 .. n-1 (n > 0).
    std::size_t below(std::size_t n);
    std::uint64_t bits() { return engine_(); }

private:
    std::mt19937_64 engine_;
};

// n points of (0, 1)^dims, row-major (point i's coordinate j at [i * dims + j]):
// mc: independent uniforms; lhs: each coordinate one point in each of n equal strata, the strata in
// a random order per coordinate, the point uniform within its stratum; sobol: the first n points
// of Boost.Random's Sobol sequence (Joe and Kuo's direction numbers; from the origin) in `dims` dimensions, each
// coordinate's 64 bits XORed with a random word of its own (a random digital shift: it keeps the
// sequence's stratification and makes its estimates unbiased; not Owen's scrambling). Deterministic
// for a given seed.
std::vector<double> unit_cube_points(SamplingMethod method, std::size_t n, std::size_t dims, std::uint64_t seed);

// Most dimensions the Sobol sequence is given for (Boost's table of direction numbers).
std::size_t sobol_max_dimensions();

}  // namespace vi
