#!/bin/bash
# checkpoint.sh - checkpoint/restart and interrupted runs, end to end:
# for each scene (tests/checkpoint-shear.cfg: Lees-Edwards shear, profile, RDF,
# MSD; tests/checkpoint-overdamped.cfg: m = 0 with a warm-started PCG solve;
# tests/checkpoint-colloids2d.cfg: 2D spring colloids; tests/checkpoint-
# rotation.cfg: spinning particles; tests/checkpoint-colloids3d.cfg: 3D rigid
# colloid bodies; tests/checkpoint-tcaf.cfg: TCAF time origins)
#   ref   uninterrupted run, no checkpoints
#   kill  run with --checkpoint-every, SIGKILLed at a random moment after its
#         first checkpoint exists (mid-step, mid-write or between checkpoints),
#         must leave INCOMPLETE and no summary.tsv; then --resume
#   term  SIGTERM: status 143, a checkpoint, INCOMPLETE; then --resume
# Threads (ref kill resume): 1 1 2 (results do not depend on the thread count;
# 2 2 2 for the TCAF scene, which test_threads checks on 1 and 2 threads).
# The resumed m = 0 run keeps every solver CPU-time sample (solver.tsv cpu_seconds, issue 24).
# Every resumed run must equal ref bit for bit: /results/final_state
# (positions, images, velocities by particle id) and the time series (/series) of run.h5
# by h5diff (exact), profile/rdf/msd tables by cmp, summary.tsv without its
# timing rows. Trajectory output (H5MD) across a SIGKILL and a SIGTERM: the
# resumed /particles equal the uninterrupted ones (no frame lost or doubled).
# The harness (tools/lib/exp.sh dpd_run) with the real simulator killed in the
# middle of a rotation, a 3D colloid and a TCAF run: no result for make check,
# then a resume that equals the uninterrupted runs. Controls with power:
# another seed must differ (h5diff sees it); a truncated checkpoint, one of
# another scene, one of a future format, a missing trajectory segment, and
# --resume with nothing to resume are handled. DPD selects the binary.
# Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh checkpoint
check() { local name=$1; shift; if "$@"; then ok "$name"; else bad "$name" "$*"; fi; }

physics() { grep -Ev 'seconds|per_second|memory' "$1"; }
same_run() {   # same_run REF DIR: bit-identical results
    local r=$1 d=$2 t
    [ -s "$d/summary.tsv" ] && [ ! -e "$d/INCOMPLETE" ] || { echo "  $d: no complete result"; return 1; }
    h5diff -q "$r/run.h5" "$d/run.h5" /results/final_state || { echo "  final_state differs"; return 1; }
    h5diff -q "$r/run.h5" "$d/run.h5" /series || { echo "  time series differ"; return 1; }
    for t in profile rdf msd around density_map colloid_msd colloid_around colloid_rdf tcaf tcaf_eta tcaf_extrapolation; do
        [ -e "$r/$t.tsv" ] || continue
        cmp -s "$r/$t.tsv" "$d/$t.tsv" || { echo "  $t.tsv differs"; return 1; }
    done
    diff <(physics "$r/summary.tsv") <(physics "$d/summary.tsv") >/dev/null || { echo "  summary.tsv differs"; return 1; }
}
incomplete() { [ -e "$1/INCOMPLETE" ] && [ ! -e "$1/summary.tsv" ] && [ ! -e "$1/run.h5" ]; }
# cpu_samples DIR: the m = 0 solver's CPU-time samples in solver.tsv (rows whose cpu_seconds is a number)
cpu_samples() { awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "cpu_seconds") c = i; next }
                              c && $c != "nan" && $c != "" { n++ } END { print n + 0 }' "$1/solver.tsv" 2>/dev/null; }
same_cpu_samples() {   # same_cpu_samples REF DIR: as many as the uninterrupted run, one per production step
    local r d; r=$(cpu_samples "$1") d=$(cpu_samples "$2")
    [ "$r" -gt 0 ] && [ "$r" = "$d" ] || { echo "  cpu_seconds samples: $d, uninterrupted $r"; return 1; }
}

# kill_later DIR PID SIG: SIG once DIR has a checkpoint, after 0-30 ms more
kill_later() { wait_for "$1/checkpoint.dpd" "$2"; sleep "0.0$((RANDOM % 4))"; kill -"$3" "$2" 2>/dev/null; }

