#!/bin/bash
# checkpoint.sh - checkpoint/restart and interrupted runs, end to end:
# for each scene (tests/checkpoint-shear.cfg: Lees-Edwards shear, profile, RDF,
# MSD; tests/checkpoint-overdamped.cfg: m = 0 with a warm-started PCG solve)
#   ref   uninterrupted run, 1 thread, no checkpoints
#   kill  run with --checkpoint-every, SIGKILLed as soon as its first
#         checkpoint exists (wherever it is then: mid-step or mid-write), must
#         leave INCOMPLETE and no summary.tsv; then --resume on 2 threads
#   term  SIGTERM: status 143, a checkpoint, INCOMPLETE; then --resume
# and every resumed run must equal ref bit for bit: /results/final_state
# (positions, images, velocities by particle id) and /observables of run.h5
# by h5diff (exact), profile/rdf/msd tables by cmp, summary.tsv without its
# timing rows. Controls with power: another seed must differ (h5diff sees it);
# a truncated checkpoint, one of another scene, and --resume with nothing to
# resume are handled. DPD selects the binary. Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
DPD=${DPD:-bin/dpd}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/dpd-checkpoint-XXXXXX")
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok()  { pass=$((pass + 1)); echo "PASS $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1: $2"; }
check() { local name=$1; shift; if "$@"; then ok "$name"; else bad "$name" "$*"; fi; }

physics() { grep -Ev 'seconds|per_second|memory' "$1"; }
same_run() {   # same_run REF DIR: bit-identical results
    local r=$1 d=$2 t
    [ -s "$d/summary.tsv" ] && [ ! -e "$d/INCOMPLETE" ] || { echo "  $d: no complete result"; return 1; }
    h5diff -q "$r/run.h5" "$d/run.h5" /results/final_state || { echo "  final_state differs"; return 1; }
    h5diff -q "$r/run.h5" "$d/run.h5" /observables || { echo "  observables differ"; return 1; }
    for t in profile rdf msd around density_map colloid_msd colloid_around colloid_rdf; do
        [ -e "$r/$t.tsv" ] || continue
        cmp -s "$r/$t.tsv" "$d/$t.tsv" || { echo "  $t.tsv differs"; return 1; }
    done
    diff <(physics "$r/summary.tsv") <(physics "$d/summary.tsv") >/dev/null || { echo "  summary.tsv differs"; return 1; }
}
incomplete() { [ -e "$1/INCOMPLETE" ] && [ ! -e "$1/summary.tsv" ] && [ ! -e "$1/run.h5" ]; }

