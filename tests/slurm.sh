#!/usr/bin/env bash
# tests/slurm.sh - the Slurm engine against a real Slurm (make test-slurm; CI runs it).
# Starts a one-node cluster (tools/slurm-local: munged, slurmctld, slurmd; 2 CPUs) in a scratch
# directory, runs the quick tier of two experiments (11 simulations between them) through it
# (DPD_ENGINE=slurm: a Slurm job per simulation, the analyses as Slurm jobs too) and through the
# local pool (beside the Slurm part; with DPD_SLURM_LOCAL_FROM=results, as CI runs it after make
# figures, only the cancelled simulation and the analyses: the other simulations are make
# figures' own, made by this binary), each in a scratch copy of the package, and checks:
#  - both complete, and every summary.tsv (but its measured cpu_seconds row), every table of the
#    results and every simulation's summary (but its measured times) are byte-identical: the
#    simulator is deterministic, so any difference is a bug;
#  - one running job, cancelled with scancel (SIGTERM: the simulator writes a checkpoint) and
#    requeued with scontrol requeue, resumes from its checkpoint (its provenance says at which
#    step) and gives bit-identical results: its tables, and its run.h5 time series and final
#    state (h5diff) against the local pool's uninterrupted run;
#  - a job cancelled with scancel and not requeued within DPD_SLURM_CANCEL_GRACE (here 5 s): the
#    experiment stops with a message naming it and submits it no second time (README "The Slurm
#    engine"); run again, it resubmits it, and the simulation resumes from its checkpoint.
# Exit status: 0 when every check passes. Needs: slurm-wlm, munge (tools/deps slurm).
set -uo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
EXPS=(mai-duy-2019/sec43-repulsion-viscosity mai-duy-2019/fig03-diffusion-repulsion)
VICTIM=a3.53                           # the simulation whose job is cancelled and requeued (sec43)
dpd=${DPD:-$repo/bin/dpd}
[ -x "$dpd" ] || { echo "slurm.sh: no simulator $dpd (make bin/dpd)" >&2; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/dpd-slurm.XXXXXX") && chmod 755 "$tmp"   # munged wants its socket's path open to all
cluster=$tmp/cluster
cleanup() { pkill -TERM -f "$tmp/local/tools/run-experiment" 2>/dev/null; "$repo/tools/slurm-local" stop "$cluster" >/dev/null 2>&1; [ "${KEEP:-0}" = 1 ] && echo "kept $tmp" || rm -rf "$tmp"; }
trap cleanup EXIT
pass=0 fail=0
ok()  { pass=$((pass + 1)); echo "ok   - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1"; }
t0=$(date +%s)
# two scratch copies of the package (tools and experiments; no results): local and slurm
for t in local slurm; do mkdir -p "$tmp/$t" && cp -a "$repo/tools" "$repo/experiments" "$tmp/$t/"; done
# the same settings for both: run.h5 kept for the comparison, frequent checkpoints (they do not
# change the results) so that the cancelled job has one to resume from
export DPD_BIN=$dpd DPD_KEEP_H5=1 DPD_CHECKPOINT_EVERY=500 DPD_CHECKPOINT_WALL=0
unset MAKEFLAGS MFLAGS

echo "== local pool"
# DPD_SLURM_LOCAL_FROM=results (CI, after `make figures TIER=quick` with this same simulator): the
# local pool's simulations are the ones that make figures just ran in this checkout
# (results/EXP/quick/runs), taken only if each one's provenance names this simulator ($dpd) and
# its version; they go into the local copy's partial (stamped with this binary), so that
# run-experiment keeps them, reruns only the victim (its run.h5 is needed, and figures does not
# keep it) and redoes every analysis. Anything else: every simulation runs here.
reused=0
if [ "${DPD_SLURM_LOCAL_FROM:-}" = results ]; then
    ver=$("$dpd" --version); ver=${ver#dpd }
    for e in "${EXPS[@]}"; do
        src=$repo/results/$e/quick/runs p=$tmp/local/results/$e/.quick.partial
        [ -d "$src" ] || continue
        mkdir -p "$p/runs"
        for r in "$src"/*/; do r=${r%/}; n=${r##*/}
            [ "$e/$n" = "${EXPS[0]}/$VICTIM" ] && continue
            awk -F'\t' -v d="$dpd" -v v="$ver" '$1 == "git_commit" && $2 == v { c = 1 }
                $1 == "command" && index($2, d " run ") == 1 { b = 1 } END { exit !(c && b) }' "$r/provenance.tsv" 2>/dev/null ||
                continue
            cp -a "$r" "$p/runs/$n" && reused=$((reused + 1))
        done
        (. "$repo/tools/lib/common.sh" && partial_stamp quick "$dpd") > "$p/.stamp"
    done
fi
[ "${DPD_SLURM_LOCAL_FROM:-}" != results ] || [ "$reused" -ge 10 ] ||
    bad "DPD_SLURM_LOCAL_FROM=results: only $reused of the 10 simulations other than the victim were taken (make figures TIER=quick first)"
# the local pool runs beside the Slurm sections below (they wait on Slurm's polls and grace
# times; one core each would idle), and is waited for before the comparison
local_pool() {
    local e t=$(date +%s)
    for e in "${EXPS[@]}"; do
        DPD_JOBS=2 "$tmp/local/tools/run-experiment" "$e" quick >> "$tmp/local.log" 2>&1 || { echo "$e" > "$tmp/local.failed"; return 1; }
    done
    echo $(( $(date +%s) - t )) > "$tmp/local.seconds"
}
local_pool & local_pid=$!

echo "== Slurm"
t1=$(date +%s)
# requeued jobs may start 10 s after a requeue, not Slurm's default 120 (cred_expire)
out=$(SLURM_LOCAL_CRED_EXPIRE=10 "$repo/tools/slurm-local" start "$cluster") || { bad "slurm-local start"; exit 1; }
eval "$out"
sinfo -h -o '%D %C %t' | grep -q idle && ok "cluster up: $(sinfo -h -o '%D node(s), CPUs A/I/O/T %C')" || bad "cluster not idle"
pids=()
for e in "${EXPS[@]}"; do
    DPD_ENGINE=slurm DPD_SLURM_POLL=1 DPD_SLURM_CANCEL_GRACE=120 DPD_JOBS=8 \
        "$tmp/slurm/tools/run-experiment" "$e" quick > "$tmp/slurm-${e##*/}.log" 2>&1 &
    pids+=($!)
done
# the victim: once its job runs and has written a checkpoint, cancel it
vdir=$tmp/slurm/results/${EXPS[0]}/.quick.partial/runs/$VICTIM
id=
for _ in $(seq 600); do
    id=$(squeue -h -o '%i %j %T' | awk -v v=":$VICTIM:" 'index($2, v) && $3 == "RUNNING" { print $1; exit }')
    [ -n "$id" ] && [ -s "$vdir/checkpoint.dpd" ] && break
    sleep 0.2
done
if [ -n "$id" ] && [ -s "$vdir/checkpoint.dpd" ]; then
    scancel "$id"
    for _ in $(seq 300); do [ "$(squeue -h -t all -j "$id" -o %T)" = CANCELLED ] && break; sleep 0.2; done
    st=$(squeue -h -t all -j "$id" -o %T)
    [ "$st" = CANCELLED ] && ok "scancel: job $id ($VICTIM) CANCELLED" || bad "scancel: job $id is $st"
    if [ -e "$vdir/INCOMPLETE" ] && [ ! -e "$vdir/summary.tsv" ] && [ -s "$vdir/checkpoint.dpd" ]; then
        ok "scancel: the simulation stopped incomplete with a checkpoint (exit $(cat "$vdir/.exit" 2>/dev/null))"
    else bad "scancel: $VICTIM not left incomplete with a checkpoint"; fi
    scontrol requeue "$id" && scontrol update jobid="$id" StartTime=now &&
        ok "scontrol requeue: job $id back in the queue" || bad "scontrol requeue $id failed"
else
    bad "no running job of $VICTIM with a checkpoint to cancel"
fi
for i in "${!pids[@]}"; do
    if wait "${pids[i]}"; then ok "Slurm engine: ${EXPS[i]} complete"
    else bad "Slurm engine: ${EXPS[i]} failed"; tail -20 "$tmp/slurm-${EXPS[i]##*/}.log"; fi
done
ok "Slurm: $(( $(date +%s) - t1 )) s"
restarts=$(scontrol show job "$id" 2>/dev/null | sed -n 's/.*Restarts=\([0-9]*\).*/\1/p')
[ "${restarts:-0}" -ge 1 ] && ok "the cancelled job ran again (Restarts=$restarts)" || bad "the cancelled job did not run again (Restarts=${restarts:-?})"
grep -q 'CANCELLED AT' "$tmp/slurm/results/${EXPS[0]}/quick/runs/$VICTIM/slurm.out" 2>/dev/null &&
    ok "its output records the cancellation" || bad "no cancellation in its slurm.out"
at=$(awk -F'\t' '$1 == "resumed_at_step" { print $2 }' "$tmp/slurm/results/${EXPS[0]}/quick/runs/$VICTIM/provenance.tsv" 2>/dev/null)
[ -n "$at" ] && [ "$at" -gt 0 ] && ok "it resumed from its checkpoint at step $at" || bad "it did not resume from a checkpoint"
n=$(squeue -h -t all -o '%j' | grep -c '^dpd:')
[ "$n" -ge 6 ] && ok "$n simulations ran as Slurm jobs" || bad "only $n simulations ran as Slurm jobs"
squeue -h -t all -o '%j' | grep -q '^dpd-analysis:' && ok "the analyses ran as Slurm jobs" || bad "no analysis ran as a Slurm job"

echo "== scancel without requeue"
mkdir -p "$tmp/cancel" && cp -a "$repo/tools" "$repo/experiments" "$tmp/cancel/"
run_cancel() { DPD_ENGINE=slurm DPD_SLURM_POLL=1 DPD_SLURM_CANCEL_GRACE=5 DPD_JOBS=8 \
                   "$tmp/cancel/tools/run-experiment" "${EXPS[0]}" quick > "$tmp/cancel-$1.log" 2>&1; }
run_cancel 1 & cpid=$!
cdir=$tmp/cancel/results/${EXPS[0]}/.quick.partial/runs/$VICTIM
cid=
for _ in $(seq 600); do
    cid=$(squeue -h -o '%i %j %T' | awk -v v=":$VICTIM:" 'index($2, v) && $3 == "RUNNING" { print $1; exit }')
    [ -n "$cid" ] && [ -s "$cdir/checkpoint.dpd" ] && break
    sleep 0.2
done
if [ -n "$cid" ] && [ -s "$cdir/checkpoint.dpd" ]; then
    cname=$(squeue -h -t all -j "$cid" -o %j)
    scancel "$cid"
    if wait $cpid; then bad "scancel without requeue: the experiment completed"
    else ok "scancel without requeue: the experiment stopped"; fi
    grep -q "$VICTIM (job $cid cancelled (scancel) and not requeued within 5 s.*was cancelled (scancel) and not requeued within DPD_SLURM_CANCEL_GRACE" "$tmp/cancel-1.log" &&
        ok "scancel without requeue: the message names the simulation and its job" ||
        { bad "scancel without requeue: message"; tail -5 "$tmp/cancel-1.log"; }
    n=$(squeue -h -t all -o '%j' | grep -cxF "$cname")
    [ "$n" = 1 ] && ok "scancel without requeue: submitted once, not again" || bad "scancel without requeue: $n jobs named $cname"
    if run_cancel 2; then ok "scancel without requeue: run again, the experiment completes"
    else bad "scancel without requeue: the second attempt failed"; tail -10 "$tmp/cancel-2.log"; fi
    at=$(awk -F'\t' '$1 == "resumed_at_step" { print $2 }' "$tmp/cancel/results/${EXPS[0]}/quick/runs/$VICTIM/provenance.tsv" 2>/dev/null)
    [ -n "$at" ] && [ "$at" -gt 0 ] && ok "scancel without requeue: the resubmitted simulation resumed at step $at" ||
        bad "scancel without requeue: the resubmitted simulation did not resume from its checkpoint"
else
    bad "scancel without requeue: no running job of $VICTIM with a checkpoint to cancel"; kill $cpid 2>/dev/null; wait $cpid
fi

echo "== Slurm against the local pool"
if wait $local_pid; then
    ok "local pool: ${EXPS[*]} complete ($(cat "$tmp/local.seconds") s beside the Slurm sections; $reused simulations taken from make figures' results)"
else
    bad "local pool: $(cat "$tmp/local.failed" 2>/dev/null) failed"; tail -20 "$tmp/local.log"
    echo "slurm.sh: $pass passed, $fail failed ($(( $(date +%s) - t0 )) s)"; exit 1
fi
measured=$'^(cpu_seconds|wall_seconds|.*particle_steps_per_second.*|peak_memory_bytes_per_particle|time_[a-z_]*seconds)\t'
for e in "${EXPS[@]}"; do
    a=$tmp/local/results/$e/quick b=$tmp/slurm/results/$e/quick
    if diff <(grep -Ev "$measured" "$a/summary.tsv") <(grep -Ev "$measured" "$b/summary.tsv") >/dev/null; then
        ok "$e: summary.tsv identical (but cpu_seconds)"
    else bad "$e: summary.tsv differs"; diff <(grep -Ev "$measured" "$a/summary.tsv") <(grep -Ev "$measured" "$b/summary.tsv") | head -5; fi
    d=0; for f in "$a"/*.tsv; do case ${f##*/} in summary.tsv|provenance.tsv) continue ;; esac; cmp -s "$f" "$b/${f##*/}" || { d=1; echo "   differs: ${f##*/}"; }; done
    [ $d = 0 ] && ok "$e: every table identical" || bad "$e: a table differs"
    d=0; for r in "$a"/runs/*/; do r=${r%/}; n=${r##*/}
        for f in "$r"/*.tsv; do case ${f##*/} in provenance.tsv) continue ;; esac
            cmp -s <(grep -Ev "$measured" "$f") <(grep -Ev "$measured" "$b/runs/$n/${f##*/}") || { d=1; echo "   differs: runs/$n/${f##*/}"; }
        done; done
    [ $d = 0 ] && ok "$e: every simulation's tables identical (but measured times)" || bad "$e: a simulation differs"
done
a=$tmp/local/results/${EXPS[0]}/quick/runs/$VICTIM/run.h5 b=$tmp/slurm/results/${EXPS[0]}/quick/runs/$VICTIM/run.h5
for g in /series /results/final_state /results/profile; do
    if h5diff -q "$a" "$b" "$g" "$g" >/dev/null 2>&1; then ok "$VICTIM (cancelled, requeued): run.h5 $g bit-identical"
    else bad "$VICTIM: run.h5 $g differs"; h5diff -r "$a" "$b" "$g" "$g" 2>&1 | head -8; fi
done
echo "slurm.sh: $pass passed, $fail failed ($(( $(date +%s) - t0 )) s)"
[ "$fail" -eq 0 ]
