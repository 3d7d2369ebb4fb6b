#!/bin/bash
# io_errors.sh - I/O failures never leave a result that looks complete:
#   - --out below a regular file, and on a read-only file system: status 4,
#     a message naming the directory;
#   - disk full at every stage of a run's output (a small tmpfs in a user +
#     mount namespace, `unshare -rm`, pre-filled by 4 KiB steps from "room for
#     everything" to "room for nothing"): each run either succeeds completely
#     (summary.tsv, provenance.tsv, run.h5, no INCOMPLETE) or exits 4 with a
#     "dpd: " message and leaves no summary.tsv, no run.h5 and no *.part
#     file of a text result; at least three distinct failure messages (stages)
#     must be seen, so the sweep has power;
#   - a checkpoint that does not fit: status 4, "cannot write the checkpoint",
#     no half-written checkpoint left;
#   - a failed rerun into a directory that holds a finished result (unstable,
#     SIGTERM, a refused checkpoint, disk full) leaves none of the old result
#     files beside INCOMPLETE: a run removes them when it starts (for scenes
#     writing every table: each file of the finished run must be gone, or be
#     one a failed run keeps: INCOMPLETE, its checkpoint, run.h5.part); a
#     resumed run keeps its checkpoint and completes;
#   - two writers on one --out: the second is refused (status 4) with a message
#     naming the holder (pid, host, start time), also with
#     HDF5_USE_FILE_LOCKING=FALSE (the lock is dpd's own, not HDF5's), and the
#     first completes untouched; a lock left by a SIGKILLed run is free again.
# Without unprivileged namespaces the tmpfs checks are reported as SKIP and
# counted as skipped, not passed: "N passed, M failed, 1 skipped" (tests/skips.sh).
# IO_ERRORS_PART=namespace runs only the namespace part (what tests/skips.sh needs).
# DPD selects the binary. Prints "N passed, M failed[, K skipped]".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh io-errors
scene=$PWD/tests/good-scene.cfg

# IO_ERRORS_PART=namespace: only the part from the namespace check on (tests/skips.sh tests
# how that part reports a machine without namespaces; it needs none of the checks before it)
if [ "${IO_ERRORS_PART:-all}" != namespace ]; then
# --out below a regular file
touch "$tmp/file"
"$DPD" run "$scene" --out "$tmp/file/out" --quiet 2>"$tmp/err"; st=$?
if [ $st -eq 4 ] && grep -q "cannot create or write the output directory '$tmp/file/out'" "$tmp/err"; then ok "out below a file: status 4, named"
else bad "out below a file" "status $st: $(cat "$tmp/err")"; fi

# a failed rerun over a finished result
result_files() { ls -A "$1" 2>/dev/null | grep -vxE 'INCOMPLETE|checkpoint\.dpd|run\.h5\.part|\.dpd-run\.lock' || true; }
rerun_leaves_no_result() {   # NAME DIR STATUS WANT: the rerun into DIR exited STATUS, WANT expected
    local left; left=$(result_files "$2" | tr '\n' ' ')
    if [ "$3" -eq "$4" ] && [ -e "$2/INCOMPLETE" ] && [ -z "$left" ]; then ok "$1: status $4, INCOMPLETE, no old result file"
    else bad "$1" "status $3 (want $4), INCOMPLETE $([ -e "$2/INCOMPLETE" ] && echo present || echo missing), left: $left"; fi
}
d=$tmp/rerun
"$DPD" run "$scene" --out "$d" --quiet 2>"$tmp/err" || bad "rerun: first run" "$(cat "$tmp/err")"
"$DPD" run "$scene" --out "$d" --quiet --set dt=0.5 --set steps=2000 2>"$tmp/err"; st=$?
rerun_leaves_no_result "unstable rerun over a finished result" "$d" $st 3
rm -rf "$d"
"$DPD" run "$scene" --out "$d" --quiet 2>"$tmp/err" || bad "rerun: first run" "$(cat "$tmp/err")"
"$DPD" run "$scene" --out "$d" --quiet --set steps=20000 --checkpoint-every 500 2>"$tmp/err" & pid=$!
wait_for "$d/checkpoint.dpd" $pid; kill -TERM $pid 2>/dev/null; wait $pid; st=$?
rerun_leaves_no_result "SIGTERM rerun over a finished result" "$d" $st 143
"$DPD" run "$scene" --out "$d" --quiet --set steps=20000 --checkpoint-every 500 --resume 2>"$tmp/err"; st=$?
if [ $st -eq 0 ] && [ -s "$d/summary.tsv" ] && [ ! -e "$d/INCOMPLETE" ] && [ ! -e "$d/checkpoint.dpd" ] \
   && grep -q '^resumed_at_step' "$d/provenance.tsv"; then
    ok "the interrupted rerun resumes from the checkpoint it kept and completes"
