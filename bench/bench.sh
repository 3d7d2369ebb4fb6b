#!/usr/bin/env bash
# make bench: particle-steps per second of the standard DPD system on 1 and 2
# threads, for 3e3, 2.4e4 and 1e6 particles, and peak memory per particle; the
# cost of the rotating-particle terms (Pan 2008); the overdamped solvers; what
# unused modules cost (bin/dpd against the bare build, build/dpd-bare).
# With PEER=1 (make bench-peer) LAMMPS runs the same system in the same session,
# interleaved with ours, and the ratios are printed. Timing is of the production
# steps only, after equilibration. Machines are noisy: compare ratios of runs
# made side by side, not absolute numbers across sessions.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
out=build/bench; mkdir -p "$out"
DPD=bin/dpd
REPEAT=${REPEAT:-3}          # best of REPEAT for each configuration
# side -> particles: round(3 L^3); 10 -> 3000, 20 -> 24000, 69.336 -> 1e6
SIZES=${SIZES:-"10 20 69.336"}
steps_for() { case $1 in 10) echo 3000;; 20) echo 1000;; *) echo 100;; esac; }
# equilibration: at least 3 time units at every size, so the production steps
# of every size run at kBT = 1 (with 50 steps, 1e6 particles were still at
# T = 1.3 and rebuilt their neighbour list 30 % more often)
eq_for() { case $1 in 10) echo 500;; *) echo 300;; esac; }

bench_run() {  # L threads DIR: the standard system of side L, timed
    "$DPD" run bench/standard.cfg --out "$3" --threads "$2" --quiet \
        --set "box=[$1,$1,$1]" --set steps=$(steps_for "$1") --set equilibration=$(eq_for "$1") >/dev/null
}
val() { awk -F'\t' -v q="$2" '$1==q{print $2}' "$1/summary.tsv"; }   # DIR QUANTITY
max() { awk -v a="$1" -v b="$2" 'BEGIN{print (b > a) ? b : a}'; }

peer_once() {  # L threads -> rate of one LAMMPS run
    EQ=$(eq_for "$1") bench/peer/run-lammps.sh "$1" $(steps_for "$1") "$2" | cut -f4
}
# median of the numbers on stdin (one per line)
median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
range() { sort -g | awk 'NR == 1 { lo = $1 } { hi = $1 } END { printf "%.2f-%.2f", lo, hi }'; }
# the commit of the tsv files, "-dirty" if the sources differ from it; the bench's own tsv files,
# rewritten section by section, do not count (they made every section after the first "dirty")
stamp() {
    local c
    c=$(git describe --always 2>/dev/null || echo unknown)
    git diff --quiet HEAD -- . ':(exclude)bench/*.tsv' 2>/dev/null || c+=-dirty
    echo "$c"
}

# The machine's own ceiling for 2 threads: two independent one-thread runs at
# once (no shared data, no barriers), aggregate rate over the rate of one run
# alone. A 2-thread speed-up can approach this number, not exceed it; on a
# virtual machine whose two vCPUs share a physical core it is well below 2.
pair_of_runs() {  # L -> best aggregate rate of two concurrent one-thread runs
    local L=$1 best=0
    for k in $(seq "$REPEAT"); do
        bench_run "$L" 1 "$out/dpd-$L-pair-a" & bench_run "$L" 1 "$out/dpd-$L-pair-b" & wait
        best=$(max "$best" "$(awk -v a="$(val "$out/dpd-$L-pair-a" production_particle_steps_per_second)" \
            -v b="$(val "$out/dpd-$L-pair-b" production_particle_steps_per_second)" 'BEGIN{print a + b}')")
    done
    echo "$best"
}

# STANDARD=0 skips this section (the standard system: rates, speed-up, PASSIVE, ceiling, flatness)
if [ "${STANDARD:-1}" = 1 ]; then
if [ "${PEER:-0}" = 1 ]; then bash bench/peer/build-lammps.sh >/dev/null; fi
printf '%-10s %-8s %14s %14s %12s %10s %8s %16s\n' particles threads "dpd [ps/s]" "lammps [ps/s]" "dpd/lammps" "B/particle" "T" "dpd [ps/cpu-s]"
# The host's speed drifts by tens of per cent within minutes, so the 1 -> 2
# thread speed-up is taken from alternating pairs (a 1-thread run, then a
# 2-thread run, and LAMMPS's pair right after with PEER=1): the median of the
# REPEAT pairs' ratios. The table shows the best rate of each configuration.
declare -A rate crate pairs ppairs
for L in $SIZES; do
    n=$(awk -v L="$L" 'BEGIN{printf "%d", 3*L*L*L + 0.5}')
    declare -A prate=([1]=0 [2]=0) mem temp
    rate[$L,1]=0; rate[$L,2]=0; crate[$L,1]=0; crate[$L,2]=0; pairs[$L]=""; ppairs[$L]=""
    for k in $(seq "$REPEAT"); do
        declare -A this=() pthis=()
        for T in 1 2; do
            d="$out/dpd-$L-$T"
            bench_run "$L" "$T" "$d"
            this[$T]=$(val "$d" production_particle_steps_per_second)
            rate[$L,$T]=$(max "${rate[$L,$T]}" "${this[$T]}")
            crate[$L,$T]=$(max "${crate[$L,$T]}" "$(val "$d" production_particle_steps_per_second_cpu)")
            mem[$T]=$(val "$d" peak_memory_bytes_per_particle); temp[$T]=$(val "$d" temperature)
        done
        pairs[$L]+="$(awk -v a="${this[1]}" -v b="${this[2]}" 'BEGIN{print b/a}') "
        if [ "${PEER:-0}" = 1 ]; then
            for T in 1 2; do pthis[$T]=$(peer_once "$L" "$T"); prate[$T]=$(max "${prate[$T]}" "${pthis[$T]}"); done
            ppairs[$L]+="$(awk -v a="${pthis[1]}" -v b="${pthis[2]}" 'BEGIN{print b/a}') "
        fi
    done
    for T in 1 2; do
        if [ "${PEER:-0}" = 1 ]; then
            p=${prate[$T]}; ratio=$(awk -v a="${rate[$L,$T]}" -v b="$p" 'BEGIN{printf "%.2f", a/b}')
        else p="-"; ratio="-"; fi
        printf '%-10s %-8s %14.4g %14s %12s %10.0f %8.3f %16.4g\n' "$n" "$T" "${rate[$L,$T]}" "$p" "$ratio" "${mem[$T]}" "${temp[$T]}" "${crate[$L,$T]}"
    done
