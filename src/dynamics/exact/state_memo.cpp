#include "dynamics/exact/state_memo.hpp"

#include <algorithm>

namespace vi {
namespace {

template <class A>
bool same(const A& a, const A& b) {
    return a.rows() == b.rows() && a.cols() == b.cols() && a == b;
}

}  // namespace

StateMemoKey state_memo_key(const PiecewiseLinearProblem& p, const std::vector<bool>& active) {
    StateMemoKey k;
    k.active = active;
    for (std::size_t c = 0; c < p.contacts.size() && c < active.size(); ++c) {
        if (!active[c]) continue;
        k.closed.push_back(p.contacts[c].stiffness);
        k.closed.push_back(p.contacts[c].damping);
    }
    return k;
}

bool StateMemo::Model::same_except_phi(const Model& o) const {
    if (energy != o.energy || watched_dof != o.watched_dof || contact_dofs != o.contact_dofs) return false;
    if (load_shapes.size() != o.load_shapes.size()) return false;
    for (std::size_t l = 0; l < load_shapes.size(); ++l) {
        if (!same(load_shapes[l], o.load_shapes[l])) return false;
    }
    return same(omega, o.omega) && same(zeta, o.zeta);
}

StateMemo& StateMemo::for_model(const BaseModes& b, const PiecewiseLinearProblem& p, bool energy) {
    thread_local StateMemo memo;
    Model m;
    m.omega = b.omega;
    m.zeta = b.zeta;
    m.energy = energy;
    m.watched_dof = p.watched_dof;
    for (const ContactElement& c : p.contacts) m.contact_dofs.push_back(c.dof);
    for (const LoadTerm& l : p.loads) m.load_shapes.push_back(l.shape);
    // phi (n x n) is compared in place, once the cheap parts agree.
    if (!(m.same_except_phi(memo.model_) && same(b.phi, memo.model_.phi))) {
        memo.entries_.clear();
        memo.bytes_ = 0;
        m.phi = b.phi;
        memo.model_ = std::move(m);
    }
    return memo;
}

std::shared_ptr<const StateData> StateMemo::find(const StateMemoKey& k) {
    for (auto& [key, e] : entries_) {
        if (key == k) {
            e.last_use = ++uses_;
            return e.data;
        }
    }
    return nullptr;
}

void StateMemo::keep(const StateMemoKey& k, std::shared_ptr<const StateData> s, std::size_t bytes, std::size_t limit) {
    const std::size_t cap = std::min(kStateMemoBytes, limit);
    if (bytes > cap) return;
    while (!entries_.empty() && bytes_ + bytes > cap) {
        auto lru = std::min_element(entries_.begin(), entries_.end(),
                                    [](const auto& a, const auto& b) { return a.second.last_use < b.second.last_use; });
        bytes_ -= lru->second.bytes;
        entries_.erase(lru);
    }
    bytes_ += bytes;
    entries_.push_back({k, Entry{std::move(s), bytes, ++uses_}});
}

}  // namespace vi
