#!/bin/bash
# Robustness sweep of the Ricci flow (run by hand, never in CI): every scheme on 3 mesh shapes
# x 4 jitters x 5 seeds x 2 sizes (720 disk maps), counting the failures per scheme.
#   tools/bench/flow_sweep.sh [build/confvis_bench_flow] [schemes, default all]
set -euo pipefail
bench=${1:-build/confvis_bench_flow}
schemes=${2:-all}
results=$(mktemp)
for size in 300 1500; do for mesh in lopsided round hemisphere; do
  for jitter in 0.1 0.2 0.3 0.4; do for seed in 1 2 3 4 5; do
    "$bench" --sizes $size --schemes "$schemes" --repeat 1 --mesh $mesh --jitter $jitter \
      --seed $seed 2>/dev/null | grep '^| [0-9]' | grep -v LDLT | sed "s/^/$mesh $jitter $seed /"
  done; done
done; done > "$results"
echo "runs: $(wc -l < "$results")  failed: $(grep -c failed "$results" || true)"
grep failed "$results" | cut -c1-160 || true
# Mean Newton steps per scheme over the converged maps (fields: mesh jitter seed | vertices |
# route | scheme | iterations | ...).
grep -v failed "$results" | awk -F'|' '{ s = $4; gsub(/ /, "", s); n[s]++; it[s] += $5 }
  END { for (s in n) printf "%s %.2f (%d maps)  ", s, it[s] / n[s], n[s]; print "" }'
rm -f "$results"