done
echo
for L in $SIZES; do
    n=$(awk -v L="$L" 'BEGIN{printf "%d", 3*L*L*L + 0.5}')
    line=$(printf 'speed-up 1 -> 2 threads, %d particles: %.2f (median of %d alternating pairs, %s)' "$n" \
        "$(tr ' ' '\n' <<< "${pairs[$L]}" | grep . | median)" "$REPEAT" "$(tr ' ' '\n' <<< "${pairs[$L]}" | grep . | range)")
    if [ "${PEER:-0}" = 1 ]; then
        line+=$(printf '; LAMMPS %.2f (%s)' "$(tr ' ' '\n' <<< "${ppairs[$L]}" | grep . | median)" "$(tr ' ' '\n' <<< "${ppairs[$L]}" | grep . | range)")
    fi
    echo "$line"
done
fi   # STANDARD (rates)

# ---- threads under the harness's OpenMP settings (tools/lib/omp.sh: an idle thread spins
# GOMP_SPINCOUNT = 3000 iterations, then sleeps), against sleeping at once (OMP_WAIT_POLICY=PASSIVE)
# and libgomp's default spin (300000). Quiet machine: 10125 particles (L = 15), the 2-thread /
# 1-thread rate, median of REPEAT alternating pairs per policy (target, issue 22: >= 1.7 under
# the harness's settings). Busy machine: the same ratio at 3000 particles with BUSY_LOADS one-thread
# busy loops running beside it (default "2 6"); a ratio far below 1 is a collapse (the 2-thread
# run slower than one thread would be). THREADS=0 skips it; the results go to bench/threads.tsv.
if [ "${THREADS:-1}" = 1 ]; then
    . tools/lib/omp.sh
    thr_rate() {  # L threads steps ENV... -> production particle-steps per second
        local L=$1 t=$2 n=$3; shift 3
        env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT "$@" "$DPD" run bench/standard.cfg --out "$out/thr" --threads "$t" \
            --quiet --set "box=[$L,$L,$L]" --set steps="$n" --set equilibration=200 >/dev/null
        val "$out/thr" production_particle_steps_per_second
    }
    policies=("harness (GOMP_SPINCOUNT=3000)|GOMP_SPINCOUNT=3000" "OMP_WAIT_POLICY=PASSIVE|OMP_WAIT_POLICY=PASSIVE"
              "libgomp default spin (300000)|GOMP_SPINCOUNT=300000")
    thr_ratio() {  # L steps ENV -> median 2/1-thread ratio of REPEAT alternating pairs, and the range
        local L=$1 n=$2 e=$3 r="" a b
        for k in $(seq "$REPEAT"); do a=$(thr_rate "$L" 1 "$n" "$e"); b=$(thr_rate "$L" 2 "$n" "$e"); r+="$(awk -v a="$a" -v b="$b" 'BEGIN{print b/a}') "; done
        printf '%.2f\t%s\n' "$(printf '%s\n' $r | median)" "$(printf '%s\n' $r | range)"
    }
    { printf 'machine\tparticles\tpolicy\tratio_2_over_1_threads\trange\n'
      for p in "${policies[@]}"; do printf 'quiet\t10125\t%s\t%s\n' "${p%%|*}" "$(thr_ratio 15 600 "${p#*|}")"; done
      for N in ${BUSY_LOADS:-2 6}; do
          for i in $(seq "$N"); do ( while :; do :; done ) & done
          for p in "${policies[@]}"; do printf 'load %s\t3000\t%s\t%s\n' "$N" "${p%%|*}" "$(thr_ratio 10 1000 "${p#*|}")"; done
          kill $(jobs -p) 2>/dev/null; wait 2>/dev/null || true
      done
      printf 'date, commit\t%s\t%s\t\t\n' "$(date -u +%Y-%m-%d)" "$(stamp)"
    } > "$out/threads.tsv"
    cp "$out/threads.tsv" bench/threads.tsv
    echo
    echo "threads: 2-thread / 1-thread rate (median of $REPEAT alternating pairs; target >= 1.7 quiet, harness settings):"
    column -t -s $'\t' bench/threads.tsv
fi

if [ "${STANDARD:-1}" = 1 ]; then
if [ "${CEILING:-1}" = 1 ]; then
    for L in $SIZES; do
        pr=$(pair_of_runs "$L")
        awk -v L="$L" -v a="${rate[$L,1]}" -v b="${rate[$L,2]}" -v p="$pr" \
            'BEGIN{printf "ceiling (two 1-thread runs at once / one alone), %d particles: %.2f; 2-thread speed-up / ceiling: %.2f\n", 3*L*L*L+0.5, p/a, (b/a)/(p/a)}'
    done
fi
first=$(echo $SIZES | awk '{print $1}'); last=$(echo $SIZES | awk '{print $NF}')
awk -v a="${rate[$first,1]}" -v b="${rate[$last,1]}" \
    'BEGIN{printf "time per particle-step, largest / smallest system (1 thread, wall): %.2f\n", a/b}'
awk -v a="${crate[$first,1]}" -v b="${crate[$last,1]}" \
    'BEGIN{printf "time per particle-step, largest / smallest system (1 thread, process CPU time): %.2f\n", a/b}'
fi   # STANDARD

# ---- the speed targets of issue 25, side by side in one run (PEER=1: with LAMMPS; TARGETS=0 skips
# it). Each ratio is the median of REPEAT alternating pairs (ours then the peer's, or the two
# configurations), with its range; rates are production particle-steps per second, 1 thread:
#  - standard DPD, 10125 particles (bench/standard.cfg, L = 15) against LAMMPS pair dpd (target >= 3);
#  - the mai-duy-2019 solvent, 13500 particles (bench/mai-duy-solvent.cfg) against LAMMPS pair
#    dpd/ext (bench/peer/in.dpd-ext; target >= 4);
#  - the TCAF accumulation at fig01's paper settings (its solvent scene, 600 steps): the run's
#    measurement time over its force time (time_measure_seconds / time_force_seconds; target < 0.15);
#  - 1 -> 2 threads at 1e5 particles (L = 32.18), under the harness's OpenMP settings
#    (GOMP_SPINCOUNT = 3000; target >= 1.8).
# The Pan / standard kernel ratio (target < 1.5) is the rotation section's; flatness and memory per
# particle at 1e6 are the standard section's. Written to bench/targets.tsv with date and commit.
if [ "${TARGETS:-1}" = 1 ]; then
    tg_rate() {  # SCENE L STEPS EQ THREADS [ENV...] -> production particle-steps per second (wall)
        local sc=$1 L=$2 n=$3 eq=$4 t=$5; shift 5
        env "$@" "$DPD" run "$sc" --out "$out/tg" --threads "$t" --quiet --set "box=[$L,$L,$L]" \
            --set steps="$n" --set equilibration="$eq" >/dev/null
        val "$out/tg" production_particle_steps_per_second
    }
    tg_pairs() {  # NAME CMD_A CMD_B: REPEAT alternating pairs; prints "median<TAB>range<TAB>best a<TAB>best b"
        local r="" a b ba=0 bb=0
        for k in $(seq "$REPEAT"); do
            a=$(eval "$2"); b=$(eval "$3"); ba=$(max "$ba" "$a"); bb=$(max "$bb" "$b")
            r+="$(awk -v a="$a" -v b="$b" 'BEGIN{print a/b}') "
        done
        printf '%.3f\t%s\t%.4g\t%.4g\n' "$(printf '%s\n' $r | median)" "$(printf '%s\n' $r | range)" "$ba" "$bb"
    }
    tcaf_share() {  # -> measurement / force time of a 600-step run of fig01's solvent scene
        "$DPD" run experiments/mai-duy-2019/fig01-viscosity-wavenumber/solvent-tcaf.cfg --out "$out/tg" --threads 1 \
            --quiet --set steps=600 --set equilibration=40 --set measure.blocks=2 >/dev/null
        awk -F'\t' '$1=="time_measure_seconds"{m=$2} $1=="time_force_seconds"{f=$2} END{print m/f}' "$out/tg/summary.tsv"
    }
    {
        printf 'target\tvalue\trange\tours\tpeer or reference\tgoal\n'
        if [ "${PEER:-0}" = 1 ]; then
            bash bench/peer/build-lammps.sh >/dev/null
            IFS=$'\t' read -r m g a b < <(tg_pairs std "tg_rate bench/standard.cfg 15 1000 300 1" "EQ=300 bench/peer/run-lammps.sh 15 1000 1 | cut -f4")
            printf 'standard DPD / LAMMPS dpd, 10125 particles, 1 thread\t%s\t%s\t%s\t%s\t>= 3\n' "$m" "$g" "$a" "$b"
            IFS=$'\t' read -r m g a b < <(tg_pairs ext "tg_rate bench/mai-duy-solvent.cfg 15 400 300 1" "EQ=300 IN=in.dpd-ext bench/peer/run-lammps.sh 15 400 1 | cut -f4")
            printf 'mai-duy-2019 solvent / LAMMPS dpd/ext, 13500 particles, 1 thread\t%s\t%s\t%s\t%s\t>= 4\n' "$m" "$g" "$a" "$b"
        fi
        r=""; for k in $(seq "$REPEAT"); do r+="$(tcaf_share) "; done
        printf 'TCAF accumulation / force time, fig01 paper settings\t%.3f\t%s\t-\t-\t< 0.15\n' "$(printf '%s\n' $r | median)" "$(printf '%s\n' $r | range)"
        IFS=$'\t' read -r m g a b < <(tg_pairs thr "tg_rate bench/standard.cfg 32.18 100 200 2 GOMP_SPINCOUNT=3000" "tg_rate bench/standard.cfg 32.18 100 200 1 GOMP_SPINCOUNT=3000")
        printf '2 threads / 1 thread, 1e5 particles, harness settings\t%s\t%s\t%s\t%s\t>= 1.8\n' "$m" "$g" "$a" "$b"
        # the machine's own share of that ratio: one thread pinned to CPU 1, then to CPU 0. The
        # force chunks are fixed (their sums in a fixed order give the same bits on any thread
        # count) and split in halves, so 2 threads run at about twice the slower CPU's rate
        if command -v taskset >/dev/null && [ "$(nproc)" -ge 2 ]; then
            IFS=$'\t' read -r m g a b < <(tg_pairs cpu "tg_rate bench/standard.cfg 32.18 100 200 1 GOMP_SPINCOUNT=3000 taskset -c 1" "tg_rate bench/standard.cfg 32.18 100 200 1 GOMP_SPINCOUNT=3000 taskset -c 0")
            printf 'one thread on CPU 1 / on CPU 0, 1e5 particles (the hardware)\t%s\t%s\t%s\t%s\t-\n' "$m" "$g" "$a" "$b"
        fi
        printf 'date, commit\t%s\t%s\t\t\t\n' "$(date -u +%Y-%m-%d)" "$(stamp)"
    } > "$out/targets.tsv"
    cp "$out/targets.tsv" bench/targets.tsv
    echo
    echo "issue 25 targets (ratios: median of $REPEAT alternating pairs):"
    column -t -s $'\t' bench/targets.tsv
fi

# ---- rotating particles (issue 6): the Pan et al. 2008 fluid (3000 particles) with the shear and
# rotational pair terms and particle spin, against the same system with rotation = false and
# gamma_shear = 0 (standard DPD pairs), 1 thread, process CPU time. The host drifts within minutes
# (a best-of-5 of each configuration run one after the other once gave 1.16 where side-by-side
# runs gave 1.83), so the ratio is the median of REPEAT alternating pairs, with its range; the rates
# shown are the best of each. Target (issue 6): the extra cost below 2x. ROTATION=0 skips it.
if [ "${ROTATION:-1}" = 1 ]; then
    rot_once() {  # extra --set arguments -> production particle-steps per CPU second
        "$DPD" run bench/pan-fluid.cfg --out "$out/rotation" --threads 1 --quiet "$@" >/dev/null
        awk -F'\t' '$1=="production_particle_steps_per_second_cpu"{print $2}' "$out/rotation/summary.tsv"
    }
    with=0 without=0 ratios=""
    for k in $(seq "$REPEAT"); do
        w=$(rot_once) wo=$(rot_once --set rotation=false --set 'pairs.[0].gamma_shear=0.0')
        with=$(max "$with" "$w"); without=$(max "$without" "$wo")
        ratios+="$(awk -v a="$w" -v b="$wo" 'BEGIN{print b/a}') "
    done
    ratio=$(printf '%s\n' $ratios | median)
    range=$(printf '%s\n' $ratios | sort -g | awk 'NR==1{lo=$1} {hi=$1} END{printf "%.2f-%.2f", lo, hi}')
    # A second estimator of the same ratio: both runs at once, one on each CPU, then swapped
    # (the standard twin with 3000 production steps, so that the two end at about the same
    # time). Both see the host's same moment, and the CPUs' speeds cancel in
    # sqrt((S1 / P0) (S0 / P1)) (P: Pan, S: standard, 0 and 1: the CPU). Median of REPEAT.
    conc=""
    if command -v taskset >/dev/null && [ "$(nproc)" -ge 2 ]; then
        rot_on() {  # CPU DIR [--set ...] -> production particle-steps per CPU second, pinned
            local c=$1 d=$2; shift 2
            taskset -c "$c" "$DPD" run bench/pan-fluid.cfg --out "$out/$d" --threads 1 --quiet "$@" >/dev/null
            awk -F'\t' '$1=="production_particle_steps_per_second_cpu"{print $2}' "$out/$d/summary.tsv"
        }
        twin=(--set rotation=false --set 'pairs.[0].gamma_shear=0.0' --set steps=3000)
        for k in $(seq "$REPEAT"); do
            rot_on 0 rot-p0 > "$out/rot-p0.rate" & rot_on 1 rot-s1 "${twin[@]}" > "$out/rot-s1.rate"; wait
            rot_on 1 rot-p1 > "$out/rot-p1.rate" & rot_on 0 rot-s0 "${twin[@]}" > "$out/rot-s0.rate"; wait
            conc+="$(awk -v p0="$(cat "$out/rot-p0.rate")" -v p1="$(cat "$out/rot-p1.rate")" -v s0="$(cat "$out/rot-s0.rate")" \
                -v s1="$(cat "$out/rot-s1.rate")" 'BEGIN{print sqrt((s1 / p0) * (s0 / p1))}') "
        done
        cratio=$(printf '%s\n' $conc | median); crange=$(printf '%s\n' $conc | range)
    fi
    echo
    echo "rotating particles (Pan 2008 fluid, 3000 particles, 1 thread, particle-steps per CPU second):"
    awk -v a="$with" -v b="$without" -v r="$ratio" -v g="$range" -v n="$REPEAT" \
        'BEGIN{printf "  with shear + rotational terms %.4g, without %.4g (best of %d): cost ratio %.2f (median of %d alternating pairs, %s; target < 1.5, issue 25)\n", a, b, n, r, n, g}'
    if [ -n "$conc" ]; then
        printf '  the same, both at once on the two CPUs and swapped: %.2f (median of %d, %s)\n' "$cratio" "$REPEAT" "$crange"
    fi
    # machine-readable copy for paper.md ({{bench:rotation.tsv:ROW:value}}), with its date and commit
    {
        printf 'measure\tvalue\tnote\n'
        printf 'particle-steps per CPU second, rotation\t%.4g\tbench/pan-fluid.cfg, 3000 particles, 1 thread, best of %d\n' "$with" "$REPEAT"
        printf 'particle-steps per CPU second, standard\t%.4g\tthe same with rotation = false, gamma_shear = 0, best of %d\n' "$without" "$REPEAT"
        printf 'cost ratio, rotation / standard\t%.2f\tmedian of %d alternating pairs (range %s); target < 1.5 (issue 25; < 2, issue 6)\n' "$ratio" "$REPEAT" "$range"
        if [ -n "$conc" ]; then
            printf 'cost ratio, both at once on two CPUs, swapped\t%.2f\tmedian of %d (range %s): sqrt((S1 / P0) (S0 / P1)), the same moment of the host for both, the CPUs cancel\n' "$cratio" "$REPEAT" "$crange"
        fi
        printf 'date, commit\t%s\t%s\n' "$(date -u +%Y-%m-%d)" "$(stamp)"
    } > "$out/rotation.tsv"
    cp "$out/rotation.tsv" bench/rotation.tsv
fi

# ---- overdamped solvers (issue 3): the Fig. 2 system of Phan-Thien et al. 2016 at the paper
# tier, every solver side by side in one run, compared at equal true relative error (1e-6);
# the experiment phan-thien-2016/fig02-equal-error run into build/bench (the committed results
# are not touched). SOLVERS=0 skips it.
if [ "${SOLVERS:-1}" = 1 ]; then
    exp=experiments/phan-thien-2016/fig02-equal-error
    sout="$root/$out/solvers"; rm -rf "$sout"; mkdir -p "$sout"
    ( cd "$exp" && DPD="$root/$DPD" TIER=paper OUT="$sout" EXP="$root/$exp" DPD_ROOT="$root" \
        OMP_NUM_THREADS=1 ./run.sh paper "$sout" ) > "$out/solvers.log" 2>&1 \
        || { echo "bench: overdamped solvers failed (see $out/solvers.log)"; exit 1; }
    echo
    echo "overdamped solvers, Fig. 2 system, per step (mean +- stderr):"
    column -t -s $'\t' "$sout/ladder.tsv"
    echo
    awk -F'\t' '$1 ~ /^(iteration_ratio_scheme2_best|time_ratio_scheme1_best|cpu_ratio_scheme1_scheme2_at_Estar)$/ {
        printf "%-36s %8.3f +- %.3f\n", $1, $2, $3 }' "$sout/summary.tsv"
    echo "targets (issue 3): iteration_ratio_scheme2_best >= 10, time_ratio_scheme1_best >= 15"
fi

# ---- unused modules (issue 7): bin/dpd against build/dpd-bare, the same sources with every
# optional module's run-time test compiled out (-DDPD_BARE, src/core/modules.h; tests/bare.sh: the two
# give the same numbers bit for bit on this scene). On the standard scene, which switches no module
# on, the difference is what the unused modules cost. Three measures:
#  - instructions per production particle-step (valgrind cachegrind, 3000 particles, 1 thread): the
#    difference of a 300- and a 100-step run, so set-up and output cancel; deterministic, so it
#    decides what the shared machine's timings cannot;
#  - CPU time (24000 and 3000 particles, 1 thread, the two binaries alternating, best of REPEAT);
#  - peak memory per particle, and the run's phase timers (measure, output) of bin/dpd.
# Written to bench/modules.tsv (with date and commit), which paper.md shows. MODULES=0 skips it.
if [ "${MODULES:-1}" = 1 ]; then
    BARE=build/dpd-bare
    [ -x "$BARE" ] || { echo "bench: $BARE missing (make $BARE)"; exit 1; }
    mod_run() {  # BIN L DIR [--set ...]: the standard system of side L, 1 thread
        local b=$1 L=$2 d=$3; shift 3
        "$b" run bench/standard.cfg --out "$d" --threads 1 --quiet --set "box=[$L,$L,$L]" "$@" >/dev/null
    }
    irefs() {  # BIN STEPS -> instructions of the whole run (cachegrind)
        OMP_NUM_THREADS=1 valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null \
            "$1" run bench/standard.cfg --out "$out/modules-cg" --threads 1 --quiet --set "box=[10,10,10]" \
            --set steps="$2" --set equilibration=50 2>&1 >/dev/null | awk '/I *refs:/ { gsub(",", "", $NF); print $NF }'
    }
    {
        printf 'measure\tbin/dpd\tbare build\tcost dpd / bare\tnote\n'
        if command -v valgrind >/dev/null; then
            declare -A ips
            for b in "$DPD" "$BARE"; do
                i1=$(irefs "$b" 100); i3=$(irefs "$b" 300)
                ips[$b]=$(awk -v a="$i1" -v b="$i3" 'BEGIN{printf "%.1f", (b - a) / (200 * 3000)}')
            done
            printf 'instructions per particle-step, 3000 particles\t%s\t%s\t%s\tcachegrind, 1 thread, production steps 100 to 300\n' \
                "${ips[$DPD]}" "${ips[$BARE]}" "$(awk -v a="${ips[$DPD]}" -v b="${ips[$BARE]}" 'BEGIN{printf "%.4f", a/b}')"
        fi
        for L in 20 10; do
            n=$(awk -v L="$L" 'BEGIN{printf "%d", 3*L*L*L + 0.5}')
            bd=0; bb=0; pr=""
            for k in $(seq "$REPEAT"); do   # alternating, so slow spells of the machine hit both
                for b in "$DPD" "$BARE"; do
                    d="$out/modules-$(basename "$b")-$L"
                    mod_run "$b" "$L" "$d" --set steps=$(steps_for "$L") --set equilibration=$(eq_for "$L")
                    c=$(val "$d" production_particle_steps_per_second_cpu)
                    if [ "$b" = "$DPD" ]; then bd=$(max "$bd" "$c"); cd=$c; else bb=$(max "$bb" "$c"); pr="$pr $(awk -v a="$cd" -v b="$c" 'BEGIN{print b/a}')"; fi
                done
            done
            # the spread of the ratio over the REPEAT pairs of runs shows the machine's noise
            printf 'particle-steps per CPU second, %d particles\t%.4g\t%.4g\t%s\t1 thread, best of %d, alternating; ratio of each pair %s\n' \
                "$n" "$bd" "$bb" "$(awk -v a="$bd" -v b="$bb" 'BEGIN{printf "%.3f", b/a}')" "$REPEAT" \
                "$(echo $pr | awk '{ lo = hi = $1; for (i = 2; i <= NF; i++) { if ($i < lo) lo = $i; if ($i > hi) hi = $i }
                                     printf "%.3f to %.3f", lo, hi }')"
            dd="$out/modules-$(basename "$DPD")-$L" db="$out/modules-$(basename "$BARE")-$L"
            printf 'peak memory per particle [B], %d particles\t%.0f\t%.0f\t%s\tpeak RSS / particles\n' "$n" \
                "$(val "$dd" peak_memory_bytes_per_particle)" "$(val "$db" peak_memory_bytes_per_particle)" \
                "$(awk -v a="$(val "$dd" peak_memory_bytes_per_particle)" -v b="$(val "$db" peak_memory_bytes_per_particle)" 'BEGIN{printf "%.3f", a/b}')"
            for ph in measure output; do
                printf 'phase timer %s [s] / force [s], %d particles\t%s / %s\t%s / %s\t-\tthe last run'"'"'s summary.tsv\n' "$ph" "$n" \
                    "$(val "$dd" time_${ph}_seconds)" "$(val "$dd" time_force_seconds)" \
                    "$(val "$db" time_${ph}_seconds)" "$(val "$db" time_force_seconds)"
            done
        done
        printf 'date, commit\t%s\t%s\t-\t%s\n' "$(date -u +%Y-%m-%d)" "$(stamp)" "$(uname -m), $(nproc --all) cores"
    } > "$out/modules.tsv"
    cp "$out/modules.tsv" bench/modules.tsv
    echo
    echo "unused modules: bin/dpd against the bare build (standard scene, no module on; bench/modules.tsv):"
    column -t -s $'\t' bench/modules.tsv
