#pragma once
// The paper's claims (Ostasevicius et al. 2009, sections 3 and 4) beside the numbers of one run of
// the study, each with a plain verdict. Every number is computed from the study, none typed in.

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "study/paper/study.hpp"

namespace vi {

enum class Verdict { agrees, partly, disagrees, not_computed };

// "agrees", "partly", "disagrees", "not computed".
const char* verdict_name(Verdict v);

struct Claim {
    Claim() = default;
    Claim(std::string where_, std::string paper_, std::string ours_, Verdict verdict_, std::string note_)
        : where(std::move(where_)), paper(std::move(paper_)), ours(std::move(ours_)), verdict(verdict_), note(std::move(note_)) {}
    std::string where;    // the paper's figure or section, e.g. "Fig. 4"
    std::string paper;    // what the paper says, with its number
    std::string ours;     // our number(s), with units
    Verdict verdict = Verdict::not_computed;
    std::string note;     // why, when it does not simply agree; or what the number means
    std::string id;       // short stable name, e.g. "nodal_point_mode2" (for claims.json and tests)
    std::map<std::string, double> values;  // the numbers behind `ours`, by name (SI or dimensionless)
};

// Distance in x0/l (or Delta/l) within which a minimum counts as "at" the paper's point; a little
// more than one scan step of the default scan, and above the two decimals the paper reads.
inline constexpr double kPointTolerance = 0.025;

std::vector<Claim> paper_claims(const PaperStudy& study);

// Values of one scan as curves over x, for the claims and the figures.
std::vector<double> scan_x(const TransientScan& s);
std::vector<std::optional<double>> scan_z_max(const TransientScan& s);
std::vector<std::optional<double>> scan_tau_p(const TransientScan& s);

}  // namespace vi
