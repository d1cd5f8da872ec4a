#!/usr/bin/env bash
# The work (instructions counted by callgrind inside solve_cvode, a figure the machine's load does
# not change) of the two switching transients whose speed docs/squeeze-film.md §6 and
# docs/electrostatics.md §9 compare between builds:
#   film: the cantilever switch in air at 1 kPa, 50 us, m = 50, full model (cantilever_switch_air.toml);
#   red8: the cantilever switch at 1.2 V_PI (70.0989 V), reduced_modes = 8, rtol = 1e-6.
# Both through `vibroimpact simulate` (history and energy on). And, counted inside trace_pullin,
#   pullin: `vibroimpact pullin` of the cantilever switch (m = 50, 16 frequency points).
# And, counted inside the exact solver (solve_exact), the paper's free impact
# (examples/paper/free_impact_tip.toml, m = 50) through its T_p of 68.6443 us as a sweep point runs
# it (no sampled history, no energy ledger):
#   exact_cold: one run, the first on its thread;
#   exact_warm: a second run of the same case on the same thread (the decomposed contact states of
#               the first are taken again, as by the points of a sweep that keep the beam).
# Run it once per build to compare:
#   bash bench/callgrind_work.sh [VIBROIMPACT]      (needs valgrind; about two minutes)
set -euo pipefail
bin=$(realpath "${1:-build/apps/vibroimpact}")
examples=$(dirname "$(realpath "$0")")/../examples/switch
paper=$(dirname "$(realpath "$0")")/../examples/paper
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
sed -e 's/^pressure = .*/pressure = "1000 Pa"/' "$examples/cantilever_switch_air.toml" > film.toml
sed -e 's/^rtol = 1e-8/rtol = 1e-6\nreduced_modes = 8/' -e 's/^voltage = .*/voltage = "70.0989 V"/' \
    "$examples/cantilever_switch.toml" > red8.toml
for c in film red8; do
  valgrind --tool=callgrind --callgrind-out-file="$c.out" --toggle-collect='vi::solve_cvode*' \
      "$bin" simulate "$c.toml" > /dev/null 2> "$c.err"
  echo "$c $(grep -o 'Collected : [0-9]*' "$c.err" | grep -o '[0-9]*$') instructions"
done
valgrind --tool=callgrind --callgrind-out-file=pullin.out --toggle-collect='vi::trace_pullin(vi::PullinModel const&, vi::PullinOptions const&)' \
    "$bin" pullin "$examples/cantilever_switch.toml" --out pullin > /dev/null 2> pullin.err
echo "pullin $(grep -o 'Collected : [0-9]*' pullin.err | grep -o '[0-9]*$') instructions"
exact_work() {  # label, --set value of solver.horizon (one value per run)
  valgrind --tool=callgrind --callgrind-out-file="$1.out" \
      --toggle-collect='vi::solve_exact(vi::PiecewiseLinearProblem const&, vi::TransientOptions const&, vi::ExactOptions const&)' \
      "$bin" sweep "$paper/free_impact_tip.toml" --set "solver.horizon=$2" --threads 1 --out "$1" > /dev/null 2> "$1.err"
  grep -o 'Collected : [0-9]*' "$1.err" | grep -o '[0-9]*$'
}
one=$(exact_work exact1 68.6443e-6)
two=$(exact_work exact2 68.6443e-6,68.6443e-6)
echo "exact_cold $one instructions"
echo "exact_warm $((two - one)) instructions"
