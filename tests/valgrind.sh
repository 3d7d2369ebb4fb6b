#!/bin/bash
# valgrind.sh - memcheck on small scenes (`make valgrind`): a valid scene,
# a bad scene (status 2), a run that writes checkpoints, and resumes from
# checkpoints left by SIGKILLed runs (shear; rotation with a trajectory; 3D
# colloids; TCAF). Any memcheck error or definite leak
# fails (--error-exitcode=99). DPD selects the binary (default bin/dpd).
# OpenMP runs on one thread (libgomp's pool is then not created).
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh valgrind
export OMP_NUM_THREADS=1
VG=(valgrind --tool=memcheck --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite
    --quiet)
vg() {   # vg NAME WANTED_STATUS ARGS...
    local name=$1 want=$2; shift 2
    "${VG[@]}" "$DPD" "$@" >/dev/null 2>"$tmp/$name.err"; local st=$?
    if [ $st -eq "$want" ]; then pass=$((pass + 1)); echo "PASS $name (status $st, memcheck clean)"
    else fail=$((fail + 1)); echo "FAIL $name: status $st, want $want"; sed 's/^/    /' "$tmp/$name.err" | head -40; fi
}
vg good-scene 0 run tests/good-scene.cfg --out "$tmp/good" --quiet --threads 1
vg bad-scene 2 run tests/bad-scenes/region-outside-box.cfg --out "$tmp/bad" --quiet --threads 1
vg checkpointing-run 0 run tests/checkpoint-shear.cfg --set steps=40 --set equilibration=10 \
    --set measure.msd.window=20 --out "$tmp/ck" --quiet --threads 1 --checkpoint-every 10
vg overdamped-run 0 run tests/checkpoint-overdamped.cfg --set steps=10 --set equilibration=2 \
    --set measure.msd.window=10 --out "$tmp/od" --quiet --threads 1
# a checkpoint from a killed native run, resumed under memcheck
"$DPD" run tests/checkpoint-shear.cfg --out "$tmp/res" --quiet --threads 1 --checkpoint-every 20 2>/dev/null &
pid=$!
for _ in $(seq 6000); do [ -e "$tmp/res/checkpoint.dpd" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.01; done
kill -KILL $pid 2>/dev/null; wait $pid 2>/dev/null
vg resume 0 run tests/checkpoint-shear.cfg --out "$tmp/res" --quiet --threads 1 --resume
# the same for the state of checkpoint format 2: spins with trajectory segments,
# rigid colloid bodies, TCAF origins
for spec in "rotation --set output={trajectory_every=20;}" colloids3d tcaf; do
    read -r s extra <<< "$spec"
    "$DPD" run tests/checkpoint-$s.cfg $extra --out "$tmp/res-$s" --quiet --threads 1 --checkpoint-every 20 2>/dev/null &
    pid=$!
    for _ in $(seq 6000); do [ -e "$tmp/res-$s/checkpoint.dpd" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.01; done
    sleep 0.05; kill -KILL $pid 2>/dev/null; wait $pid 2>/dev/null
    vg resume-$s 0 run tests/checkpoint-$s.cfg $extra --out "$tmp/res-$s" --quiet --threads 1 --resume
done
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
