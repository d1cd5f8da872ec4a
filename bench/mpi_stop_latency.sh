#!/usr/bin/env bash
# How long mpirun takes to end after its own SIGTERM or SIGINT while a sweep point runs
# (docs/sweeps.md, "MPI"): prints one line per run, "SIGNAL seconds-after-the-signal resume-line-seen",
# then the count, the range and the runs slower than 0.5 s.
#   bash bench/mpi_stop_latency.sh [VIBROIMPACT] [ROUNDS]   (each round: one SIGTERM run, one SIGINT run)
set -euo pipefail
bin=${1:-build/apps/vibroimpact}
rounds=${2:-150}
bin=$(realpath "$bin")
case_dir=$(dirname "$(realpath "$0")")/../examples/paper
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# The stop tests' case: the free-impact example at m = 10, contact undamped. The last grid point
# (horizon 2 s; it takes about 0.35 s of wall time) is still running when the signal comes, and the
# third column says the stop reached it (the resume line was printed).
sed -e 's/elements = 50/elements = 10/' -e 's/horizon = "150 us"/horizon = "40 us"/' \
    -e 's/damping_ratio = 0.2/damping_ratio = 0.0/' "$case_dir/free_impact_tip.toml" > case.toml
for ((i = 0; i < rounds; ++i)); do
  for sig in TERM INT; do
    rm -rf out
    mpirun --allow-run-as-root --oversubscribe -n 2 "$bin" sweep case.toml \
      --set 'solver.horizon=4e-5,4.5e-5,5e-5,5.5e-5,6e-5,2.0' --threads 1 --point-timeout 0 --out out \
      >/dev/null 2>err.txt &
    pid=$!
    # Bounded wait (30 s) for the five fast points in the journal.
    for ((k = 0; k < 3000; ++k)); do
      if [ -f out/sweep.journal ] && [ "$(wc -l < out/sweep.journal)" -ge 9 ]; then break; fi
      sleep 0.01
    done
    t0=$(date +%s.%N)
    kill -"$sig" "$pid"
    wait "$pid" || true
    t1=$(date +%s.%N)
    echo "$sig $(echo "$t1 - $t0" | bc) $(grep -c 'sweep interrupted' err.txt || true)"
  done
done | tee runs.txt
awk '{print $2}' runs.txt | sort -n | awk '{a[NR] = $1} END {print "runs", NR, "fastest", a[1], "s, slowest", a[NR], "s"}'
awk '$2 > 0.5 {n++} END {print n + 0, "runs slower than 0.5 s"}' runs.txt