else bad "the interrupted rerun resumes" "status $st: $(cat "$tmp/err") $(ls -A "$d" | tr '\n' ' ')"; fi
# every table of the modules: the finished run's files all gone after a rerun refused at its checkpoint
for entry in tests/checkpoint-overdamped.cfg tests/checkpoint-colloids2d.cfg tests/checkpoint-tcaf.cfg \
             tests/checkpoint-shear.cfg "experiments/phan-thien-2016/fig08-compressibility/cylinder-m1.cfg --set steps=50 --set equilibration=10"; do
    read -r -a a <<< "$entry"
    rm -rf "$d"
    "$DPD" run "${a[@]}" --out "$d" --quiet 2>"$tmp/err" || { bad "rerun of ${a[0]}: first run" "$(cat "$tmp/err")"; continue; }
    before=$(ls -A "$d" | tr '\n' ' ')
    echo "not a checkpoint" > "$d/checkpoint.dpd"
    "$DPD" run "${a[@]}" --out "$d" --quiet --resume 2>"$tmp/err"; st=$?
    rerun_leaves_no_result "rerun of $(basename "${a[0]}") refused at its checkpoint (finished run had: $before)" "$d" $st 2
done

# two writers on one output directory
for locking in default FALSE; do
    d=$tmp/two-$locking
    env_lock=(); [ $locking = FALSE ] && env_lock=(HDF5_USE_FILE_LOCKING=FALSE)
    env "${env_lock[@]}" "$DPD" run "$scene" --out "$d" --quiet --set steps=6000 2>"$tmp/err1" & pid=$!
    wait_for "$d/INCOMPLETE" $pid
    env "${env_lock[@]}" "$DPD" run "$scene" --out "$d" --quiet --set steps=10 2>"$tmp/err2"; st2=$?
    wait $pid; st1=$?
    if [ $st2 -eq 4 ] && grep -q "dpd: '$d' is in use by another run: pid $pid on $(hostname) since 20[0-9-]*T[0-9:]*Z" "$tmp/err2" \
       && [ $st1 -eq 0 ] && [ "$(awk -F'\t' '$1 == "steps" { print $2 }' "$d/summary.tsv")" = 6000 ] && [ ! -e "$d/INCOMPLETE" ]; then
        ok "second writer on one --out (HDF5 file locking $locking): refused naming the holder; the first completes"
    else bad "second writer on one --out (HDF5 file locking $locking)" "first: status $st1 $(head -2 "$tmp/err1"); second: status $st2 $(head -2 "$tmp/err2"); $(ls -A "$d" | tr '\n' ' ')"; fi
done
d=$tmp/killed
"$DPD" run "$scene" --out "$d" --quiet --set steps=200000 2>/dev/null & pid=$!
wait_for "$d/INCOMPLETE" $pid; kill -KILL $pid; wait $pid 2>/dev/null
"$DPD" run "$scene" --out "$d" --quiet 2>"$tmp/err"; st=$?
if [ $st -eq 0 ] && [ -s "$d/summary.tsv" ]; then ok "the lock of a SIGKILLed run is free again"
else bad "the lock of a SIGKILLed run is free again" "status $st: $(cat "$tmp/err")"; fi
fi

if ! unshare -rm true 2>/dev/null; then
    echo "SKIP tmpfs checks: no unprivileged user/mount namespaces here (read-only file system, disk full at every stage, checkpoint and trajectory on a full disk)"
    echo "$pass passed, $fail failed, 1 skipped"; [ $fail -eq 0 ]; exit
