// switch_study CASE [PATH=VALUE ...]: a case through the installed library's entry header. Reads the
// case, sets each PATH=VALUE as `sweep --set` takes one value ("electrodes[0].voltage=75 V"), checks
// it, then prints, one line each: the first bending frequency of the free beam [Hz], the static
// pull-in voltage [V] (with electrodes), the transient's impacts and period T [s], and a three-point
// sweep of the first support's stiffness (x0.5, x1, x2) with T at each point [s].
// Bad input exits 2 with the library's one-line message; numerical trouble exits 1.

#include <cstdio>
#include <exception>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <vibroimpact/vibroimpact.hpp>

namespace {

void print_frequency(const vi::Case& c) {
    const vi::ModalStudy study = vi::modal_study(c, 1, vi::SupportModel::pin);
    if (study.unsupported.bending.empty()) throw std::runtime_error("the free beam has no bending mode");
    const vi::BeamModel model = vi::build_beam_model(c);
    std::printf("model: %d bending DOFs, %zu force elements, first frequency %.12g Hz\n",
                static_cast<int>(model.K.rows()), model.forces.size(),
                study.unsupported.bending.front().frequency_hz);
}

void print_pullin(const vi::Case& c) {
    if (c.electrodes.empty()) {
        std::printf("pull-in: no electrode\n");
        return;
    }
    const vi::PullinResult p = vi::trace_pullin(c);
    if (p.pullin) {
        std::printf("pull-in: %.12g V\n", p.pullin->voltage);
    } else {
        std::printf("pull-in: none (%s)\n", p.end.c_str());
    }
}

void print_simulation(const vi::Case& c) {
    const vi::SimulationRun run = vi::run_simulation(c);
    std::printf("simulate: %zu impacts, T %.12g s\n", run.summary.impacts.size(),
                run.summary.T_first.value_or(0.0));
}

// The column's index among the sweep's result columns.
std::size_t column(const std::string& name) {
    const auto columns = vi::sweep_result_columns(vi::SweepAnalysis::simulate, 0);
    for (std::size_t i = 0; i < columns.size(); ++i)
        if (columns[i].name == name) return i;
    throw std::runtime_error("no sweep column " + name);
}

void print_sweep(const vi::Case& c) {
    if (c.supports.empty()) {
        std::printf("sweep: no support\n");
        return;
    }
    const vi::CasePath path = vi::resolve_case_path("supports[0].stiffness", c);
    const double k = vi::get_case_value(c, path);
    char spec[160];
    std::snprintf(spec, sizeof spec, "%s=%.17g,%.17g,%.17g", path.text().c_str(), 0.5 * k, k, 2.0 * k);
    const vi::SweepGrid grid = vi::parse_sweep_grid({spec}, c);
    std::vector<std::size_t> indices(grid.size());
    std::iota(indices.begin(), indices.end(), std::size_t{0});
    std::vector<vi::SweepPointResult> points(grid.size());
    vi::run_sweep_points(c, grid, indices, vi::SweepSettings{}, 0,
                         [&](const vi::SweepPointResult& r) { points[r.index] = r; });
    const std::size_t T = column("T_s");
    std::printf("sweep %s:", path.text().c_str());
    for (const vi::SweepPointResult& r : points) {
        if (!r.ok()) {
            std::printf(" [%s]", r.status.c_str());
            continue;
        }
        std::printf(" %.6g N/m -> T %.12g s;", r.parameters[0], vi::numeric_cell(r.cells[T]).value_or(0.0));
    }
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: switch_study CASE [PATH=VALUE ...]\n");
        return 2;
    }
    try {
        vi::Case c = vi::read_case_file(argv[1]);
        for (int i = 2; i < argc; ++i) {
            const std::string setting = argv[i];
            const std::size_t eq = setting.find('=');
            if (eq == std::string::npos) throw vi::InputError(setting + ": expected PATH=VALUE");
            vi::set_case_text(c, setting.substr(0, eq), setting.substr(eq + 1));
        }
        const auto problems = vi::check_case(c);
        for (const vi::CaseProblem& p : problems) std::fprintf(stderr, "%s: %s\n", p.key.c_str(), p.message.c_str());
        if (!problems.empty()) return 2;
        std::printf("case %s\n", c.name.c_str());
        print_frequency(c);
        print_pullin(c);
        print_simulation(c);
        print_sweep(c);
        return 0;
    } catch (const vi::InputError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "switch_study: %s\n", e.what());
        return 1;
    }
}