for spec in "shear 1 1 2" "overdamped 1 1 2" "colloids2d 1 1 2" "rotation 1 1 2" "colloids3d 1 1 2" "tcaf 2 2 2"; do
    read -r s tref tkill tres <<< "$spec"
    scene=tests/checkpoint-$s.cfg s=checkpoint-$s
    "$DPD" run "$scene" --out "$tmp/$s-ref" --threads "$tref" --quiet 2>"$tmp/err"
    check "$s: reference run ($tref threads)" test $? -eq 0

    # SIGKILL at a random moment after the first checkpoint, resume on $tres threads
    # (a run that ended before the signal landed, on a loaded machine, tested
    # nothing: it is repeated, up to three times)
    for attempt in 1 2 3; do
        rm -rf "$tmp/$s-kill"
        "$DPD" run "$scene" --out "$tmp/$s-kill" --threads "$tkill" --quiet --checkpoint-every 20 2>"$tmp/err" &
        pid=$!
        kill_later "$tmp/$s-kill" $pid KILL
        wait $pid 2>/dev/null; st=$?
        [ $st -eq 0 ] || break
    done
    check "$s: SIGKILL (status $st) leaves INCOMPLETE, no result" test $st -eq 137 -a -e "$tmp/$s-kill/INCOMPLETE" -a ! -e "$tmp/$s-kill/summary.tsv"
    "$DPD" run "$scene" --out "$tmp/$s-kill" --threads "$tres" --checkpoint-every 20 --resume 2>"$tmp/err"
    st=$?
    check "$s: resume after SIGKILL (status $st)" test $st -eq 0
    check "$s: the resume started from a checkpoint" grep -q 'dpd: resuming .* at step [1-9]' "$tmp/err"
    check "$s: killed ($tkill threads) + resumed ($tres threads) = uninterrupted, bit for bit" same_run "$tmp/$s-ref" "$tmp/$s-kill"
    [ $s = checkpoint-overdamped ] && check "$s: SIGKILL + resumed keeps every solver CPU-time sample" same_cpu_samples "$tmp/$s-ref" "$tmp/$s-kill"
    check "$s: no checkpoint left after completion" test ! -e "$tmp/$s-kill/checkpoint.dpd"

    # SIGTERM: checkpoint written at the end of the current step
    for attempt in 1 2 3; do
        rm -rf "$tmp/$s-term"
        "$DPD" run "$scene" --out "$tmp/$s-term" --threads "$tkill" --quiet --checkpoint-every 20 2>"$tmp/err" &
        pid=$!
        for _ in $(seq 6000); do [ -e "$tmp/$s-term/checkpoint.dpd" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.01; done
        kill -TERM $pid 2>/dev/null
        wait $pid; st=$?
        [ $st -eq 0 ] || break
    done
    check "$s: SIGTERM gives status 143, a checkpoint and INCOMPLETE" \
        test $st -eq 143 -a -s "$tmp/$s-term/checkpoint.dpd" -a -e "$tmp/$s-term/INCOMPLETE" -a ! -e "$tmp/$s-term/summary.tsv"
    grep -q 'stopped by signal 15 at step' "$tmp/err"
    check "$s: SIGTERM message" test $? -eq 0
    "$DPD" run "$scene" --out "$tmp/$s-term" --threads "$tres" --quiet --resume 2>"$tmp/err"
    check "$s: resume after SIGTERM" test $? -eq 0
    check "$s: SIGTERM + resumed = uninterrupted, bit for bit" same_run "$tmp/$s-ref" "$tmp/$s-term"
    [ $s = checkpoint-overdamped ] && check "$s: SIGTERM + resumed keeps every solver CPU-time sample" same_cpu_samples "$tmp/$s-ref" "$tmp/$s-term"
done

s=checkpoint-shear scene=tests/checkpoint-shear.cfg
# power: a different seed must be seen as different
"$DPD" run "$scene" --set seed=8 --out "$tmp/seed8" --threads 1 --quiet 2>/dev/null
check "control: another seed differs" bash -c "! h5diff -q '$tmp/$s-ref/run.h5' '$tmp/seed8/run.h5' /results/final_state"
# --resume with no checkpoint runs from the start
"$DPD" run "$scene" --out "$tmp/fresh" --threads 1 --quiet --resume 2>/dev/null
check "--resume without a checkpoint = a fresh run" same_run "$tmp/$s-ref" "$tmp/fresh"
# --checkpoint-wall: periodic checkpoints wait for the wall-clock floor (none
# within 1 s at a 1e6 s floor, though one is due every step), a signal's
# checkpoint does not (its content does not depend on the floor: the resume
# tests above cover it); control: floor 0
declare -A ckw
for w in 1e6 0; do
    rm -rf "$tmp/wall$w"
    "$DPD" run "$scene" --set steps=1000000 --out "$tmp/wall$w" --threads 1 --quiet --checkpoint-every 1 --checkpoint-wall $w 2>/dev/null &
    pid=$!; wait_for "$tmp/wall$w/INCOMPLETE" $pid
    if [ "$w" = 0 ]; then wait_for "$tmp/wall$w/checkpoint.dpd" $pid; else sleep 1; fi
    if [ -e "$tmp/wall$w/checkpoint.dpd" ]; then ckw[$w]=yes; else ckw[$w]=no; fi
    kill -KILL $pid; wait $pid 2>/dev/null
done
check "--checkpoint-wall 1e6: no periodic checkpoint within 1 s" test "${ckw[1e6]}" = no
check "--checkpoint-wall 0 (control): periodic checkpoints written" test "${ckw[0]}" = yes
# (a long run, signalled 0.5 s after it started: the handler is installed once setup is done)
rm -rf "$tmp/wallterm"
"$DPD" run "$scene" --set steps=1000000 --out "$tmp/wallterm" --threads 1 --quiet --checkpoint-every 1 --checkpoint-wall 1e6 2>/dev/null &
pid=$!; wait_for "$tmp/wallterm/INCOMPLETE" $pid; sleep 0.5; kill -TERM $pid; wait $pid; st=$?
check "--checkpoint-wall: SIGTERM still writes a checkpoint (status $st)" test $st -eq 143 -a -s "$tmp/wallterm/checkpoint.dpd"
# a truncated or foreign checkpoint is refused, nothing accepted
rm -rf "$tmp/trunc"
"$DPD" run "$scene" --out "$tmp/trunc" --threads 1 --quiet --checkpoint-every 20 2>/dev/null &
pid=$!; for _ in $(seq 6000); do [ -e "$tmp/trunc/checkpoint.dpd" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.01; done
kill -TERM $pid; wait $pid
cp -r "$tmp/trunc" "$tmp/foreign"
# dpd checkpoint-info: how far the interrupted run got, as the file says it (the step read directly
# at its offset 24, after the 24-byte header; the time, step x dt; the particles, the header's count)
info() { "$DPD" checkpoint-info "$1" 2>/dev/null | awk -F'\t' -v q="$2" '$1 == q { print $2 }'; }
raw_step=$(od -An -t u8 -j 24 -N 8 "$tmp/trunc/checkpoint.dpd" | tr -d ' ')
raw_n=$(od -An -t u4 -j 20 -N 4 "$tmp/trunc/checkpoint.dpd" | tr -d ' ')
check "checkpoint-info: the step ($(info "$tmp/trunc" step), where SIGTERM stopped it) is the file's" \
    test "$(info "$tmp/trunc" step)" = "$raw_step" -a "$raw_step" -gt 0
check "checkpoint-info: the time is step x dt, the particles the header's" \
    awk -v t="$(info "$tmp/trunc/checkpoint.dpd" time)" -v s="$raw_step" -v dt="$(awk '/^dt/ { gsub(/[^0-9.e-]/, "", $3); print $3 }' "$scene")" \
        -v n="$(info "$tmp/trunc" particles)" -v rn="$raw_n" 'BEGIN { exit !(t > 0 && (t - s * dt) ^ 2 < 1e-18 && n == rn && n > 0) }'
"$DPD" checkpoint-info "$tmp" 2>"$tmp/err"; st=$?
check "checkpoint-info: no checkpoint there, status 2, named" bash -c "[ $st -eq 2 ] && grep -q 'no checkpoint $tmp/checkpoint.dpd' '$tmp/err'"
"$DPD" checkpoint-info "$scene" 2>"$tmp/err"; st=$?
check "checkpoint-info: a scene file is not a checkpoint, status 2" bash -c "[ $st -eq 2 ] && grep -q 'is not a dpd checkpoint' '$tmp/err'"
# the checksum is summed over the file in 64 KiB chunks, the last 8 bytes (the stored sum) held
# back: files of the real header (magic to time, 40 bytes), zero padding and their sum (reseal), of
# every size that splits the sum across a chunk boundary, at one and on either side, are read; a
# byte flipped in the padding just before the sum, or in the sum, is corrupt
cut_ok=0 cut_bad=""
for size in 48 65535 65536 65537 65538 65539 65540 65541 65542 65543 65544 65545 131075; do
    f=$tmp/cut$size.dpd
    { head -c 40 "$tmp/trunc/checkpoint.dpd"; head -c $((size - 40)) /dev/zero; } > "$f"
    reseal "$f" ""
    if [ "$(info "$f" step)" = "$raw_step" ]; then cut_ok=$((cut_ok + 1)); else cut_bad="$cut_bad $size"; fi
    cp "$f" "$f.pad"; printf '\001' | dd of="$f.pad" bs=1 seek=$((size - 9)) conv=notrunc 2>/dev/null
    cp "$f" "$f.sum"; printf '\001' | dd of="$f.sum" bs=1 seek=$((size - 4)) conv=notrunc 2>/dev/null
    for g in "$f.pad" "$f.sum"; do
        "$DPD" checkpoint-info "$g" > /dev/null 2> "$tmp/err" && cut_bad="$cut_bad $size:${g##*.}-accepted"
        grep -q 'is corrupt' "$tmp/err" || cut_bad="$cut_bad $size:${g##*.}-message"
    done
done
check "checkpoint-info: 13 file sizes around the 64 KiB read boundary read, and each with a byte flipped before or in the sum corrupt ($cut_ok read;${cut_bad:- none wrong})" \
    test "$cut_ok" = 13 -a -z "$cut_bad"
truncate -s 1000 "$tmp/trunc/checkpoint.dpd"
"$DPD" checkpoint-info "$tmp/trunc" 2>"$tmp/err"; st=$?
check "checkpoint-info: a truncated checkpoint, status 2, corrupt" bash -c "[ $st -eq 2 ] && grep -q 'checkpoint.dpd is corrupt' '$tmp/err'"
"$DPD" run "$scene" --out "$tmp/trunc" --quiet --resume 2>"$tmp/err"; st=$?
check "truncated checkpoint: status 2, named, no result" test $st -eq 2 -a ! -e "$tmp/trunc/summary.tsv"
check "truncated checkpoint: message" grep -q 'checkpoint.dpd is corrupt' "$tmp/err"
"$DPD" run "$scene" --set pairs.[0].a=26.0 --out "$tmp/foreign" --quiet --resume 2>"$tmp/err"; st=$?
check "checkpoint of another scene: status 2, no result" test $st -eq 2 -a ! -e "$tmp/foreign/summary.tsv"
check "checkpoint of another scene: message" grep -q 'written for another scene' "$tmp/err"

# checkpoint format versions: a version 1, 2 or 3 file of a scene without MSD,
# spins, rigid bodies, TCAF, trajectory, shear or m = 0 solver (the shear scene
# without its MSD and its shear) still resumes (same layout); one of a rotation
# scene cannot (version 1 had no spins), nor a version 2 one of an MSD scene
# (version 3 keeps the MSD per particle group), nor a version 3 one of an m = 0
# scene (version 4 keeps the solver's CPU time per step) or of a sheared scene
# (version 4 counts the offset's wraps in the image counters), nor one of a
# future format (reseal: tests/shlib.sh); version 5 only adds the trajectory
# segments' checksums (a version 4 one of a trajectory scene is refused below)
sed '/msd = {/d; s/rdf = { rmax = 1.0; bins = 20; every = 10; };/&  };/' "$scene" > "$tmp/plain.cfg"
still=(--set shear_rate=0.0)
"$DPD" run "$tmp/plain.cfg" "${still[@]}" --out "$tmp/plain-ref" --threads 1 --quiet 2>"$tmp/err"
check "plain scene (no MSD, no shear): reference run" test $? -eq 0
rm -rf "$tmp/old"
"$DPD" run "$tmp/plain.cfg" "${still[@]}" --out "$tmp/old" --threads 1 --quiet --checkpoint-every 20 2>/dev/null &
pid=$!; wait_for "$tmp/old/checkpoint.dpd" $pid; kill -TERM $pid; wait $pid
for v in 5 4 3 2 1; do
    rm -rf "$tmp/v$v"; cp -r "$tmp/old" "$tmp/v$v"
    reseal "$tmp/v$v/checkpoint.dpd" $v
    "$DPD" run "$tmp/plain.cfg" "${still[@]}" --out "$tmp/v$v" --threads 1 --quiet --resume 2>"$tmp/err"
done
check "reseal control: the rewritten version 5 checkpoint resumes (checksum right)" same_run "$tmp/plain-ref" "$tmp/v5"
for v in 4 3 2 1; do
    check "version $v checkpoint of a scene without MSD, shear or m = 0: resumes, bit for bit" same_run "$tmp/plain-ref" "$tmp/v$v"
done
# refused_version NAME SCENE DIR VERSION: the checkpoint in DIR resealed as VERSION is refused
refused_version() {
    reseal "$3/checkpoint.dpd" $4
    "$DPD" run "$2" --out "$3" --quiet --resume 2>"$tmp/err"; st=$?
    check "version $4 checkpoint of $1: status 2, no result" test $st -eq 2 -a ! -e "$3/summary.tsv"
    check "version $4 checkpoint of $1: message" grep -q "format version $4, which this dpd (format 5) cannot resume" "$tmp/err"
}
rm -rf "$tmp/v2m"; cp -r "$tmp/foreign" "$tmp/v2m"
refused_version "an MSD scene" "$scene" "$tmp/v2m" 2
c=checkpoint-colloids2d
rm -rf "$tmp/v3m0"
"$DPD" run tests/$c.cfg --out "$tmp/v3m0" --threads 1 --quiet --checkpoint-every 20 2>/dev/null &
pid=$!; wait_for "$tmp/v3m0/checkpoint.dpd" $pid; kill -TERM $pid; wait $pid
refused_version "an m = 0 scene" tests/$c.cfg "$tmp/v3m0" 3
rm -rf "$tmp/v3s"
"$DPD" run "$tmp/plain.cfg" --out "$tmp/v3s" --threads 1 --quiet --checkpoint-every 20 2>/dev/null &
pid=$!; wait_for "$tmp/v3s/checkpoint.dpd" $pid; kill -TERM $pid; wait $pid
refused_version "a sheared scene" "$tmp/plain.cfg" "$tmp/v3s" 3
rm -rf "$tmp/v1r" "$tmp/v6"
"$DPD" run tests/checkpoint-rotation.cfg --out "$tmp/v1r" --threads 1 --quiet --checkpoint-every 20 2>/dev/null &
pid=$!; wait_for "$tmp/v1r/checkpoint.dpd" $pid; kill -TERM $pid; wait $pid
cp -r "$tmp/v1r" "$tmp/v6"
refused_version "a rotation scene" tests/checkpoint-rotation.cfg "$tmp/v1r" 1
reseal "$tmp/v6/checkpoint.dpd" 6
"$DPD" run tests/checkpoint-rotation.cfg --out "$tmp/v6" --quiet --resume 2>"$tmp/err"; st=$?
check "future checkpoint format: status 2, no result" test $st -eq 2 -a ! -e "$tmp/v6/summary.tsv"
check "future checkpoint format: message" grep -q 'format version 6' "$tmp/err"

# trajectory output (H5MD) across interruptions: frames go to segment files
# closed at each checkpoint and are copied into run.h5 when the run completes
frames() { h5ls -d "$1/run.h5/particles/all/position/step" | tail -n +3 | tr -d ' \n'; }
segments_gone() { ! ls -a "$1" | grep -q 'trajectory-'; }
traj=(--set 'output={trajectory_every=30;}')
"$DPD" run "$scene" "${traj[@]}" --out "$tmp/traj-ref" --threads 1 --quiet 2>"$tmp/err"
check "trajectory: uninterrupted run" test $? -eq 0
check "trajectory: frames at steps 30, 60, ..., 450" test "$(frames "$tmp/traj-ref")" = "$(seq -s, 30 30 450)"
check "trajectory: same physics as without it" same_run "$tmp/$s-ref" "$tmp/traj-ref"
check "trajectory: no segment files left" segments_gone "$tmp/traj-ref"
for sig in KILL TERM; do
    d=$tmp/traj-$sig
    "$DPD" run "$scene" "${traj[@]}" --out "$d" --threads 1 --quiet --checkpoint-every 20 2>"$tmp/err" &
    pid=$!
    kill_later "$d" $pid $sig
    wait $pid 2>/dev/null; st=$?
    check "trajectory: SIG$sig (status $st) leaves no run.h5, no result" test $st -gt 128 -a ! -e "$d/run.h5" -a ! -e "$d/summary.tsv"
    : > "$d/trajectory-0099.h5"; : > "$d/.trajectory-0098.h5.part"   # stale leftovers
    "$DPD" run "$scene" "${traj[@]}" --out "$d" --threads 1 --checkpoint-every 20 --resume 2>"$tmp/err"
    check "trajectory: resume after SIG$sig" test $? -eq 0
    grep -q 'resuming .* at step [1-9]' "$tmp/err"
    check "trajectory: SIG$sig resume started from a checkpoint" test $? -eq 0
    check "trajectory: SIG$sig + resumed frames = uninterrupted (none lost or doubled)" test "$(frames "$d")" = "$(frames "$tmp/traj-ref")"
    check "trajectory: SIG$sig + resumed /particles = uninterrupted, bit for bit" h5diff -q "$tmp/traj-ref/run.h5" "$d/run.h5" /particles
    check "trajectory: SIG$sig + resumed results = uninterrupted" same_run "$tmp/traj-ref" "$d"
    check "trajectory: SIG$sig segments (stale ones too) removed" segments_gone "$d"
done
# a segment of the checkpoint that went missing: refused, nothing accepted
d=$tmp/traj-lost
"$DPD" run "$scene" "${traj[@]}" --out "$d" --threads 1 --quiet --checkpoint-every 20 2>/dev/null &
pid=$!; wait_for "$d/trajectory-0000.h5" $pid; wait_for "$d/trajectory-0001.h5" $pid; kill -TERM $pid; wait $pid
rm -f "$d/trajectory-0000.h5"
"$DPD" run "$scene" "${traj[@]}" --out "$d" --quiet --resume 2>"$tmp/err"; st=$?
check "trajectory: missing segment: status 2, no result" test $st -eq 2 -a ! -e "$d/summary.tsv" -a ! -e "$d/run.h5"
check "trajectory: missing segment: message" grep -q 'trajectory segment .*trajectory-0000.h5 of the checkpoint is missing' "$tmp/err"
# a segment of the checkpoint with one value changed in its last bit (the kind of silent corruption
# HDF5 reads without complaint): the resume refuses it, and so does the final assembly when it
# happens while the run goes on; never status 0 with it in run.h5
flip_position() {   # FILE: the first position value's lowest bit flipped, in place
    local v; v=$(h5dump -m %.17g -d '/particles/all/position/value[0,0,0;;1,1,1]' "$1" | sed -n 's/^ *([0-9, ]*): //p' | tr -d ' ,')
    perl -e 'local $/; open my $f, "+<:raw", $ARGV[0] or die; my $b = <$f>; my $p = pack("d<", $ARGV[1]);
             my $at = index($b, $p); die "value not found\n" if $at < 0;
             substr($b, $at, 1) = chr(ord(substr($b, $at, 1)) ^ 1); seek $f, 0, 0; print $f $b; close $f' "$1" "$v"
}
d=$tmp/traj-flip
"$DPD" run "$scene" "${traj[@]}" --out "$d" --threads 1 --quiet --checkpoint-every 20 2>/dev/null &
pid=$!; wait_for "$d/trajectory-0001.h5" $pid; kill -TERM $pid; wait $pid
flip_position "$d/trajectory-0000.h5"
"$DPD" run "$scene" "${traj[@]}" --out "$d" --quiet --resume 2>"$tmp/err"; st=$?
check "trajectory: flipped bit in a segment: resume refused (status 2), no result" test $st -eq 2 -a ! -e "$d/summary.tsv" -a ! -e "$d/run.h5"
check "trajectory: flipped bit in a segment: message" grep -q 'trajectory segment .*trajectory-0000.h5 does not match its checksum' "$tmp/err"
d=$tmp/traj-flip-live
"$DPD" run "$scene" "${traj[@]}" --set steps=3000 --out "$d" --threads 1 --quiet --checkpoint-every 20 2>"$tmp/err" &
pid=$!; wait_for "$d/trajectory-0000.h5" $pid
flip_position "$d/trajectory-0000.h5"
wait $pid; st=$?
check "trajectory: segment flipped while the run goes on: the assembly fails (status 4), no result" test $st -eq 4 -a ! -e "$d/summary.tsv" -a ! -e "$d/run.h5"
check "trajectory: segment flipped while the run goes on: message" grep -q 'trajectory segment .*trajectory-0000.h5 does not match its checksum' "$tmp/err"
# a format 3 checkpoint of a trajectory scene (without shear, which alone refuses it): its segments
# have no box edges per frame, refused
d=$tmp/traj-v3
"$DPD" run "$scene" "${traj[@]}" --set shear_rate=0.0 --out "$d" --threads 1 --quiet --checkpoint-every 20 2>/dev/null &
pid=$!; wait_for "$d/trajectory-0000.h5" $pid; kill -TERM $pid; wait $pid
cp -r "$d" "$d-v4"
reseal "$d/checkpoint.dpd" 3
"$DPD" run "$scene" "${traj[@]}" --set shear_rate=0.0 --out "$d" --quiet --resume 2>"$tmp/err"; st=$?
check "trajectory: format 3 checkpoint: status 2, no result" test $st -eq 2 -a ! -e "$d/summary.tsv" -a ! -e "$d/run.h5"
check "trajectory: format 3 checkpoint: message" grep -q 'format version 3, which this dpd (format 5) cannot resume' "$tmp/err"
# a format 4 one: no checksums of its segments, which cannot then be verified: refused
d=$d-v4
reseal "$d/checkpoint.dpd" 4
"$DPD" run "$scene" "${traj[@]}" --set shear_rate=0.0 --out "$d" --quiet --resume 2>"$tmp/err"; st=$?
check "trajectory: format 4 checkpoint (no segment checksums): status 2, no result" test $st -eq 2 -a ! -e "$d/summary.tsv" -a ! -e "$d/run.h5"
check "trajectory: format 4 checkpoint: message" grep -q 'format version 4, which this dpd (format 5) cannot resume' "$tmp/err"

# the harness with the real simulator: tools/run-experiment of an experiment with a rotation, a
# 3D colloid and a TCAF run (tools/lib/exp.sh dpd_run; the local pool runs them at once, each
# --checkpoint-every --resume), one of them SIGKILLed in the middle by a wrapper (a crash).
# (1) The pool retries it in the same attempt, resuming from its checkpoint. (2) With no retry
# left (DPD_MAX_FAILURES=1) the experiment leaves no result and make check (tools/check) reports it
# MISSING, the other simulations of the pool are complete, and the next attempt runs only the
# killed one, resuming it. Every run equals its uninterrupted reference.
rx=$tmp/rx
mkdir -p "$rx/experiments/t/e"
cp -r tools "$rx/tools"
cp tests/checkpoint-rotation.cfg "$rx/experiments/t/e/rot.cfg"
cp tests/checkpoint-colloids3d.cfg "$rx/experiments/t/e/c3d.cfg"
cp tests/checkpoint-tcaf.cfg "$rx/experiments/t/e/tcaf.cfg"
cat > "$rx/experiments/t/e/run.sh" <<'EOF2'
#!/usr/bin/env bash
. "$DPD_ROOT/tools/lib/exp.sh"
simulations() {
    dpd_run rot rot.cfg
    dpd_run c3d c3d.cfg
    dpd_run tcaf tcaf.cfg --threads 2
}
analysis() {
    emit_from rot particles n_rot
    emit_from c3d colloids n_colloids
    emit_from tcaf tcaf_origins n_origins
}
experiment
EOF2
cat > "$rx/crashing-dpd" <<'EOF2'
#!/usr/bin/env bash
# the real simulator; the run named $CRASH_RUN is SIGKILLed after its first checkpoint
# (CRASH_ONCE=1: only the first time)
out=; args=("$@")
for ((i = 0; i < $#; i++)); do [ "${args[i]}" = --out ] && out=${args[i + 1]}; done
echo "$(basename "$out")" >> "$CRASH_LOG"
[ "$(basename "$out")" = "${CRASH_RUN:-}" ] || exec "$REAL_DPD" "$@"
if [ "${CRASH_ONCE:-0}" = 1 ]; then [ -e "$out.crashed" ] && exec "$REAL_DPD" "$@"; : > "$out.crashed"; fi
"$REAL_DPD" "$@" & pid=$!
for _ in $(seq 6000); do [ -e "$out/checkpoint.dpd" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.01; done
sleep "0.0$((RANDOM % 4))"; kill -KILL $pid; wait $pid
EOF2
chmod +x "$rx/experiments/t/e/run.sh" "$rx/crashing-dpd"
printf 'quantity\ttier\tkind\tlo\thi\tk_sigma\tresolution\tpaper\tsource\n%s\n%s\n%s\n' \
    $'n_rot\tquick\tgate\t384\t384\t0\t-\t-\tparticle count of the scene' \
    $'n_colloids\tquick\tgate\t8\t8\t0\t-\t-\tcolloid count of the scene' \
    $'n_origins\tquick\tgate\t1\t1e9\t-\t-\t-\tat least one origin' > "$rx/experiments/t/e/bands.tsv"
RX() { env -u DPD_ROOT -u MAKEFLAGS OMP_NUM_THREADS=1 DPD_JOBS=2 DPD_BIN="$rx/crashing-dpd" REAL_DPD="$(cd "$(dirname "$DPD")" && pwd)/$(basename "$DPD")" \
       CRASH_LOG="$tmp/crash.log" DPD_CHECKPOINT_EVERY=20 DPD_CHECKPOINT_WALL=0 "$@"; }
part=$rx/results/t/e/.quick.partial/runs
same_as_references() {
    local pair run ref
    for pair in rot:checkpoint-rotation c3d:checkpoint-colloids3d tcaf:checkpoint-tcaf; do
        run=${pair%%:*} ref=${pair#*:}
        check "harness ($1): $run = uninterrupted (summary)" \
            diff <(physics "$rx/results/t/e/quick/runs/$run/summary.tsv") <(physics "$tmp/$ref-ref/summary.tsv")
    done
}
: > "$tmp/crash.log"
RX CRASH_RUN=rot CRASH_ONCE=1 "$rx/tools/run-experiment" t/e quick 2>"$tmp/err"
check "harness: rot killed once: the attempt completes" test $? -eq 0
check "harness: rot killed once: retried in the same attempt" test "$(sort "$tmp/crash.log" | tr '\n' ' ')" = "c3d rot rot tcaf "
check "harness: rot killed once: resumed from its checkpoint" grep -q '^resumed_at_step	[1-9]' "$rx/results/t/e/quick/runs/rot/provenance.tsv"
same_as_references "rot killed once"
check "harness: the experiment's CPU time is the sum of its simulations' attempts (> 0)" \
    awk -F'\t' '$1 == "cpu_seconds" && $2 > 0 { f = 1 } END { exit !f }' "$rx/results/t/e/quick/provenance.tsv"
check "harness: every attempt of the killed run counted" test "$(grep -c . "$rx/results/t/e/quick/runs/rot/.cpu_seconds")" = 2
rm -rf "$rx/results/t/e"
: > "$tmp/crash.log"
RX CRASH_RUN=tcaf DPD_MAX_FAILURES=1 "$rx/tools/run-experiment" t/e quick 2>"$tmp/err"
check "harness: tcaf killed: run-experiment fails" test $? -ne 0
check "harness: tcaf killed: no experiment result" test ! -e "$rx/results/t/e/quick/summary.tsv"
env DPD_ROOT="$rx" "$rx/tools/check" t/e > "$tmp/out" 2>&1
check "harness: tcaf killed: make check fails" test $? -ne 0
check "harness: tcaf killed: make check says MISSING" grep -q 'MISSING' "$tmp/out"
check "harness: tcaf killed: INCOMPLETE, a checkpoint, no summary" \
    test -e "$part/tcaf/INCOMPLETE" -a -e "$part/tcaf/checkpoint.dpd" -a ! -e "$part/tcaf/summary.tsv"
check "harness: tcaf killed: the rest of the pool completed" test -s "$part/rot/summary.tsv" -a -s "$part/c3d/summary.tsv"
: > "$tmp/crash.log"
RX "$rx/tools/run-experiment" t/e quick 2>"$tmp/err"
check "harness: last attempt completes" test $? -eq 0
check "harness: only the killed run was rerun (resumed)" test "$(tr '\n' ' ' < "$tmp/crash.log")" = "tcaf "
check "harness: the killed run resumed from its checkpoint" grep -q '^resumed_at_step	[1-9]' "$rx/results/t/e/quick/runs/tcaf/provenance.tsv"
env DPD_ROOT="$rx" "$rx/tools/check" t/e > "$tmp/out" 2>&1
check "harness: make check passes after the resume" test $? -eq 0
same_as_references "tcaf killed, resumed by the next attempt"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
