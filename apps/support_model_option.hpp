#pragma once
// The --support-model option shared by modal subcommands: supports as pins or as contact springs.

#include <CLI/CLI.hpp>
#include <string>

#include "fem/system.hpp"

namespace vi::cli {

inline CLI::Option* add_support_model_option(CLI::App& sub, std::string& value) {
    return sub.add_option("--support-model", value, "How supports act in the supported modes: pin or spring (Kc)")
        ->check(CLI::IsMember({"pin", "spring"}));
}

inline SupportModel parse_support_model(const std::string& value) {
    return value == "spring" ? SupportModel::spring : SupportModel::pin;
}

}  // namespace vi::cli
