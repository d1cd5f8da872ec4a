#include "modal/modal_analysis.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include "modal/eigen_solver.hpp"

namespace vi {
namespace {

std::vector<Mode> family_modes(const System& s, const std::vector<int>& dofs, int count, bool with_features) {
    std::vector<Mode> modes;
    if (dofs.empty() || count <= 0) return modes;
    const ModeSet set = lowest_modes(submatrix(s.K, dofs), submatrix(s.M, dofs), count);
    for (Eigen::Index j = 0; j < set.omega.size(); ++j) {
        Eigen::VectorXd reduced = Eigen::VectorXd::Zero(s.size());
        for (std::size_t i = 0; i < dofs.size(); ++i) reduced[dofs[i]] = set.shapes(static_cast<Eigen::Index>(i), j);
        Mode m;
        m.number = static_cast<int>(j) + 1;
        m.omega = set.omega[j];
        m.frequency_hz = m.omega / (2.0 * std::numbers::pi);
        m.shape = expand_to_global(s, reduced);
        if (with_features) m.features = shape_features(s, m.shape);
        modes.push_back(std::move(m));
    }
    return modes;
}

}  // namespace

ModalResult analyse_modes(const System& s, int count) {
    ModalResult r;
    r.system = s;
    r.dofs = s.size();
    r.bending = family_modes(s, s.bending, count, true);
    r.axial = family_modes(s, s.axial, count, false);
    return r;
}

ModalStudy modal_study(const Case& c, int count, SupportModel support_model) {
    if (support_model == SupportModel::none) throw std::invalid_argument("modal_study: supported model must be pin or spring");
    ModalStudy study;
    study.case_name = c.name;
    study.support_model = support_model;
    study.unsupported = analyse_modes(build_system(c, SupportModel::none), count);
    study.released = released_curl(c, study.unsupported.system);
    if (!c.supports.empty()) {
        study.supported = analyse_modes(build_system(c, support_model), count);
        const std::size_t n = std::min(study.supported.bending.size(), study.unsupported.bending.size());
        for (std::size_t i = 0; i < n; ++i) {
            study.ratios.push_back(study.supported.bending[i].omega / study.unsupported.bending[i].omega);
        }
    }
    return study;
}

}  // namespace vi
