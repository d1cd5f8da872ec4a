#pragma once
// InputError: bad user input (case file, command-line value); its message is one line, ready to print.

#include <stdexcept>
#include <string>

namespace vi {

// Thrown for input the user must fix; the command line prints what() and exits with code 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace vi
