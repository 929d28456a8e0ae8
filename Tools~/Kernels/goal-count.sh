#!/usr/bin/env bash
# Instructions of issue 18's goal frame, native code (NativeAOT) under callgrind, by count.sh's method.
#   bash "Tools~/Kernels/goal-count.sh" [ROPES]        (default 100; KERNELS_OUT, KERNELS_ISA as for count.sh; KERNELS_VECTORS=off: scalar paths)
# Counts the scene goal-world:ROPES (ROPES lanyards x 64 segments + 16-sided tube meshes in one RopeWorld on 1 worker,
# Tools~/Bench/GoalScene.cs) and goal-step:ROPES (the same frames without the mesh fills) with count.sh, 0 against
# WINDOW frames after the bench's warm-up (the frames the bench's goal rows time: GoalScene.WindowFrames), so
# building, warm-up and start-up cancel. Prints instructions per frame, per segment-substep (step + mesh; step alone)
# and per tube vertex (mesh = goal-world - goal-step), and writes them to $KERNELS_OUT/goal-count.txt with the commit
# (and a hash of uncommitted changes) they were counted at: `bench goal` shows them for the rows of that
# configuration while the tree is unchanged. Takes 2-4 minutes for 100 ropes (two publishes, four callgrind runs).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
ropes="${1:-100}"
out="${KERNELS_OUT:-/tmp/hookerope-kernels-$(id -u)}"
mkdir -p "$out"
window=$(sed -n 's/.*public const int WindowFrames = \([0-9]*\);.*/\1/p' "$here/../Bench/GoalScene.cs")
[ -n "$window" ] || { echo "goal-count.sh: WindowFrames not found in Tools~/Bench/GoalScene.cs" >&2; exit 1; }
root="$(cd "$here/../.." && pwd)"
# what the count depends on: the core, the probe and the scene, committed (tree hashes) and uncommitted (diff), taken
# before the publishes (do not edit those files while the script runs)
paths=(Runtime/Core Tools~/Kernels Tools~/Bench/GoalScene.cs)
commit=$(git -C "$root" rev-parse HEAD)
code=$(git -C "$root" rev-parse "${paths[@]/#/HEAD:}" | sha1sum | cut -c1-12)
changes=$(git -C "$root" diff HEAD -- "${paths[@]}" | sha1sum | cut -c1-12)
per_frame() { bash "$here/count.sh" "$1" 0 "$window" | sed -n 's/.*: \([0-9]*\) instructions per host step.*/\1/p'; }
world=$(per_frame "goal-world:$ropes")
step=$(per_frame "goal-step:$ropes")
# the probe count.sh left behind: the window's work units and vertices (native run, no valgrind)
line=$("$out/probe" run "goal-world:$ropes" "$window")
units=$(echo "$line" | sed -n 's/.* units \([0-9]*\) .*/\1/p')
vertices=$(echo "$line" | sed -n 's/.* vertices \([0-9]*\).*/\1/p')
frames=$(echo "$line" | sed -n 's/.* frames \([0-9]*-[0-9]*\):.*/\1/p')
isa="${KERNELS_ISA:-default}"
# KERNELS_VECTORS=off counts the scalar paths (VectorPath off): a source of its own, never compared with the lanes'
if [ "${KERNELS_VECTORS:-on}" = off ]; then isa="$isa-scalar"; fi
file="$out/goal-count.txt"
awk -v w="$world" -v s="$step" -v u="$units" -v v="$vertices" -v n="$window" -v r="$ropes" -v fr="$frames" \
    -v c="$commit" -v k="$code" -v d="$changes" -v i="$isa" 'BEGIN {
  upf = u / n; vpf = v / n; mesh = w - s
  printf "commit=%s\ncode=%s\nchanges=%s\nisa=%s\nropes=%d\nsegments=64\nwindow=%s\n", c, k, d, i, r, fr
  printf "instructions_per_frame=%.0f\nstep_instructions_per_frame=%.0f\nmesh_instructions_per_frame=%.0f\n", w, s, mesh
  printf "units_per_frame=%.0f\nvertices_per_frame=%.0f\n", upf, vpf
  printf "instructions_per_unit=%.3f\nstep_instructions_per_unit=%.3f\nmesh_instructions_per_vertex=%.3f\n", w / upf, s / upf, mesh / vpf
}' > "$file"
awk -F= -v r="$ropes" -v fr="$frames" -v i="$isa" '
  { v[$1] = $2 }
  END { printf "goal %d x 64 + 16-sided mesh, frames %s, 1 worker, ISA %s: %.0f instructions per frame = step %.0f (%.1f per segment-substep) + mesh %.0f (%.1f per vertex, %.0f vertices per frame); %.1f per segment-substep in all\n",
          r, fr, i, v["instructions_per_frame"], v["step_instructions_per_frame"], v["step_instructions_per_unit"],
          v["mesh_instructions_per_frame"], v["mesh_instructions_per_vertex"], v["vertices_per_frame"], v["instructions_per_unit"] }' "$file"
echo "written: $file"
