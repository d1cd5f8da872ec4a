#include "sweep/identity.hpp"

#include <cstdint>
#include <cstdio>

#include "model/number_format.hpp"

namespace vi {

std::string sweep_identity_text(std::string_view case_text, const SweepGrid& grid, const SweepSettings& settings) {
    std::string t = "vibroimpact sweep identity 1\n";
    // The case text is hashed on its own so that no text inside it can mimic the lines below.
    t += "case " + fingerprint_of(case_text) + " " + std::to_string(case_text.size()) + "\n";
    for (const SweepAxis& a : grid.axes()) {
        t += "set " + a.path.text() + " =";
        for (double v : a.values) {
            t += ' ';
            t += significant(v, 17);
        }
        t += "\n";
    }
    if (settings.analysis == SweepAnalysis::modes) {
        t += "analysis modes " + std::to_string(settings.modes) + " " +
             (settings.support_model == SupportModel::spring ? "spring" : "pin") + "\n";
    } else {
        t += std::string("analysis ") + sweep_analysis_name(settings.analysis) + "\n";
    }
    // A sample design (uq) pairs its axes point by point; a grid's text stays as it always was.
    if (grid.paired()) t += "layout paired\n";
    return t;
}

std::string fingerprint_of(std::string_view text) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char ch : text) {
        h ^= ch;
        h *= 1099511628211ull;
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

}  // namespace vi
