#include "uq/sampling.hpp"

#include <boost/random/sobol.hpp>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace vi {
namespace {

// A 64-bit word as a point of (0, 1): its top 53 bits and half a step, so never 0 or 1.
double unit_of_bits(std::uint64_t x) { return (static_cast<double>(x >> 11) + 0.5) * 0x1p-53; }

}  // namespace

const char* sampling_method_name(SamplingMethod m) {
    switch (m) {
        case SamplingMethod::mc: return "mc";
        case SamplingMethod::lhs: return "lhs";
        case SamplingMethod::sobol: return "sobol";
    }
    return "mc";
}

double UnitRandom::uniform() { return unit_of_bits(engine_()); }

std::size_t UnitRandom::below(std::size_t n) {
    // The remainder's bias, below n / 2^64, is far under any sample's noise.
    return static_cast<std::size_t>(engine_() % n);
}

std::size_t sobol_max_dimensions() { return boost::random::default_sobol_table::max_dimension; }

std::vector<double> unit_cube_points(SamplingMethod method, std::size_t n, std::size_t dims, std::uint64_t seed) {
    std::vector<double> x(n * dims);
    UnitRandom random(seed);
    switch (method) {
        case SamplingMethod::mc:
            for (double& v : x) v = random.uniform();
            break;
        case SamplingMethod::lhs:
            for (std::size_t j = 0; j < dims; ++j) {
                std::vector<std::size_t> stratum(n);
                std::iota(stratum.begin(), stratum.end(), std::size_t{0});
                for (std::size_t i = n; i > 1; --i) std::swap(stratum[i - 1], stratum[random.below(i)]);  // Fisher-Yates
                for (std::size_t i = 0; i < n; ++i) {
                    x[i * dims + j] = (static_cast<double>(stratum[i]) + random.uniform()) / static_cast<double>(n);
                }
            }
            break;
        case SamplingMethod::sobol: {
            if (dims > sobol_max_dimensions()) {
                throw std::invalid_argument("the Sobol sequence has at most " + std::to_string(sobol_max_dimensions()) +
                                            " dimensions");
            }
            std::vector<std::uint64_t> shift(dims);
            for (std::uint64_t& s : shift) s = random.bits();
            // Boost's engine starts from the sequence's second point; its first, the origin, is put
            // back, so that the first 2^m points are a (t, m, s)-net (each coordinate one point per
            // stratum of 2^-m). The shift moves the origin off the cube's corner.
            boost::random::sobol qrng(dims);
            for (std::size_t i = 0; i < n; ++i) {
                for (std::size_t j = 0; j < dims; ++j) x[i * dims + j] = unit_of_bits((i == 0 ? 0 : qrng()) ^ shift[j]);
            }
            break;
        }
    }
    return x;
}

}  // namespace vi
