#pragma once
// Decomposed contact states kept on each thread from one exact solve to the next: the points of a
// sweep, a fit or a repeated run that keep the beam (mesh, material, damping) meet the same states
// again (the free state at every point; every state when only the start or the horizon changes),
// and take them instead of decomposing them again. The result is the same either way.

#include <cstddef>
#include <memory>
#include <vector>

#include "dynamics/exact/state_modes.hpp"
#include "dynamics/piecewise_linear_problem.hpp"

namespace vi {

struct StateData;

// One contact state of one model: which contacts are closed, and the stiffness and damping of each
// closed one (the open ones do not enter the state's modes).
struct StateMemoKey {
    std::vector<bool> active;
    std::vector<double> closed;  // Kc [N/m], Cc [N s/m] of each closed contact, in order
    auto operator<=>(const StateMemoKey&) const = default;
};
StateMemoKey state_memo_key(const PiecewiseLinearProblem& p, const std::vector<bool>& active);

// Memory the memo of one thread keeps at most [bytes] (besides a run's own cache).
inline constexpr std::size_t kStateMemoBytes = std::size_t{16} << 20;

// The memo of this thread, made the one of model (b, p, energy): the states of any other model
// (another beam, contact points, watched point, load shapes, or with/without the energy ledger) are
// dropped first.
class StateMemo {
public:
    static StateMemo& for_model(const BaseModes& b, const PiecewiseLinearProblem& p, bool energy);
    // The state kept under k, or null.
    [[nodiscard]] std::shared_ptr<const StateData> find(const StateMemoKey& k);
    // Keeps s (of `bytes`) within min(kStateMemoBytes, limit), dropping the least recently used.
    void keep(const StateMemoKey& k, std::shared_ptr<const StateData> s, std::size_t bytes, std::size_t limit);

private:
    struct Entry {
        std::shared_ptr<const StateData> data;
        std::size_t bytes = 0;
        long last_use = 0;
    };
    struct Model {
        Eigen::MatrixXd phi;
        Eigen::VectorXd omega, zeta;
        std::vector<int> contact_dofs;
        int watched_dof = -1;
        std::vector<Eigen::VectorXd> load_shapes;
        bool energy = false;
        [[nodiscard]] bool same_except_phi(const Model& o) const;
    };
    Model model_;
    std::vector<std::pair<StateMemoKey, Entry>> entries_;
    std::size_t bytes_ = 0;
    long uses_ = 0;
};

}  // namespace vi