for scene in tests/checkpoint-shear.cfg tests/checkpoint-overdamped.cfg tests/checkpoint-colloids2d.cfg; do
    s=$(basename "$scene" .cfg)
    "$DPD" run "$scene" --out "$tmp/$s-ref" --threads 1 --quiet 2>"$tmp/err"
    check "$s: reference run" test $? -eq 0

    # SIGKILL after the first checkpoint, resume on 2 threads
    "$DPD" run "$scene" --out "$tmp/$s-kill" --threads 1 --quiet --checkpoint-every 20 2>"$tmp/err" &
    pid=$!
    for _ in $(seq 6000); do [ -e "$tmp/$s-kill/checkpoint.dpd" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.01; done
    kill -KILL $pid 2>/dev/null
    wait $pid 2>/dev/null; st=$?
    check "$s: SIGKILL (status $st) leaves INCOMPLETE, no result" test $st -eq 137 -a -e "$tmp/$s-kill/INCOMPLETE" -a ! -e "$tmp/$s-kill/summary.tsv"
    "$DPD" run "$scene" --out "$tmp/$s-kill" --threads 2 --quiet --checkpoint-every 20 --resume 2>"$tmp/err"
    st=$?
    check "$s: resume after SIGKILL (status $st)" test $st -eq 0
    check "$s: killed + resumed = uninterrupted, bit for bit" same_run "$tmp/$s-ref" "$tmp/$s-kill"
    check "$s: no checkpoint left after completion" test ! -e "$tmp/$s-kill/checkpoint.dpd"

    # SIGTERM: checkpoint written at the end of the current step
    "$DPD" run "$scene" --out "$tmp/$s-term" --threads 1 --quiet --checkpoint-every 20 2>"$tmp/err" &
    pid=$!
    for _ in $(seq 6000); do [ -e "$tmp/$s-term/checkpoint.dpd" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.01; done
    kill -TERM $pid
    wait $pid; st=$?
    check "$s: SIGTERM gives status 143, a checkpoint and INCOMPLETE" \
        test $st -eq 143 -a -s "$tmp/$s-term/checkpoint.dpd" -a -e "$tmp/$s-term/INCOMPLETE" -a ! -e "$tmp/$s-term/summary.tsv"
    grep -q 'stopped by signal 15 at step' "$tmp/err"
    check "$s: SIGTERM message" test $? -eq 0
    "$DPD" run "$scene" --out "$tmp/$s-term" --threads 1 --quiet --resume 2>"$tmp/err"
    check "$s: resume after SIGTERM" test $? -eq 0
    check "$s: SIGTERM + resumed = uninterrupted, bit for bit" same_run "$tmp/$s-ref" "$tmp/$s-term"
done

s=checkpoint-shear scene=tests/checkpoint-shear.cfg
# power: a different seed must be seen as different
"$DPD" run "$scene" --set seed=8 --out "$tmp/seed8" --threads 1 --quiet 2>/dev/null
check "control: another seed differs" bash -c "! h5diff -q '$tmp/$s-ref/run.h5' '$tmp/seed8/run.h5' /results/final_state"
# --resume with no checkpoint runs from the start
"$DPD" run "$scene" --out "$tmp/fresh" --threads 1 --quiet --resume 2>/dev/null
check "--resume without a checkpoint = a fresh run" same_run "$tmp/$s-ref" "$tmp/fresh"
# a truncated or foreign checkpoint is refused, nothing accepted
rm -rf "$tmp/trunc"
"$DPD" run "$scene" --out "$tmp/trunc" --threads 1 --quiet --checkpoint-every 20 2>/dev/null &
pid=$!; for _ in $(seq 6000); do [ -e "$tmp/trunc/checkpoint.dpd" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.01; done
kill -TERM $pid; wait $pid
cp -r "$tmp/trunc" "$tmp/foreign"
truncate -s 1000 "$tmp/trunc/checkpoint.dpd"
"$DPD" run "$scene" --out "$tmp/trunc" --quiet --resume 2>"$tmp/err"; st=$?
check "truncated checkpoint: status 2, named, no result" test $st -eq 2 -a ! -e "$tmp/trunc/summary.tsv"
check "truncated checkpoint: message" grep -q 'checkpoint.dpd is corrupt' "$tmp/err"
"$DPD" run "$scene" --set pairs.[0].a=26.0 --out "$tmp/foreign" --quiet --resume 2>"$tmp/err"; st=$?
check "checkpoint of another scene: status 2, no result" test $st -eq 2 -a ! -e "$tmp/foreign/summary.tsv"
check "checkpoint of another scene: message" grep -q 'written for another scene' "$tmp/err"
# resuming a run with trajectory frames is refused (the frames before the checkpoint are gone)
"$DPD" run "$scene" --set 'output={trajectory_every=100;}' --out "$tmp/traj" --threads 1 --quiet --checkpoint-every 20 2>/dev/null &
pid=$!; for _ in $(seq 6000); do [ -e "$tmp/traj/checkpoint.dpd" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.01; done
kill -TERM $pid; wait $pid
"$DPD" run "$scene" --set 'output={trajectory_every=100;}' --out "$tmp/traj" --quiet --resume 2>"$tmp/err"; st=$?
check "resume with trajectory output: status 2, no result" test $st -eq 2 -a ! -e "$tmp/traj/summary.tsv"
check "resume with trajectory output: message" grep -q 'trajectory_every > 0 is not supported' "$tmp/err"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
