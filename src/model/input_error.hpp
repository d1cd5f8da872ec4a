#pragma once
// InputError: bad user input (case file, command-line value); its message is one line, ready to print.

#include <stdexcept>
#include <string>
#include <string_view>

namespace vi {

// Thrown for input the user must fix; the command line prints what() and exits with code 2. An
// error in one setting of an option ("--set PATH=SPEC") also keeps the option and the case path
// apart, so that a caller other than the command line (the Python module) need not take the
// message apart: the spec may itself hold ':' and '='.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
    InputError(std::string_view option, const std::string& setting, const std::string& reason)
        : std::runtime_error(std::string(option) + " " + setting + ": " + reason),
          option_(option),
          key_(setting.substr(0, setting.find('='))) {}

    // The option of a setting's error ("--set", "--vary", "--fit"); empty otherwise.
    [[nodiscard]] const std::string& option() const noexcept { return option_; }
    // The case path the setting names, as written ("supports[0].position"); empty otherwise.
    [[nodiscard]] const std::string& key() const noexcept { return key_; }

private:
    std::string option_, key_;
};

}  // namespace vi
