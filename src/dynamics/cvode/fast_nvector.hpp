#pragma once
// A serial N_Vector whose kernels are compiled with the project (optimised). Debian's SUNDIALS 6.4.1
// ships its serial vector kernels built without optimisation (-O0: objdump shows every loop
// variable kept on the stack), and on the beam's small systems CVODE spends most of its time in
// them. The vector is an ordinary NVECTOR_SERIAL (same content, same N_VGetArrayPointer); only the
// operations CVODE calls are replaced, through the documented N_Vector ops table, and clones
// inherit them (N_VCloneEmpty copies the ops).

#include <nvector/nvector_serial.h>

namespace vi::cvode_detail {

// A new serial vector of length n with the project's kernels (fused operations enabled).
N_Vector new_fast_vector(sunindextype n, SUNContext ctx);

}  // namespace vi::cvode_detail
