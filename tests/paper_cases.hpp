#pragma once
// Cases built in code for tests: the library's reference problems under the tests' namespace.

#include "validation/reference_problems.hpp"

namespace vi::test {

using vi::clamped_clamped;
using vi::paper_cantilever;

}  // namespace vi::test
