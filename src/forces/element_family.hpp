#pragma once
// ElementFamily: one kind of force element a case describes (the supports' contacts, the point
// loads, the electrodes' pads, ...), as a small object that makes its elements from the Case. The
// model builder (problem/beam_model.cpp) loops over the registered families
// (problem/element_families.cpp) and adds what each makes, in the registry's order. The keys a
// family reads are described once in the case schema (model/case_schema.hpp: a built-in section, or
// keys the family registers from its own file with register_section / register_keys).

#include <Eigen/Dense>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "fem/system.hpp"
#include "forces/force_element.hpp"
#include "model/case.hpp"

namespace vi {

// What a family reads to make its elements.
struct ElementSource {
    const Case& c;
    const System& system;                      // the beam without supports
    const std::vector<int>& bending_position;  // each reduced DOF's index among the bending DOFs, -1 if axial
    const Eigen::VectorXd& first_mode;         // the first unsupported bending mode over the bending DOFs (M-normalised)
};

// Where in the case an element comes from: a table and the index of its entry ("electrodes", 1 for
// electrodes[1].dielectric; index 0 for a table that is not an array, "beam").
struct CaseEntry {
    std::string_view table;
    std::size_t index = 0;
};

// An element a family made, and its entry.
struct FamilyElement {
    ForceElementPtr element;
    CaseEntry entry;
};

class ElementFamily {
public:
    virtual ~ElementFamily() = default;
    // What it makes, for messages: "support contacts", "squeeze films".
    [[nodiscard]] virtual std::string_view name() const = 0;
    // Its elements for source.c, in case order, each named by its case key ("supports[0]",
    // "electrodes[1].dielectric"). Throws InputError naming the key a case gives that the model
    // cannot have (a support on a node an end condition holds).
    [[nodiscard]] virtual std::vector<FamilyElement> elements(const ElementSource& source) const = 0;
    // Registers the case keys it reads that are not built in (register_section, register_keys),
    // for the program's life; called once, before the first case is read.
    virtual void register_case_keys() const {}
    // One item of the validation report's list of checks that run in the test suite
    // (docs/validation.md, "Validated in the test suite"): its test file, the closed forms it checks
    // and their sources, in Markdown without the leading "- "; empty: the list names it already.
    [[nodiscard]] virtual std::string validation() const { return {}; }
};

}  // namespace vi
