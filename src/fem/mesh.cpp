#include "fem/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "model/input_error.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {

// A node placed for a support (or two supports close together) can make an element so short that
// its stiffness EI/L^3 swamps the rest of K; refused on the latest support at either of its nodes.
void check_shortest_element(const Mesh& mesh, const Beam& beam) {
    const double l = beam.length, h = l / beam.elements;
    int shortest = 0;
    for (int e = 1; e < mesh.element_count(); ++e) {
        if (mesh.element_length(e) < mesh.element_length(shortest)) shortest = e;
    }
    const double len = mesh.element_length(shortest);
    const double condition = 5.0 * (l / len) * (l / len) * (l / len) * (l / h);
    if (condition <= kMaxMeshCondition) return;
    int support = -1;
    for (std::size_t k = 0; k < mesh.support_nodes.size(); ++k) {
        const int node = mesh.support_nodes[k];
        if (node == shortest || node == shortest + 1) support = static_cast<int>(k);
    }
    const std::string key = support < 0 ? "beam.elements" : "supports[" + std::to_string(support) + "].position";
    const double least = std::cbrt(5.0 * (l / h) / kMaxMeshCondition);
    throw InputError(key + ": its node makes an element of " + significant(len / l, 2) + " l between x/l = " +
                     significant(mesh.x[static_cast<std::size_t>(shortest)] / l, 9) + " and " +
                     significant(mesh.x[static_cast<std::size_t>(shortest) + 1] / l, 9) +
                     ", too short for double precision (stiffness condition about " + significant(condition, 2) +
                     ", at most " + significant(kMaxMeshCondition, 2) + "): keep supports at least " + significant(least, 2) +
                     " l from an end and from each other, or at the same place");
}

}  // namespace

Mesh build_mesh(const Beam& beam, const std::vector<Support>& supports) {
    if (beam.elements < 1) throw std::invalid_argument("build_mesh: at least one element is needed");
    const double l = beam.length;
    const int m = beam.elements;
    const double h = l / m;
    Mesh mesh;
    mesh.x.reserve(static_cast<std::size_t>(m) + 1 + supports.size());
    for (int i = 0; i <= m; ++i) mesh.x.push_back(l * static_cast<double>(i) / m);
    mesh.x.back() = l;

    // A support near an interior grid node takes that node (moved by under kNodeMoveFraction h)
    // rather than a new one beside it: the sliver element would stiffen the system by (h / sliver)^3
    // and cost both solvers digits. Each grid node serves one support.
    const double merge = kNodeMergeTolerance * h;
    std::vector<bool> taken(static_cast<std::size_t>(m) + 1, false);
    std::vector<double> insert;
    // The supports' places, then the section boundaries inside the beam: each needs a node.
    std::vector<double> places;
    for (const Support& s : supports) places.push_back(s.position * l);
    for (std::size_t k = 1; k < beam.sections.size(); ++k) places.push_back(beam.sections[k].from * l);
    for (const double x0 : places) {
        const int j = std::clamp(static_cast<int>(std::lround(x0 / h)), 0, m);
        const double gap = std::abs(x0 - mesh.x[static_cast<std::size_t>(j)]);
        if (gap <= merge) {
            taken[static_cast<std::size_t>(j)] = true;
        } else if (gap < kNodeMoveFraction * h && j > 0 && j < m && !taken[static_cast<std::size_t>(j)]) {
            mesh.x[static_cast<std::size_t>(j)] = x0;
            taken[static_cast<std::size_t>(j)] = true;
        } else {
            insert.push_back(x0);
        }
    }
    for (const double x0 : insert) {
        auto it = std::lower_bound(mesh.x.begin(), mesh.x.end(), x0);
        const bool near_next = it != mesh.x.end() && std::abs(*it - x0) <= merge;
        const bool near_prev = it != mesh.x.begin() && std::abs(*(it - 1) - x0) <= merge;
        if (!near_next && !near_prev) mesh.x.insert(it, x0);
    }
    if (!std::is_sorted(mesh.x.begin(), mesh.x.end())) throw std::logic_error("build_mesh: nodes out of order");
    for (const Support& s : supports) {
        const double x0 = s.position * l;
        auto it = std::lower_bound(mesh.x.begin(), mesh.x.end(), x0 - merge);
        mesh.support_nodes.push_back(static_cast<int>(it - mesh.x.begin()));
    }
    check_shortest_element(mesh, beam);
    return mesh;
}

ElementPoint locate(const Mesh& mesh, double x) {
    const int ne = mesh.element_count();
    auto it = std::upper_bound(mesh.x.begin(), mesh.x.end(), x);
    int e = static_cast<int>(it - mesh.x.begin()) - 1;
    e = std::clamp(e, 0, ne - 1);
    const double xi = (x - mesh.x[e]) / mesh.element_length(e);
    return {e, std::clamp(xi, 0.0, 1.0)};
}

}  // namespace vi
