#!/bin/bash
# in_flight.sh - tools/in-flight on a tree built for it: the simulations of a result being made
# (results/P/E/.TIER.partial/runs/NAME) that have no summary, each with its checkpoint's step (the
# number dpd checkpoint-info reads, checked against the file's own bytes), the steps it runs
# (equilibration + steps of its recorded arguments), and its state: running (a simulator holds
# the directory: a real one, started here), stopped (a checkpoint, nobody running), queued (none
# yet). A finished simulation is not listed, a tier argument selects, a corrupt checkpoint makes
# the exit status 1. DPD selects the binary. Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh in-flight
tool=$PWD/tools/in-flight
root=$tmp/tree; exp=$root/experiments/p/e; runs=$root/results/p/e/.paper.partial/runs
mkdir -p "$exp" "$runs"
cp tests/good-scene.cfg "$exp/fluid.cfg"   # a small fluid
# record NAME ARG...: a simulation's recorded command, as tools/run-simulation keeps it
record() { local d=$runs/$1; shift; mkdir -p "$d"; printf '%s\n' fluid.cfg "$@" > "$d/.args"; printf '%s\n' "$exp" > "$d/.cwd"; }
# stopped: interrupted by SIGTERM once it wrote a checkpoint (steps raised so that it cannot end first)
long=(--set equilibration=10 --set steps=1000000)
record stopped "${long[@]}"
(cd "$exp" && exec "$DPD" run fluid.cfg "${long[@]}" --out "$runs/stopped" --quiet --checkpoint-every 20) 2>/dev/null &
pid=$!; wait_for "$runs/stopped/checkpoint.dpd" $pid; sleep 0.2; kill -TERM $pid; wait $pid
# running: the same, left running while the tool looks
record running "${long[@]}"
(cd "$exp" && exec "$DPD" run fluid.cfg "${long[@]}" --out "$runs/running" --quiet --checkpoint-every 20) 2>/dev/null &
rpid=$!; wait_for "$runs/running/checkpoint.dpd" $rpid
# queued: recorded, never started; finished: has its summary; no-args: planned, nothing recorded yet
record queued --set equilibration=10 --set steps=200
record finished; : > "$runs/finished/summary.tsv"
mkdir -p "$runs/no-args"
# another tier's: quick
runs=$root/results/p/e/.quick.partial/runs record q; runs=$root/results/p/e/.paper.partial/runs

DPD_ROOT=$root DPD_BIN=$DPD "$tool" paper > "$tmp/out" 2> "$tmp/err"; st=$?
kill -TERM $rpid; wait $rpid 2>/dev/null
row() { awk -F'\t' -v n="$1" -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next } $3 == n { print $col[c] }' "$tmp/out"; }
if [ $st -eq 0 ] && [ ! -s "$tmp/err" ]; then ok "exit 0, nothing on stderr"; else bad "exit" "$st: $(cat "$tmp/err")"; fi
raw=$(od -An -t u8 -j 24 -N 8 "$runs/stopped/checkpoint.dpd" | tr -d ' ')
if [ "$(row stopped step)" = "$raw" ] && [ "$raw" -gt 0 ]; then ok "stopped: the checkpoint's step ($raw)"; else bad "stopped: step" "'$(row stopped step)' against the file's $raw"; fi
if [ "$(row stopped of)" = 1000010 ] && [ "$(row queued of)" = 210 ]; then ok "the steps each runs: equilibration + its recorded steps (1000010, 210)"
else bad "of" "'$(row stopped of)' '$(row queued of)'"; fi
if [ "$(row stopped state)" = stopped ] && [ "$(row running state)" = running ] && [ "$(row queued state)" = queued ] && [ "$(row no-args state)" = queued ]
then ok "states: stopped, running, queued, queued"; else bad "states" "$(cut -f3,8 "$tmp/out" | tr '\n' ' ')"; fi
if [ -z "$(row finished state)" ] && [ -z "$(row q state)" ] && [ "$(wc -l < "$tmp/out")" -eq 5 ]
then ok "a finished simulation and another tier's are not listed"; else bad "listing" "$(cut -f3 "$tmp/out" | tr '\n' ' ')"; fi
if [ "$(row stopped experiment)" = p/e ] && [ "$(row stopped tier)" = paper ]; then ok "experiment p/e, tier paper"; else bad "names" "$(head -2 "$tmp/out")"; fi
DPD_ROOT=$root DPD_BIN=$DPD "$tool" > "$tmp/all" 2>/dev/null
if grep -q $'^p/e\tquick\tq\t' "$tmp/all" && [ "$(wc -l < "$tmp/all")" -eq 6 ]; then ok "no tier: every tier's"; else bad "no tier" "$(cut -f2,3 "$tmp/all" | tr '\n' ' ')"; fi
# a corrupt checkpoint: exit 1, named
printf 'x' | dd of="$runs/stopped/checkpoint.dpd" bs=1 seek=100 conv=notrunc 2>/dev/null
DPD_ROOT=$root DPD_BIN=$DPD "$tool" paper > /dev/null 2> "$tmp/err"; st=$?
if [ $st -eq 1 ] && grep -q 'stopped/checkpoint.dpd is corrupt' "$tmp/err"; then ok "a corrupt checkpoint: exit 1, named"; else bad "corrupt" "$st: $(cat "$tmp/err")"; fi
# nothing in flight: the header alone
mkdir -p "$tmp/empty"
DPD_ROOT=$tmp/empty DPD_BIN=$DPD "$tool" > "$tmp/out" 2>&1; st=$?
if [ $st -eq 0 ] && [ "$(wc -l < "$tmp/out")" -eq 1 ]; then ok "nothing in flight: the header alone"; else bad "empty" "$st: $(cat "$tmp/out")"; fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