fi

# ---- the memory of a run's series: bench/series.cfg (every step sampled) at 2000 and 60000
# production steps, a checkpoint every 10000 steps. What a sample costs: the peak RSS of the long
# run less the short run's, over the samples added; what it holds: the growth of the checkpoint
# between two of its writes (the series are the only part of it that grows), over the samples
# between them. Their ratio is 1 when the series are held once; growth by doubling makes it up
# to 2, and a checkpoint copied into a buffer before it is written adds 1 more. With
# BASE=path/to/earlier/dpd the same for it, side by side in one run. Written to bench/series.tsv.
# SERIES=0 skips it.
if [ "${SERIES:-1}" = 1 ]; then
    series_run() {  # BIN STEPS DIR -> "peak RSS [kB]<TAB>checkpoint bytes per step" (the second
        # from the first two checkpoints seen while it runs; "-" if fewer were seen)
        local b=$1 d=$out/$3 seen="" st sz
        rm -rf "$d"
        "$b" run bench/series.cfg --out "$d" --threads 1 --quiet --checkpoint-every 10000 --set steps="$2" >/dev/null &
        local pid=$!
        while kill -0 "$pid" 2>/dev/null; do
            if [ -e "$d/checkpoint.dpd" ] && cp "$d/checkpoint.dpd" "$d.ck" 2>/dev/null &&
               st=$("$DPD" checkpoint-info "$d.ck" 2>/dev/null | awk -F'\t' '$1 == "step" { print $2 }'); then
                sz=$(stat -c %s "$d.ck")
                case " $seen " in *" $st:"*) ;; *) seen="$seen $st:$sz" ;; esac
            fi
            sleep 0.1
        done
        wait "$pid"; rm -f "$d.ck"
        printf '%s\t%s\n' "$(awk -F'\t' '$1 == "peak_rss_kb" { print $2 }' "$d/provenance.tsv")" \
            "$(echo $seen | tr ' :' '\n ' | awk 'NF == 2 && n < 2 { s[++n] = $1; z[n] = $2 }
                END { if (n == 2 && s[2] != s[1]) printf "%.1f", (z[2] - z[1]) / (s[2] - s[1]); else print "-" }')"
    }
    {
        printf 'binary\tpeak RSS, 2000 steps [kB]\tpeak RSS, 60000 steps [kB]\tmemory per sample [B]\tseries per sample [B]\tmemory / series\tnote\n'
        for b in "$DPD" ${BASE:+"$BASE"}; do
            short=$(series_run "$b" 2000 series-short | cut -f1); read -r long held < <(series_run "$b" 60000 series-long)
            per=$(awk -v s="$short" -v l="$long" 'BEGIN{printf "%.1f", (l - s) * 1024 / 58000}')
            printf '%s\t%s\t%s\t%s\t%s\t%s\tbench/series.cfg, 1 thread, every step sampled\n' "$("$b" --version 2>&1 | head -1)" \
                "$short" "$long" "$per" "$held" "$(awk -v p="$per" -v h="$held" 'BEGIN{ if (h + 0 > 0) printf "%.2f", p / h; else print "-" }')"
        done
        printf 'date, commit\t%s\t%s\t-\t-\t-\t%s\n' "$(date -u +%Y-%m-%d)" "$(stamp)" "$(uname -m)"
    } > "$out/series.tsv"
    cp "$out/series.tsv" bench/series.tsv
    echo
    echo "the memory of a run's series (bench/series.tsv):"
    column -t -s $'\t' bench/series.tsv
