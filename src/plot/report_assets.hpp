#pragma once
// The files report.html inlines for its interactive figures, built into the program (src/CMakeLists.txt
// embeds them with cmake/embed_files.cmake): uPlot.iife.min.js and uPlot.min.css (third_party/uplot,
// MIT) and the page script report_charts.js (src/plot).

#include <string_view>
#include <vector>

#include "model/embedded_file.hpp"

namespace vi {

// uPlot.iife.min.js, uPlot.min.css, report_charts.js, in this order.
const std::vector<EmbeddedFile>& report_asset_files();

// The text of one of them by name; throws std::logic_error when the build did not embed it.
std::string_view report_asset(std::string_view name);

}  // namespace vi
