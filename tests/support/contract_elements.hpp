#pragma once
// The elements the force-element contract (tests/force_elements_test.cpp) checks. A test file adds
// samples of its own element with add_contract_element at static initialisation, naming the family
// (ElementFamily::name) that makes such elements; the contract test checks each sample and fails
// for a registered family (problem/element_families.cpp) without one.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "forces/force_element.hpp"

namespace vi::test {

struct ContractElement {
    std::string label;
    std::string family;                      // ElementFamily::name of the family that makes it
    std::function<ForceElementPtr()> make;
    bool linear = true;     // has a LinearForm (else the exact solver refuses it)
    bool potential = true;  // its force at rest is minus the gradient of its stored energy (not a prescribed load)
};

inline std::vector<ContractElement>& contract_elements() {
    static std::vector<ContractElement> all;
    return all;
}

// Adds e to the samples; returns true, for a namespace-scope `const bool` that runs it.
inline bool add_contract_element(ContractElement e) {
    contract_elements().push_back(std::move(e));
    return true;
}

}  // namespace vi::test
