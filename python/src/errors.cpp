// The library's exceptions as Python ones: InputError (a ValueError) carries the file, line and key
// of the message "FILE:LINE: KEY: reason"; numerical trouble and run limits become SolverError (a
// RuntimeError); a stop (Ctrl-C) becomes KeyboardInterrupt.

#include <cctype>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"

namespace vi::python {
namespace {

struct Located {
    std::optional<std::string> file;
    std::optional<int> line;
    std::optional<std::string> key;
    std::string reason;
};

// "FILE:LINE: rest" (the reader and locate_in_case), "FILE: cannot read file (...)", then in rest
// "KEY: reason" where KEY has no space.
Located locate(const std::string& message) {
    Located l;
    std::string rest = message;
    for (std::size_t colon = rest.find(':'); colon != std::string::npos; colon = rest.find(':', colon + 1)) {
        std::size_t end = colon + 1;
        while (end < rest.size() && std::isdigit(static_cast<unsigned char>(rest[end]))) ++end;
        if (end > colon + 1 && rest.compare(end, 2, ": ") == 0) {
            l.file = rest.substr(0, colon);
            l.line = std::stoi(rest.substr(colon + 1, end - colon - 1));
            rest = rest.substr(end + 2);
            break;
        }
    }
    if (!l.file) {
        const auto unreadable = rest.find(": cannot read file (");
        if (unreadable != std::string::npos) {
            l.file = rest.substr(0, unreadable);
            l.reason = rest.substr(unreadable + 2);
            return l;
        }
    }
    const auto sep = rest.find(": ");
    if (sep != std::string::npos) {
        const std::string key = rest.substr(0, sep);
        if (!key.empty() && key.find(' ') == std::string::npos) {
            l.key = key;
            rest = rest.substr(sep + 2);
        }
    }
    l.reason = rest;
    return l;
}

py::object optional_object(const std::optional<std::string>& v) { return v ? py::object(py::str(*v)) : py::none(); }

// Owned by the module (its attributes); plain handles here.
PyObject* input_error_type = nullptr;
PyObject* solver_error_type = nullptr;

// The error of an option's setting ("--set PATH=SPEC: reason") carries its option and path; the
// message is not taken apart, since the spec may hold ':' itself. Every other message is.
void raise_input_error(const InputError& e) {
    const std::string message = e.what();
    Located l;
    std::optional<std::string> option;
    if (!e.option().empty()) {
        option = e.option();
        l.key = e.key();
        const auto sep = message.find(": ", e.option().size() + 1 + e.key().size());
        l.reason = sep == std::string::npos ? message : message.substr(sep + 2);
    } else {
        l = locate(message);
    }
    py::object error = py::reinterpret_borrow<py::object>(input_error_type)(message);
    error.attr("file") = optional_object(l.file);
    error.attr("line") = l.line ? py::object(py::int_(*l.line)) : py::none();
    error.attr("key") = optional_object(l.key);
    error.attr("option") = optional_object(option);
    error.attr("reason") = py::str(l.reason);
    PyErr_SetObject(input_error_type, error.ptr());
}

}  // namespace

void bind_errors(py::module_& m) {
    static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
    static py::exception<std::runtime_error> solver_error(m, "SolverError", PyExc_RuntimeError);
    input_error_type = input_error.ptr();
    solver_error_type = solver_error.ptr();
    input_error.doc() =
        "Bad input (case, path, value): attributes file, line, key, option (None when unknown) and reason";
    solver_error.doc() = "A run that could not finish: numerical trouble or a bound on its work or time";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const py::builtin_exception&) {
            throw;  // pybind11's own (cast errors, ...): its default translation
        } catch (const InputError& e) {
            raise_input_error(e);
        } catch (const StopRequested&) {
            PyErr_SetNone(PyExc_KeyboardInterrupt);
        } catch (const std::runtime_error& e) {
            PyErr_SetString(solver_error_type, e.what());
        }
    });
}

}  // namespace vi::python