fi

# everything below runs inside a namespace with its own tmpfs mounts; it
# prints PASS/FAIL lines itself
DPD=$DPD scene=$scene T=$tmp unshare -rm bash -c '
set -u
ok()  { echo "PASS $1"; }
bad() { echo "FAIL $1: $2"; }
mnt=$T/mnt; mkdir -p "$mnt"
# sweep LABEL FROM STEP COMPLETE ARGS...: dpd run with ARGS on the tmpfs at $mnt
# pre-filled by FROM, FROM + STEP, ... KiB up to $free_kb: each run either is
# complete (COMPLETE DIR) or exits 4 with a "dpd: " message and leaves no
# result and no *.part file. Sets sweep_ok and stages ("stage|message" lines).
complete_plain() { [ -s "$1/summary.tsv" ] && [ -s "$1/provenance.tsv" ] && [ -s "$1/run.h5" ] && [ ! -e "$1/INCOMPLETE" ]; }
complete_traj()  { [ -s "$1/summary.tsv" ] && [ -s "$1/run.h5" ] && [ ! -e "$1/INCOMPLETE" ] && ! ls -a "$1" | grep -q trajectory-; }
sweep() {
    local label=$1 from=$2 step=$3 complete=$4 fill st msg d=$mnt/out; shift 4
    stages="" sweep_ok=1
    for fill in $(seq "$from" "$step" "$free_kb"); do
        rm -rf "$mnt"/*
        head -c "${fill}k" /dev/zero > "$mnt/filler" 2>/dev/null
        "$DPD" run "$scene" "$@" --out "$d" 2>"$T/err"; st=$?
        if [ $st -eq 0 ]; then
            $complete "$d" || { bad "${label}disk full, ${fill} KiB filled" "status 0 but the result is not complete (or segments left)"; sweep_ok=0; }
        elif [ $st -eq 4 ]; then
            msg=$(grep -m1 "^dpd: " "$T/err" | sed "s|$mnt|MNT|g")
            if [ -z "$msg" ] || [ -e "$d/summary.tsv" ] || [ -e "$d/run.h5" ] || ls "$d"/.*.part >/dev/null 2>&1 \
               || grep -q "runtime error\|Sanitizer" "$T/err"; then
                bad "${label}disk full, ${fill} KiB filled" "a result or *.part was left, or no message: $(ls -a "$d" 2>/dev/null | tr "\n" " ") $(head -3 "$T/err")"; sweep_ok=0
            fi
            stages="$stages${msg%%:*}|${msg#*: }
"
        else
            bad "${label}disk full, ${fill} KiB filled" "status $st: $(head -5 "$T/err")"; sweep_ok=0
        fi
    done
}
# read-only file system
mount -t tmpfs -o size=1m,ro tmpfs "$mnt" || { bad mount "cannot mount tmpfs"; exit 0; }
"$DPD" run "$scene" --out "$mnt/out" --quiet 2>"$T/err"; st=$?
if [ $st -eq 4 ] && grep -q "cannot create or write the output directory" "$T/err"; then ok "read-only file system: status 4, named"
else bad "read-only file system" "status $st: $(cat "$T/err")"; fi
umount "$mnt"
# disk full at every stage
mount -t tmpfs -o size=512k tmpfs "$mnt"
free_kb=$(df -k --output=avail "$mnt" | tail -1)
"$DPD" run "$scene" --out "$mnt/out" --quiet 2>"$T/err"; st=$?
need_kb=$(du -sk "$mnt/out" | cut -f1)
if [ $st -eq 0 ]; then ok "disk-full control: the run fits an empty tmpfs"; else bad "disk-full control" "status $st"; fi
rm -rf "$mnt/out"
sweep "" $((free_kb - need_kb - 8)) 4 complete_plain --quiet
nst=$(printf "%s" "$stages" | sed "/^$/d" | sed "s/[0-9]* bytes//" | sort -u | wc -l)
[ $sweep_ok = 1 ] && ok "disk full at every stage: complete result or status 4 with no result"
if [ "$nst" -ge 3 ]; then ok "disk full sweep reached $nst distinct failure stages"
else bad "disk full sweep" "only $nst failure stages: $stages"; fi
printf "%s" "$stages" | sed "/^$/d" | sort -u | sed "s/^/    stage: /"
# a checkpoint that does not fit
umount "$mnt"; mount -t tmpfs -o size=160k tmpfs "$mnt"
"$DPD" run "$PWD/tests/checkpoint-shear.cfg" --out "$mnt/ck" --quiet --checkpoint-every 20 2>"$T/err"; st=$?
if [ $st -eq 4 ] && grep -q "cannot write the checkpoint" "$T/err" && [ ! -e "$mnt/ck/summary.tsv" ] \
   && [ ! -e "$mnt/ck/.checkpoint.dpd.part" ] && [ -e "$mnt/ck/INCOMPLETE" ]; then ok "checkpoint on a full disk: status 4, named, no result, no partial checkpoint"
else bad "checkpoint on a full disk" "status $st: $(cat "$T/err") $(ls -a "$mnt/ck" | tr "\n" " ")"; fi
umount "$mnt"
# a trajectory (segment files closed at each checkpoint, copied into run.h5 at
# the end) with checkpoints on a disk that fills at every stage
mount -t tmpfs -o size=1m tmpfs "$mnt"
targs=(--set steps=20 --set "output={trajectory_every=5;}" --checkpoint-every 10 --quiet)
free_kb=$(df -k --output=avail "$mnt" | tail -1)
"$DPD" run "$scene" "${targs[@]}" --out "$mnt/out" 2>"$T/err"; st=$?
if [ $st -eq 0 ] && [ "$(h5ls "$mnt/out/run.h5/particles/all/position/step" | tr -s " ")" = "step Dataset {4/Inf}" ]; then
    ok "trajectory disk-full control: 4 frames in run.h5"
else bad "trajectory disk-full control" "status $st: $(head -3 "$T/err")"; fi
rm -rf "$mnt/out"
sweep "trajectory, " $((free_kb - 320)) 20 complete_traj "${targs[@]}"
nst=$(printf "%s" "$stages" | sed "/^$/d" | sed "s/[0-9]* bytes//" | sort -u | wc -l)
[ $sweep_ok = 1 ] && ok "trajectory, disk full at every stage: complete result or status 4 with no result"
if printf "%s" "$stages" | grep -q "trajectory segment"; then ok "trajectory disk-full sweep reached the segment commit ($nst stages)"
else bad "trajectory disk-full sweep" "never failed at a segment commit: $stages"; fi
printf "%s" "$stages" | sed "/^$/d" | sed "s/[0-9]* bytes//" | sort -u | sed "s/^/    stage: /"
umount "$mnt"
# a rerun over a finished result on a disk that is full by then
mount -t tmpfs -o size=1m tmpfs "$mnt"
"$DPD" run "$scene" --out "$mnt/out" --quiet 2>"$T/err" || bad "disk-full rerun: first run" "$(cat "$T/err")"
head -c 2m /dev/zero > "$mnt/filler" 2>/dev/null
"$DPD" run "$scene" --out "$mnt/out" --quiet --set steps=20 --set "output={trajectory_every=5;}" 2>"$T/err"; st=$?
left=$(ls -A "$mnt/out" | grep -vxE "INCOMPLETE|checkpoint\.dpd|run\.h5\.part|\.dpd-run\.lock" | tr "\n" " ")
if [ $st -eq 4 ] && [ -z "$left" ]; then ok "disk-full rerun over a finished result: status 4, no old result file"
else bad "disk-full rerun over a finished result" "status $st, left: $left; $(head -2 "$T/err")"; fi
umount "$mnt"
' > "$tmp/ns.log" 2>&1
cat "$tmp/ns.log"
pass=$((pass + $(grep -c '^PASS' "$tmp/ns.log")))
fail=$((fail + $(grep -c '^FAIL' "$tmp/ns.log")))
grep -q '^PASS disk full at every stage' "$tmp/ns.log" || { bad "namespace checks" "did not finish"; }
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