fi

# ---- a refactor against the binary before it (issue 24): BASE=path/to/earlier/dpd (e.g. built by
# `git worktree add /tmp/base COMMIT && make -C /tmp/base bin/dpd`). For the four kernels -- the
# standard scene, the general weight exponent (the mai-duy-2019 solvent, bench/mai-duy-solvent.cfg in
# a box of 10: 4000 particles), the rotating particles of Pan et al. 2008 (bench/pan-fluid.cfg) and
# the m = 0 solver (the Couette scene of phan-thien-2016 Fig. 3) -- instructions per production particle-step
# (cachegrind, the difference of a long and a short run, deterministic; valgrind runs the AVX2
# level, it has no AVX-512) and CPU time per particle-step (the two binaries alternating, median of
# REPEAT pairs' ratios; and both at once on the two CPUs, swapped). Written to bench/refactor.tsv.
# Without BASE the section is skipped.
if [ -n "${BASE:-}" ] && [ "${REFACTOR:-1}" = 1 ]; then
    [ -x "$BASE" ] || { echo "bench: BASE=$BASE is not an executable"; exit 1; }
    kernel_args() {  # KERNEL -> scene and settings of 3000 particles (standard, pan) or its own size (m = 0)
        case $1 in
            standard) echo "bench/standard.cfg --set box=[10.0,10.0,10.0]" ;;
            pow) echo "bench/mai-duy-solvent.cfg --set box=[10.0,10.0,10.0]" ;;
            pan2008) echo "bench/pan-fluid.cfg" ;;
            m0) echo "experiments/phan-thien-2016/fig03-couette-profile/couette.cfg" ;;
        esac
    }
    kernel_irefs() {  # BIN KERNEL STEPS -> instructions of the whole run
        # shellcheck disable=SC2046
        OMP_NUM_THREADS=1 valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null \
            "$1" run $(kernel_args "$2") --out "$out/refactor-cg" --threads 1 --quiet --set steps="$3" \
            --set equilibration=20 2>&1 >/dev/null | awk '/I *refs:/ { gsub(",", "", $NF); print $NF }'
    }
    kernel_cpu() {  # BIN KERNEL STEPS [CPU DIR] -> production particle-steps per CPU second (pinned to CPU)
        local pin=() dir=refactor-run
        [ -n "${4:-}" ] && pin=(taskset -c "$4") && dir=$5
        # shellcheck disable=SC2046
        OMP_NUM_THREADS=1 "${pin[@]}" "$1" run $(kernel_args "$2") --out "$out/$dir" --threads 1 --quiet \
            --set steps="$3" --set equilibration=20 >/dev/null && val "$out/$dir" production_particle_steps_per_second_cpu
    }
    # the second estimator (as the rotation section's): BASE on CPU 0 and this build on CPU 1 at
    # once, then swapped; CPU time new / base = sqrt((b0 / n1) (b1 / n0)) of the rates: both see
    # the host's same moment (on a loaded host the alternating pairs do not), the CPUs cancel
    conc_ok=0
    if command -v taskset >/dev/null && [ "$(nproc)" -ge 2 ]; then conc_ok=1; fi
    {
        printf 'kernel\tinstructions per particle-step, base\tnew\tnew / base\tCPU time new / base (median of %s pairs)\trange\tboth at once, swapped (median of %s)\trange\n' "$REPEAT" "$REPEAT"
        for k in standard pow pan2008 m0; do
            case $k in m0) short=20 long=60 ;; *) short=50 long=150 ;; esac
            n=$("$DPD" run $(kernel_args $k) --dry-run --out "$out/refactor-plan" | awk '$1 == "particles" { print $2 }')
            ib=$(( $(kernel_irefs "$BASE" $k $long) - $(kernel_irefs "$BASE" $k $short) ))
            in=$(( $(kernel_irefs "$DPD" $k $long) - $(kernel_irefs "$DPD" $k $short) ))
            r="" c=""
            for j in $(seq "$REPEAT"); do   # alternating, so slow spells of the machine hit both
                a=$(kernel_cpu "$BASE" $k $long); b=$(kernel_cpu "$DPD" $k $long)
                r+="$(awk -v a="$a" -v b="$b" 'BEGIN{print a/b}') "   # CPU time ratio = inverse rate ratio
                if [ "$conc_ok" = 1 ]; then
                    kernel_cpu "$BASE" $k $long 0 rf-b0 > "$out/rf-b0.rate" & kernel_cpu "$DPD" $k $long 1 rf-n1 > "$out/rf-n1.rate"; wait
                    kernel_cpu "$DPD" $k $long 0 rf-n0 > "$out/rf-n0.rate" & kernel_cpu "$BASE" $k $long 1 rf-b1 > "$out/rf-b1.rate"; wait
                    c+="$(awk -v b0="$(cat "$out/rf-b0.rate")" -v b1="$(cat "$out/rf-b1.rate")" -v n0="$(cat "$out/rf-n0.rate")" \
                        -v n1="$(cat "$out/rf-n1.rate")" 'BEGIN{print sqrt((b0 / n1) * (b1 / n0))}') "
                fi
            done
            printf '%s (%d particles)\t%.1f\t%.1f\t%.4f\t%.3f\t%s\t%s\t%s\n' "$k" "$n" \
                "$(awk -v i="$ib" -v n="$n" -v s=$((long - short)) 'BEGIN{print i / (n * s)}')" \
                "$(awk -v i="$in" -v n="$n" -v s=$((long - short)) 'BEGIN{print i / (n * s)}')" \
                "$(awk -v a="$ib" -v b="$in" 'BEGIN{print b / a}')" \
                "$(tr ' ' '\n' <<< "$r" | grep . | median)" "$(tr ' ' '\n' <<< "$r" | grep . | range)" \
                "$( [ -n "$c" ] && printf '%.3f' "$(tr ' ' '\n' <<< "$c" | grep . | median)" || echo -)" \
                "$( [ -n "$c" ] && tr ' ' '\n' <<< "$c" | grep . | range || echo -)"
        done
        printf 'date, commits\t%s\t%s\t-\tbase %s\t%s\t-\t-\n' "$(date -u +%Y-%m-%d)" "$(stamp)" \
            "$("$BASE" --version 2>/dev/null | head -1 || echo unknown)" "$(uname -m), $(nproc --all) cores"
    } > "$out/refactor.tsv"
    cp "$out/refactor.tsv" bench/refactor.tsv
    echo
    echo "this build against BASE=$BASE (bench/refactor.tsv):"
    column -t -s $'\t' bench/refactor.tsv
