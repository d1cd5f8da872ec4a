// The one-line message of the InputError a call throws ("" when it reads the input without one).
#pragma once

#include <string>
#include <utility>

#include "model/input_error.hpp"

namespace vi::test {

template <class Read>
std::string input_error_of(Read&& read) {
    try {
        std::forward<Read>(read)();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace vi::test
