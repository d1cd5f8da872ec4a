#include <cmath>
#include <mutex>
#include <string>

#include "bindings.hpp"
#include "model/input_error.hpp"

namespace vi::python {

struct PythonProgress::Queue {
    std::mutex mutex;
    std::string text;
};

PythonProgress::PythonProgress(const std::optional<std::string>& mode, double interval_s)
    : interval_s_(interval_s), queue_(std::make_shared<Queue>()) {
    if (!(interval_s >= 0.0) || !std::isfinite(interval_s)) {
        throw InputError("progress_interval: must be 0 (a line at every step) or positive seconds");
    }
    bool terminal = false;
    try {
        terminal = py::module_::import("sys").attr("stderr").attr("isatty")().cast<bool>();
    } catch (const py::error_already_set&) {
        terminal = false;  // a stream without isatty (or none at all) is no terminal
    }
    style_ = progress_style_named(mode.value_or(""), terminal, "progress");
}

ProgressSink PythonProgress::sink() const {
    return [queue = queue_](const std::string& text) {
        const std::lock_guard<std::mutex> lock(queue->mutex);
        queue->text += text;
    };
}

void PythonProgress::flush() const {
    std::string text;
    {
        const std::lock_guard<std::mutex> lock(queue_->mutex);
        text.swap(queue_->text);
    }
    if (text.empty()) return;
    try {
        const py::object err = py::module_::import("sys").attr("stderr");
        if (err.is_none()) return;
        err.attr("write")(text);
        err.attr("flush")();
    } catch (const py::error_already_set&) {
        // A closed or odd stream: the text is dropped, the run goes on.
    }
}

}  // namespace vi::python
