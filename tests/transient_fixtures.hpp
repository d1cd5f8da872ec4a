#pragma once
// Small transient problems built directly (without a case file) for solver tests.

#include "validation/reference_problems.hpp"
#include "paper_cases.hpp"

namespace vi::test {

using vi::cantilever_drop;
using vi::single_dof_drop;

}  // namespace vi::test
