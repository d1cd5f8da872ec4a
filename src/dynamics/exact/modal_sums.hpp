#pragma once
// Sums over the modes in plain loops built for several vector widths, rounding alike on every
// processor: a piece's end state x = sum_k Re(w_k [v_k; lambda_k v_k]) (StateModes::state) and the
// history's channels over a run of samples (PieceSolution::sample_many).

namespace vi {

// For each of the `count` columns j: head += wr_j vr_j - wi_j vi_j and tail += lr_j vr_j - li_j vi_j
// over n rows, with vr_j = vr + col[j] * ld (likewise vi_j) and coef[4 j .. 4 j + 3] = {wr, wi, lr, li}.
// Each entry rounds as head[i] + (wr vr[i] - wi vi[i]) in that order, on every processor.
void add_mode_columns(const double* vr, const double* vi, long ld, int n, const int* col, const double* coef,
                      int count, double* head, double* tail);

// The history's channels over a run of S samples: for each of the nl live modes l (mode live[l]) in
// order, acc[j S + s] += ar_j er[l S + s] - ai_j ei[l S + s] for the nf channels j (acc's nf S
// entries set to 0 first), where
// ar_j = pack[2 nf k + j] and ai_j = pack[2 nf k + nf + j] for k = live[l]: each sum formed in mode order,
// as one sample at a time forms it.
void add_channel_runs(const double* pack, int nf, const int* live, int nl, const double* er, const double* ei, int S,
                      double* acc);

}  // namespace vi
