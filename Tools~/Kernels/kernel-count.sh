#!/usr/bin/env bash
# Instructions of the kernels issue 18 item 1 sets targets for, native code (NativeAOT) under callgrind, by count.sh's
# method; `bench goal` prints them against the issue's figures.
#   bash "Tools~/Kernels/kernel-count.sh"        (KERNELS_OUT, KERNELS_ISA, KERNELS_VECTORS as for count.sh)
# Counts gs-be-chain16 (the default Gauss–Seidel kernel on the peer comparison's 16-segment chain, 8 substeps × 1
# iteration) and gs-fast-chain16 (the same chain on the opt-in fused single-precision kernel), in instructions per
# simulated second, and exact-rest:256 / exact-rest:10000 (the exact solve on a hanging rope at its static equilibrium,
# one linear solve per iteration), in instructions per segment-substep; writes them to $KERNELS_OUT/kernel-count.txt
# with the commit and the hashes of the code counted (the same paths as goal-count.sh, so `bench goal` shows them only
# while that code is unchanged). One publish, eight callgrind runs: about 2 minutes.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out="${KERNELS_OUT:-/tmp/hookerope-kernels-$(id -u)}"
mkdir -p "$out"
root="$(cd "$here/../.." && pwd)"
paths=(Runtime/Core Tools~/Kernels Tools~/Bench/GoalScene.cs)
commit=$(git -C "$root" rev-parse HEAD)
code=$(git -C "$root" rev-parse "${paths[@]/#/HEAD:}" | sha1sum | cut -c1-12)
changes=$(git -C "$root" diff HEAD -- "${paths[@]}" | sha1sum | cut -c1-12)
# instructions per host step of scene $1 between $2 and $3 host steps; the first call publishes, the others reuse its probe
reuse=0
per_step() {
  KERNELS_REUSE=$reuse bash "$here/count.sh" "$1" "$2" "$3" | sed -n 's/.*: \([0-9]*\) instructions per host step.*/\1/p'
}
gs=$(per_step gs-be-chain16 20 200)
reuse=1
fast=$(per_step gs-fast-chain16 20 200)
rest256=$(per_step exact-rest:256 10 30)
rest10k=$(per_step exact-rest:10000 2 4)
isa="${KERNELS_ISA:-default}"
if [ "${KERNELS_VECTORS:-on}" = off ]; then isa="$isa-scalar"; fi
file="$out/kernel-count.txt"
awk -v g="$gs" -v f="$fast" -v a="$rest256" -v b="$rest10k" -v c="$commit" -v k="$code" -v d="$changes" -v i="$isa" 'BEGIN {
  printf "commit=%s\ncode=%s\nchanges=%s\nisa=%s\n", c, k, d, i
  printf "gs_be_chain16_per_simulated_second=%.0f\ngs_fast_chain16_per_simulated_second=%.0f\n", g * 90, f * 90
  printf "exact_rest_256_per_segment_substep=%.3f\nexact_rest_10000_per_segment_substep=%.3f\n", a / (256 * 8), b / (10000 * 8)
}' > "$file"
cat "$file"
echo "written: $file"
