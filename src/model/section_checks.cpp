#include "model/section_checks.hpp"

#include <cmath>
#include <string>

#include "model/number_format.hpp"

namespace vi {
namespace {

// Two section ends closer than this (x/l) are the same point: ends written as decimals meet exactly,
// ends computed elsewhere (a sweep's 1/3) within roundoff.
constexpr double kSectionEndTolerance = 1e-12;

std::string section_key(std::size_t k, const char* field) {
    return "beam.sections[" + std::to_string(k) + "]." + field;
}

void check_cover(std::vector<CaseProblem>& out, const std::vector<BeamSection>& s) {
    double end = 0.0;
    for (std::size_t k = 0; k < s.size(); ++k) {
        const double step = s[k].from - end;
        if (std::abs(step) > kSectionEndTolerance) {
            const std::string before = k == 0 ? "the beam's start" : "beam.sections[" + std::to_string(k - 1) +
                                                                      "], which ends at x/l = " + significant(end, 6);
            const std::string what = step > 0.0 ? "leaves a gap from x/l = " + significant(end, 6) + " to " +
                                                      significant(s[k].from, 6) + " after "
                                                : "overlaps ";
            out.push_back({section_key(k, "from"), what + before +
                                                       "; the sections must cover the beam from 0 to 1 in order, "
                                                       "each from at the previous to"});
            return;
        }
        if (!(s[k].to > s[k].from)) {
            out.push_back({section_key(k, "to"), "must lie beyond its from (" + significant(s[k].from, 6) + ")"});
            return;
        }
        end = s[k].to;
    }
    if (!s.empty() && std::abs(end - 1.0) > kSectionEndTolerance) {
        out.push_back({section_key(s.size() - 1, "to"), "the last section must end at x/l = 1 (it ends at " +
                                                            significant(end, 6) + ", leaving a gap to the end)"});
    }
}

}  // namespace

std::string holes_pitch_problem(double size, double pitch) {
    if (size < pitch) return "";
    return "must be below the pitch (" + significant(pitch * 1e6, 4) + " um): the holes would leave no material between them";
}

void check_sections(std::vector<CaseProblem>& out, const Case& c) {
    check_cover(out, c.beam.sections);
    for (std::size_t i = 0; i < c.materials.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (c.materials[j].name == c.materials[i].name) {
                out.push_back({"materials[" + std::to_string(i) + "].name",
                               "\"" + c.materials[i].name + "\" is already the name of materials[" + std::to_string(j) + "]"});
            }
        }
    }
    for (std::size_t k = 0; k < c.beam.sections.size(); ++k) {
        const BeamSection& s = c.beam.sections[k];
        const double w = s.width.value_or(c.beam.width);
        // The reader refuses these at once; a path (sweep, fit) may set them later.
        if (s.holes && s.holes->size > 0.0 && s.holes->pitch > 0.0) {
            if (std::string why = holes_pitch_problem(s.holes->size, s.holes->pitch); !why.empty()) {
                out.push_back({section_key(k, "holes.size"), std::move(why)});
                continue;
            }
        }
        if (s.holes && s.holes->size > 0.0 && w > 0.0 && !(s.holes->size < w)) {
            out.push_back({section_key(k, "holes.size"), "the holes (" + significant(s.holes->size * 1e6, 4) +
                                                             " um) are as wide as the section or wider (w = " +
                                                             significant(w * 1e6, 4) + " um): they would cut it"});
        }
    }
    std::string names;
    for (const LayerMaterial& m : c.materials) names += (names.empty() ? "" : ", ") + ("\"" + m.name + "\"");
    for (std::size_t k = 0; k < c.beam.sections.size(); ++k) {
        const std::vector<Layer>& layers = c.beam.sections[k].layers;
        for (std::size_t j = 0; j < layers.size(); ++j) {
            bool known = false;
            for (const LayerMaterial& m : c.materials) known = known || m.name == layers[j].material;
            if (known) continue;
            out.push_back({"beam.sections[" + std::to_string(k) + "].layers[" + std::to_string(j) + "].material",
                           "no [[materials]] entry is named \"" + layers[j].material + "\"" +
                               (names.empty() ? " (the case has no [[materials]])" : " (materials: " + names + ")")});
        }
    }
}

}  // namespace vi
