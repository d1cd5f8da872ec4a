// first_frequency CASE [EXPECTED_HZ]: reads a case file through the installed vibroimpact library and
// prints the first bending frequency of its unsupported beam [Hz]. With EXPECTED_HZ, exits 1 unless
// the two agree to 1e-9 relative; bad input exits 2 with the library's one-line message.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include <vibroimpact/io/case_reader.hpp>
#include <vibroimpact/modal/modal_analysis.hpp>
#include <vibroimpact/model/input_error.hpp>

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: first_frequency CASE [EXPECTED_HZ]\n");
        return 2;
    }
    try {
        const vi::Case c = vi::read_case_file(argv[1]);
        const vi::ModalStudy study = vi::modal_study(c, 1, vi::SupportModel::pin);
        if (study.unsupported.bending.empty()) {
            std::fprintf(stderr, "first_frequency: %s: no bending mode\n", argv[1]);
            return 1;
        }
        const double f = study.unsupported.bending.front().frequency_hz;
        std::printf("%s: first bending frequency %.12g Hz\n", c.name.c_str(), f);
        if (!std::isfinite(f) || f <= 0.0) return 1;
        if (argc == 3) {
            const double expected = std::strtod(argv[2], nullptr);
            if (!(std::abs(f - expected) <= 1e-9 * std::abs(expected))) {
                std::fprintf(stderr, "first_frequency: %.17g Hz, expected %.17g Hz\n", f, expected);
                return 1;
            }
        }
        return 0;
    } catch (const vi::InputError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "first_frequency: %s\n", e.what());
        return 1;
    }
}
