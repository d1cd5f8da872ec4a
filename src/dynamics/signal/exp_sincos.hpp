#pragma once
// exp(x) and (cos, sin)(y) over arrays, in plain arithmetic the compiler can vectorise: the modal
// exponentials of the signal scans (every live mode at each evaluation point) and of the exact
// solver's pieces (every mode at a piece's end and at the history's anchors); and the scans' death
// times of their modes.

namespace vi {

// For k < n: e[k] = exp(x[k]), c[k] = cos(y[k]), s[k] = sin(y[k]). Each to within 4 ulps of the
// exact value (relative for exp; for cos and sin relative to 1, the size of the pair), which the
// scans' rounding bounds allow per term (signal_scan.hpp). x below -707 gives 1e-307 (the scans'
// floor for an exponential); x above 700 or |y| above 1e5 is handed to the C library.
void exp_sincos(const double* x, const double* y, double* e, double* c, double* s, int n);

// For k < n, the time from which amp[k] e^(re[k] t) <= skip for good: ln(amp / skip) / -re bounded
// above by the exponent e of amp / skip (amp / skip = f 2^e, 1/2 <= f < 1) as e ln 2 / -re, never
// early. Infinite where re > 0 (an undamped mode's roundoff may grow), else 0 where amp <= skip, else
// infinite where re is not negative. The same values as with std::frexp of the quotient, to the last
// bit. skip must be a positive normal number, amp finite and non-negative.
void death_times(const double* re, const double* amp, double skip, int n, double* dead);

}  // namespace vi
