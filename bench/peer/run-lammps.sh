#!/usr/bin/env bash
# Time the LAMMPS peer on the standard DPD benchmark (bench/peer/in.dpd).
# Usage: bench/peer/run-lammps.sh L N THREADS
# env IN: the input in bench/peer (default in.dpd; in.dpd-ext: the mai-duy-2019 solvent)
#   L        box side (N_particles = round(3 L^3); L=20 -> 24000)
#   N        timed steps (after EQ equilibration steps, env EQ, default 1000)
#   THREADS  OpenMP threads; >1 uses the OPENMP package (-sf omp -pk omp T),
#            1 runs the plain (non-omp) styles unless LMP_SUFFIX=omp is set.
# Prints one line:  lammps<TAB>N_particles<TAB>threads<TAB>particle_steps_per_second
# The full LAMMPS output goes to build/peer/logs/.
set -euo pipefail

if [ $# -ne 3 ]; then
    echo "usage: $0 L N THREADS" >&2; exit 2
fi
L="$1"; N="$2"; T="$3"
EQ="${EQ:-1000}"

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
LMP="${LMP:-$ROOT/build/peer/lmp}"
if ! [ -x "$LMP" ]; then
    echo "run-lammps: $LMP missing; run bench/peer/build-lammps.sh first" >&2; exit 1
fi

LOGDIR="$ROOT/build/peer/logs"
mkdir -p "$LOGDIR"

IN="${IN:-in.dpd}"
ARGS=(-in "$HERE/$IN" -log none -nocite
      -var L "$L" -var N "$N" -var EQ "$EQ")
if [ "$T" -gt 1 ] || [ "${LMP_SUFFIX:-}" = omp ]; then
    ARGS+=(-sf omp -pk omp "$T")
    OUT="$LOGDIR/${IN#in.}-L${L}-N${N}-T${T}-omp.out"
else
    OUT="$LOGDIR/${IN#in.}-L${L}-N${N}-T${T}-plain.out"
fi

OMP_NUM_THREADS="$T" OMP_PROC_BIND="${OMP_PROC_BIND:-false}" \
    "$LMP" "${ARGS[@]}" > "$OUT" 2>&1 || {
    echo "run-lammps: lmp failed, see $OUT" >&2; tail -n 20 "$OUT" >&2; exit 1; }

# Last "Loop time of X on P procs for N steps with M atoms" = the timed run.
line="$(grep -E '^Loop time of ' "$OUT" | tail -n 1)"
[ -n "$line" ] || { echo "run-lammps: no Loop time line in $OUT" >&2; exit 1; }
read -r secs steps atoms < <(awk '{print $4, $9, $12}' <<<"$line")
[ "$steps" = "$N" ] || { echo "run-lammps: timed run has $steps steps, expected $N" >&2; exit 1; }
pss="$(awk -v s="$secs" -v n="$steps" -v m="$atoms" 'BEGIN{printf "%.4g", m*n/s}')"
printf 'lammps\t%s\t%s\t%s\n' "$atoms" "$T" "$pss"
