#!/usr/bin/env bash
# Instructions per simulated second of one kernel scene, native code (NativeAOT) under callgrind.
#   bash "Tools~/Kernels/count.sh" SCENE [SHORT LONG] [--annotate]
# KERNELS_ISA=x86-64-v3 publishes for AVX2 (Vector<double> of 4 lanes, as the JIT uses on these machines); unset, the
# NativeAOT default (x86-64-v2: 128-bit vectors), which every count recorded before 2026-12-02 used.
# KERNELS_VECTORS=off runs the scalar paths (VectorPath off, as where Vector.IsHardwareAccelerated is false).
# Publishes the probe ahead-of-time (once per call), strips its DWARF (valgrind cannot read the DWARF 5 the AOT
# toolchain writes), runs `run SCENE SHORT` and `run SCENE LONG` under callgrind and prints
# (Ir_long − Ir_short) · 90 / (LONG − SHORT): start-up and scene building cancel; for the 16-segment chains also the
# ratio against the peer kernel's 2.1 M. With --annotate, prints the
# per-function profile of the long run (inclusive of nothing: self instructions per function).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
scene="${1:?scene name}"; short="${2:-20}"; long="${3:-200}"; annotate="${4:-}"
out="${KERNELS_OUT:-/tmp/hookerope-kernels-$(id -u)}"
isa=()
if [ -n "${KERNELS_ISA:-}" ]; then isa=("-p:IlcInstructionSet=$KERNELS_ISA"); fi
# KERNELS_REUSE=1 counts with the probe an earlier call left in $KERNELS_OUT (kernel-count.sh: one publish for its scenes)
if [ "${KERNELS_REUSE:-}" != 1 ] || [ ! -x "$out/probe" ]; then
  dotnet publish "$here/HookeRope.Kernels.csproj" -c Release -r linux-x64 -o "$out/publish" -nologo -v quiet "${isa[@]}" >/dev/null
  objcopy --strip-debug "$out/publish/HookeRope.Kernels" "$out/probe"
fi
count() {
  valgrind --tool=callgrind --callgrind-out-file="$out/cg.$1" "$out/probe" run "$scene" "$1" 2>&1 >/dev/null | sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
a=$(count "$short"); b=$(count "$long")
# the 16-segment chains are the peer comparison (issue 18 item 1): PositionBasedDynamics' solve_DistanceConstraint at
# 8 substeps × 1 iteration, 2.1 M instructions per simulated second by the issue's figure; the target is ≤ 1.2× that
awk -v a="$a" -v b="$b" -v s="$short" -v l="$long" -v name="$scene" \
  'BEGIN { m = (b-a)*90/(l-s)/1e6; printf "%s: %.0f instructions per host step, %.3f M per simulated second (90 steps)\n", name, (b-a)/(l-s), m
           if (name ~ /chain16$/) printf "%s: %.2f x the peer (2.1 M per simulated second; target <= 1.2 x = 2.52 M)\n", name, m/2.1 }'
if [ "$annotate" = "--annotate" ]; then
  callgrind_annotate --threshold=99 "$out/cg.$long" | sed -n '1,60p'
fi
