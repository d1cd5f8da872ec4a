// Long runs off the interpreter: the work runs on its own thread with the GIL released while this
// thread polls Python's signal handlers, so that Ctrl-C stops the run through the library's stop
// flag (model/run_control.hpp) the way SIGINT stops the command line.

#include <chrono>
#include <csignal>
#include <exception>
#include <future>
#include <optional>
#include <thread>

#include "bindings.hpp"
#include "model/run_control.hpp"

namespace vi::python {

void run_released(const std::function<void()>& work, const std::function<void()>& while_waiting) {
    std::promise<void> done;
    std::future<void> finished = done.get_future();
    std::optional<py::error_already_set> interrupt;
    {
        const py::gil_scoped_release release;
        std::thread worker([&] {
            try {
                work();
                done.set_value();
            } catch (...) {
                done.set_exception(std::current_exception());
            }
        });
        // Every 50 ms: Python's handlers run only on the main thread and only when asked, and a
        // stopped run ends within milliseconds, so Ctrl-C takes effect in well under a second.
        while (finished.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
            const py::gil_scoped_acquire acquire;
            if (while_waiting) while_waiting();
            if (PyErr_CheckSignals() != 0) {
                interrupt.emplace();  // takes the pending exception (KeyboardInterrupt) off the thread
                request_stop(SIGINT);
                break;
            }
        }
        worker.join();
    }
    if (while_waiting) while_waiting();
    if (interrupt) {
        clear_stop();  // the stop was this run's: the next run starts clear
        throw *interrupt;
    }
    finished.get();
}

}  // namespace vi::python