fi
# ---- the cost classes against BASE (SPEEDUP=1 with BASE set; bench/speedup.tsv): CPU time per
# production particle-step of this build over BASE's, the median of REPEAT alternating pairs, for
# each class of scene tools/cost tells apart (tools/cost table scales the committed runs' rates by
# it, so the paper tier's projection follows a faster simulator without rerunning it). BASE should be
# the binary (or one as fast) that made the committed runs.
if [ -n "${BASE:-}" ] && [ "${SPEEDUP:-0}" = 1 ]; then
    class_args() {  # CLASS -> scene and settings
        case $1 in
            standard) echo "bench/standard.cfg --set box=[15.0,15.0,15.0] --set steps=400 --set equilibration=100" ;;
            pow) echo "bench/mai-duy-solvent.cfg --set steps=200 --set equilibration=50" ;;
            tcaf) echo "experiments/mai-duy-2019/fig01-viscosity-wavenumber/solvent-tcaf.cfg --set steps=600 --set equilibration=40 --set measure.blocks=2" ;;
            rotation) echo "bench/pan-fluid.cfg --set steps=600 --set equilibration=100" ;;
            m0) echo "experiments/phan-thien-2016/fig03-couette-profile/couette.cfg --set steps=60 --set equilibration=20" ;;
            # several types, shear or 2D (the generic walk for the batches that mix types, and for all
            # with shear or in 2D; the AVX-512 evaluators for the rest), on scenes of the experiments:
            # the standard system sheared, the mai-duy-2019 suspension (two types, shear, springs), its
            # TCAF scene with a free colloid (fig02), the pan-2008 two spheres (a fluid and frozen spheres)
            tcaf-generic) echo "experiments/mai-duy-2019/fig02-length-scale/free.cfg --set steps=600 --set equilibration=20 --set measure.blocks=2" ;;
            standard-generic) echo "bench/standard.cfg --set box=[15.0,15.0,15.0] --set shear_rate=0.1 --set steps=400 --set equilibration=100" ;;
            pow-generic) echo "experiments/mai-duy-2019/fig04-relative-viscosity-a353/suspension-shear.cfg --set steps=60 --set equilibration=20" ;;
            rotation-generic) echo "experiments/pan-2008/tab03-two-spheres/two-spheres.cfg --set steps=400 --set equilibration=50" ;;
        esac
    }
    class_rate() {  # BIN CLASS -> production particle-steps per CPU second
        # shellcheck disable=SC2046
        OMP_NUM_THREADS=1 "$1" run $(class_args "$2") --out "$out/speedup-run" --threads 1 --quiet >/dev/null \
            && val "$out/speedup-run" production_particle_steps_per_second_cpu
    }
    {
        printf 'class\tcpu_time_new_over_base\trange\tscene\n'
        for c in standard pow tcaf rotation m0 standard-generic pow-generic tcaf-generic rotation-generic; do
            r=""
            for j in $(seq "$REPEAT"); do
                a=$(class_rate "$BASE" $c); b=$(class_rate "$DPD" $c)
                r+="$(awk -v a="$a" -v b="$b" 'BEGIN{print a/b}') "
            done
            printf '%s\t%.3f\t%s\t%s\n' "$c" "$(tr ' ' '\n' <<< "$r" | grep . | median)" "$(tr ' ' '\n' <<< "$r" | grep . | range)" "$(class_args $c | cut -d' ' -f1)"
        done
        printf 'date, commits\t%s\t%s\tbase %s\n' "$(date -u +%Y-%m-%d)" "$(stamp)" \
            "$("$BASE" --version 2>/dev/null | head -1 || echo unknown)"
    } > "$out/speedup.tsv"
    cp "$out/speedup.tsv" bench/speedup.tsv
    echo
    echo "CPU time per particle-step, this build / BASE, by cost class (bench/speedup.tsv; tools/cost uses it):"
    column -t -s $'\t' bench/speedup.tsv
fi
