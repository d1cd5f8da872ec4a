#include "uq/sample_design.hpp"

#include <stdexcept>

#include "model/input_error.hpp"

namespace vi {

UqInput parse_uq_input(const std::string& text, const Case& c) {
    const auto fail = [&](const std::string& reason) { return InputError("--vary", text, reason); };
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) throw fail("expected PATH=DIST:..., e.g. beam.thickness=normal:2um:0.05um");
    UqInput in;
    in.setting = text;
    try {
        in.path = resolve_case_path(text.substr(0, eq), c);
    } catch (const InputError& e) {
        throw fail(e.what());
    }
    if (is_integer_path(in.path)) {
        throw fail(in.path.text() + " takes whole numbers, which a distribution does not give (sweep it with --set)");
    }
    try {
        in.distribution = parse_distribution(text.substr(eq + 1), case_path_dimension(in.path));
    } catch (const std::invalid_argument& e) {
        throw fail(e.what());
    }
    return in;
}

std::vector<UqInput> parse_uq_inputs(const std::vector<std::string>& texts, const Case& c) {
    if (texts.empty()) throw InputError("--vary: at least one PATH=DIST:... is needed");
    std::vector<UqInput> inputs;
    for (const std::string& t : texts) {
        UqInput in = parse_uq_input(t, c);
        for (const UqInput& other : inputs) {
            if (other.path == in.path) throw InputError("--vary", t, in.path.text() + " is already varied by --vary " + other.setting);
        }
        inputs.push_back(std::move(in));
    }
    return inputs;
}

SampleDesign make_sample_design(const std::vector<UqInput>& inputs, std::size_t n, SamplingMethod method,
                                std::uint64_t seed, bool sensitivity) {
    SampleDesign d;
    d.base = n;
    d.sensitivity = sensitivity;
    d.inputs = inputs;
    const std::size_t dims = inputs.size();
    const std::size_t width = sensitivity ? 2 * dims : dims;
    const std::vector<double> u = unit_cube_points(method, n, width, seed);
    // The value of input i at base row j from matrix A (block 0) or B (block 1).
    const auto value = [&](std::size_t block, std::size_t j, std::size_t i) {
        return inputs[i].distribution.quantile(u[j * width + block * dims + i]);
    };
    std::vector<SweepAxis> axes;
    for (std::size_t i = 0; i < dims; ++i) {
        SweepAxis a;
        a.setting = "--vary " + inputs[i].setting;
        a.path = inputs[i].path;
        std::vector<double>& v = a.values;
        for (std::size_t j = 0; j < n; ++j) v.push_back(value(0, j, i));
        if (sensitivity) {
            for (std::size_t j = 0; j < n; ++j) v.push_back(value(1, j, i));
            // A_B^(k): A with column k from B.
            for (std::size_t k = 0; k < dims; ++k) {
                for (std::size_t j = 0; j < n; ++j) v.push_back(value(k == i ? 1 : 0, j, i));
            }
        }
        axes.push_back(std::move(a));
    }
    d.grid = SweepGrid::paired(std::move(axes));
    return d;
}

}  // namespace vi
