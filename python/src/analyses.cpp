// modes, simulate and pullin: the commands' computations in-process, their results as the files the
// command writes with --out (CSV columns as numpy arrays, JSON as dicts).

#include <optional>
#include <string>

#include "bindings.hpp"
#include "statics/pullin.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "modal/modal_analysis.hpp"
#include "model/input_error.hpp"
#include "report/modal_output.hpp"
#include "report/pullin_output.hpp"
#include "report/transient_output.hpp"

namespace vi::python {
namespace {

// Runs body(c) off the interpreter (run_released); an InputError about a key is placed in the case
// file, as the command line does.
template <class Body>
OutputFiles run_case(const Case& c, Body&& body) {
    OutputFiles files;
    run_released([&] {
        try {
            files = body();
        } catch (const InputError& e) {
            throw locate_in_case(c, e);
        }
    });
    return files;
}

}  // namespace

SupportModel support_model_of(const std::string& name) {
    if (name == "pin") return SupportModel::pin;
    if (name == "spring") return SupportModel::spring;
    throw InputError("support_model: \"" + name + "\" is neither \"pin\" nor \"spring\"");
}

void bind_analyses(py::module_& m) {
    m.def(
        "modes",
        [](const Case& c, int count, const std::string& support_model) {
            if (count < 1 || count > 1000) throw InputError("count: must be 1 to 1000 (got " + std::to_string(count) + ")");
            const SupportModel model = support_model_of(support_model);
            return files_dict(run_case(c, [&] { return modal_study_files(modal_study(c, count, model)); }));
        },
        py::arg("case"), py::arg("count") = 5, py::arg("support_model") = "pin",
        "Natural modes (`vibroimpact modes --out`): {'modes': dict, 'frequencies': {column: array}, "
        "'shapes_unsupported': ..., 'shapes_supported': ..., 'released_shape': ... (a curled beam)}");
    m.def(
        "simulate",
        [](const Case& c) {
            return files_dict(run_case(c, [&] {
                const SimulationRun run = run_simulation(c);
                return transient_files(c, run.built, run.result, run.summary, run.switching ? &*run.switching : nullptr);
            }));
        },
        py::arg("case"),
        "The free transient (`vibroimpact simulate --out`): {'history': {column: array}, 'events': {column: array}, "
        "'summary': dict}");
    m.def(
        "pullin",
        [](const Case& c, int steps) {
            if (steps < 10 || steps > 100000) throw InputError("steps: must be 10 to 100000 (got " + std::to_string(steps) + ")");
            PullinOptions o;
            o.steps = steps;
            return files_dict(run_case(c, [&] { return pullin_files(trace_pullin(c, o)); }));
        },
        py::arg("case"), py::arg("steps") = PullinOptions{}.steps,
        "Static pull-in (`vibroimpact pullin --out`): {'pullin': dict, 'pullin_branch': {column: array}, "
        "'pullin_frequencies': {column: array}}");
}

}  // namespace vi::python
