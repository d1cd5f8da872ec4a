// uq: `vibroimpact uq` in-process; its summary is the uq.json the command writes and its table the
// samples.csv, built from the same CSV rows.

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "point_rows.hpp"
#include "model/input_error.hpp"
#include "model/parallel_for.hpp"
#include "study/analyses/sweep_analyses.hpp"
#include "sweep/table.hpp"
#include "uq/sample_design.hpp"
#include "uq/sobol_indices.hpp"
#include "uq/uq_summary.hpp"

namespace vi::python {
namespace {

// {path: "normal:MEAN:SD"} or a list of "PATH=DIST" as on the command line.
std::vector<std::string> vary_of(const py::object& vary) {
    std::vector<std::string> out;
    if (py::isinstance<py::dict>(vary)) {
        for (const auto& [k, v] : vary.cast<py::dict>()) out.push_back(py::str(k).cast<std::string>() + "=" + py::str(v).cast<std::string>());
    } else {
        for (const py::handle s : vary) out.push_back(py::str(s).cast<std::string>());
    }
    return out;
}

SamplingMethod method_of(const std::string& m) {
    if (m == "mc") return SamplingMethod::mc;
    if (m == "lhs") return SamplingMethod::lhs;
    if (m == "sobol") return SamplingMethod::sobol;
    throw InputError("method: \"" + m + "\" is none of mc, lhs, sobol");
}

py::dict uq(const Case& base, const py::object& vary, const std::string& analysis, std::size_t samples,
            const std::string& method, std::uint64_t seed, const std::vector<std::string>& specs, bool sensitivity,
            int modes, int threads, double point_timeout, std::size_t bootstrap,
            const std::optional<std::string>& progress_mode, double progress_interval) {
    if (samples < 2) throw InputError("samples: a spread needs at least 2 samples");
    if (sensitivity && samples < kMinSobolBaseSamples) {
        throw InputError("samples: sensitivity needs at least " + std::to_string(kMinSobolBaseSamples) + " base samples");
    }
    if (!(point_timeout >= 0.0)) throw InputError("point_timeout: must be 0 (none) or positive seconds");
    if (threads < 0) throw InputError("threads: must be 0 (every CPU this process may use) or more");
    if (bootstrap < 100) throw InputError("bootstrap: at least 100 resamples");
    const std::vector<UqInput> inputs = parse_uq_inputs(vary_of(vary), base);
    SweepSettings settings;
    settings.analysis = parse_sweep_analysis(analysis);
    settings.modes = modes;
    settings.point_timeout = point_timeout;
    settings = with_study_analyses(settings);
    check_sweep_analysis(base, settings);
    settings.supports = static_cast<int>(base.supports.size());
    const std::vector<SweepColumn> columns = sweep_result_columns(settings.analysis, settings.modes, settings.supports);
    UqSettings s;
    s.analysis = analysis;
    s.method = method_of(method);
    s.seed = seed;
    s.resamples = bootstrap;
    std::vector<std::string> numeric;
    for (const SweepColumn& c : columns) {
        if (!sweep_column_is_text(c.name)) numeric.push_back(c.name);
    }
    for (const std::string& spec : specs) s.specs.push_back(parse_yield_spec(spec, numeric));
    const SampleDesign design = make_sample_design(inputs, samples, s.method, seed, sensitivity);

    const PointRows points = run_point_rows(base, design.grid, settings, resolve_thread_count(threads), columns, "uq",
                                            "runs", progress_mode, progress_interval);
    std::string csv = sweep_csv_header(design.grid, columns) + "\n";
    for (const std::string& row : points.rows) csv += row + "\n";
    nlohmann::json j = uq_summary_json(design, uq_table_from_csv(csv, inputs.size()), s);
    j["case"] = base.origin.file;
    j["case_name"] = base.name;
    py::dict out;
    out["table"] = csv_columns(csv, points.integer_columns);
    out["summary"] = json_value(j.dump());
    return out;
}

}  // namespace

void bind_uq(py::module_& m) {
    m.def("uq", &uq, py::arg("case"), py::arg("vary"), py::arg("analysis") = "simulate", py::arg("samples") = 256,
          py::arg("method") = "mc", py::arg("seed") = 1, py::arg("specs") = std::vector<std::string>{},
          py::arg("sensitivity") = false, py::arg("modes") = 3, py::arg("threads") = 0, py::arg("point_timeout") = 60.0,
          py::arg("bootstrap") = 1000, py::arg("progress") = py::none(), py::arg("progress_interval") = 10.0,
          "A spread study (`vibroimpact uq`): vary is {path: 'normal:MEAN:SD'} (or uniform, lognormal, "
          "truncnormal; units as in case files) or a list of 'PATH=DIST'; specs are 'COLUMN<=VALUE' texts. "
          "Returns {'table': {column: array} as samples.csv, 'summary': dict as uq.json}");
}

}  // namespace vi::python
