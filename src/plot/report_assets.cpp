#include "plot/report_assets.hpp"

#include <stdexcept>
#include <string>

namespace vi {

std::string_view report_asset(std::string_view name) {
    for (const EmbeddedFile& f : report_asset_files()) {
        if (f.name == name) return f.text;
    }
    throw std::logic_error("report: the build embedded no " + std::string(name));
}

}  // namespace vi
