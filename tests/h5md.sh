#!/bin/bash
# h5md.sh - the trajectory of a run is H5MD 1.1 that a real reader opens:
# run.h5 of a short 3D run with output.trajectory_every, and the segment files
# trajectory-NNNN.h5 a run leaves behind its checkpoint (SIGTERM), are checked
#  - against the H5MD 1.1 layout with h5py: /h5md version and author, the
#    particles group's box (dimension, boundary, edges as a time series of
#    D x D matrices), position / velocity / image (frames x N x D) sharing
#    step and time, species; the measured series in /series (step, time,
#    value), not in /observables, which MDAnalysis reads frame by frame (only
#    the time between frames is there, sampled with the frames);
#  - by MDAnalysis's H5MDReader (Debian 12's python3-mdanalysis 2.4.2):
#    n_atoms, n_frames, frame 0's positions and velocities against the file,
#    box dimensions, times, every frame read, dt (the time between frames, which
#    MDAnalysis reads from /observables/dt: without it, 1.0 and a warning). The units are DPD reduced units,
#    which H5MD leaves without a unit attribute, so MDAnalysis opens the file
#    with convert_units=False (as its documentation says for such files) and,
#    run.h5 holding no topology, with the minimal one of n_atoms particles;
#  - a sheared run: the box is the sheared cell, edges (L_x, 0, 0),
#    (offset, L_y, 0), (0, 0, L_z), and position + image . edges moves
#    continuously (issue 24 bug 2);
#  - a 2D run: valid H5MD with dimension 2 (MDAnalysis reads only 3D boxes).
# Skips, saying so, when MDAnalysis or h5py is not installed (tools/deps
# installs python3-mdanalysis and python3-h5py). DPD selects the binary.
# Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh h5md
py=
for p in /usr/bin/python3 python3; do
    if command -v "$p" >/dev/null && "$p" -W ignore -c 'import MDAnalysis, h5py' 2>/dev/null; then py=$p; break; fi
done
if [ -z "$py" ]; then
    echo "SKIP h5md.sh: MDAnalysis and h5py are not installed for python3 (Debian: python3-mdanalysis python3-h5py, which tools/deps installs)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi

cat > "$tmp/fluid.cfg" <<'EOF'
dimension = 3;
box = [5.0, 4.0, 6.0];
kBT = 1.0; dt = 0.01; seed = 11; equilibration = 20; steps = 60;
types = ( { name = "a"; count = 100; }, { name = "b"; count = 20; } );
pairs = ( { types = ["a", "a"]; a = 25.0; gamma = 4.5; rc = 1.0; },
          { types = ["a", "b"]; a = 25.0; gamma = 4.5; rc = 1.0; },
          { types = ["b", "b"]; a = 25.0; gamma = 4.5; rc = 1.0; } );
measure = { every = 10; };
output = { trajectory_every = 20; };
EOF

# check.py FILE KIND [EXPECT...]: PASS/FAIL lines for one file
cat > "$tmp/check.py" <<'EOF'
import sys, warnings
warnings.simplefilter("ignore")
import numpy as np, h5py
path, kind = sys.argv[1], sys.argv[2]
n_expect, frames_expect = int(sys.argv[3]), int(sys.argv[4])
tag = f"{kind} {path.rsplit('/', 1)[-1]}"

def check(name, cond, detail=""):
    print(("PASS " if cond else "FAIL ") + f"{tag}: {name}" + ("" if cond else f": {detail}"))

def text(a):
    return a.decode() if isinstance(a, bytes) else str(a)

f = h5py.File(path, "r")
h = f.get("h5md")
check("/h5md version 1.1", h is not None and list(h.attrs.get("version", [])) == [1, 1])
check("/h5md author and creator names", h is not None and "name" in h["author"].attrs and "name" in h["creator"].attrs)
g = f["particles/all"]
box = g["box"]
D = int(box.attrs["dimension"])
check("box dimension", D == (2 if kind == "2d" else 3), D)
check("box boundary: D strings", [text(b) for b in box.attrs["boundary"]] == ["periodic"] * D, box.attrs["boundary"])
e = box.get("edges")
ok_e = isinstance(e, h5py.Group) and all(k in e for k in ("step", "time", "value"))
check("box edges: a time series (step, time, value)", ok_e, e)
pos = g["position"]
F, N = pos["value"].shape[0], pos["value"].shape[1]
check("position value frames x N x D", pos["value"].shape == (frames_expect, n_expect, D), pos["value"].shape)
check("position step and time, one per frame", pos["step"].shape == (F,) and pos["time"].shape == (F,))
for el in ("velocity", "image"):
    v = g[el]
    check(f"{el}: value frames x N x D, step and time", v["value"].shape == (F, N, D)
          and np.array_equal(v["step"][()], pos["step"][()]) and np.array_equal(v["time"][()], pos["time"][()]))
check("species: N integers", g["species"].shape == (N,) and g["species"].dtype.kind == "i")
if ok_e:
    ev = e["value"]
    check("box edges value: frames x D x D", ev.shape == (F, D, D), ev.shape)
    check("box edges step and time = position's", np.array_equal(e["step"][()], pos["step"][()])
          and np.array_equal(e["time"][()], pos["time"][()]))
# MDAnalysis reads /observables/NAME/value[frame]: only data sampled with the frames may be there,
# and the one such is dt, the time between frames, which is where MDAnalysis reads a dt from
obs = f.get("observables")
check("/observables: only series sampled with the frames (their step = position's)", obs is not None and all(
      isinstance(o, h5py.Group) and "step" in o and np.array_equal(o["step"][()], pos["step"][()]) for o in obs.values()),
      None if obs is None else list(obs))
if obs is not None and "dt" in obs:
    t = pos["time"][()]
    dtv = obs["dt"]["value"][()]
    check("/observables/dt: the time between frames, one per frame", dtv.shape == (F,)
          and (F < 2 or np.allclose(dtv, np.diff(t).mean(), rtol=1e-9)) and np.allclose(np.diff(t), dtv[1:], rtol=1e-6),
          (dtv[:3], np.diff(t)[:3]))
else:
    check("/observables/dt: the time between frames, one per frame", False, "absent")
if "series" in f:
    bad = [k for k, o in f["series"].items()
           if not (isinstance(o, h5py.Group) and all(x in o for x in ("step", "time", "value"))
                   and o["step"].shape[0] == o["time"].shape[0] == o["value"].shape[0])]
    check("series: step, time and value of one length", not bad, bad)
if kind == "sheared" and ok_e:
    # unwrapped = position + image . edges (rows: edge vectors); one step moves |v| dt < 0.3
    # (the flow is at most 4 here), a y crossing that jumped would move by the offset
    x = pos["value"][()]; im = g["image"]["value"][()]; ed = e["value"][()]
    un = x + np.einsum("fnk,fkd->fnd", im.astype(float), ed)
    jump = np.abs(np.diff(un, axis=0)).max()
    check("sheared: edges (L_x,0,0), (offset,L_y,0), (0,0,L_z)", np.all(ed[:, 0, 1:] == 0) and np.all(ed[:, 1, 2] == 0)
          and np.all(ed[:, 2, :2] == 0) and np.ptp(ed[:, 1, 0]) > 0, ed[:, 1, 0])
    check("sheared: position + image . edges continuous (largest move per step < 0.3)", jump < 0.3, jump)
f.close()

if kind != "2d":
    import MDAnalysis as mda
    try:
        u = mda.Universe(path, format="H5MD", topology_format="MINIMAL", n_atoms=N, convert_units=False)
        ok = True
    except Exception as err:
        ok = False
        check("MDAnalysis opens it", False, f"{type(err).__name__}: {err}")
    if ok:
        check("MDAnalysis opens it", True)
        f = h5py.File(path, "r")
        g = f["particles/all"]
        check("MDAnalysis n_atoms", u.atoms.n_atoms == n_expect, u.atoms.n_atoms)
        check("MDAnalysis n_frames", u.trajectory.n_frames == frames_expect, u.trajectory.n_frames)
        ts = u.trajectory[0]
        check("MDAnalysis frame 0 positions = file", np.allclose(ts.positions, g["position/value"][0], rtol=1e-6, atol=1e-5))
        check("MDAnalysis frame 0 velocities = file", np.allclose(ts.velocities, g["velocity/value"][0], rtol=1e-6, atol=1e-5))
        L = g["box/edges/value"][0] if isinstance(g["box/edges"], h5py.Group) else np.diag(g["box/edges"][()])
        lengths = np.sqrt((L * L).sum(axis=1))
        angle = np.degrees(np.arccos(np.dot(L[0], L[1]) / (lengths[0] * lengths[1])))
        check("MDAnalysis box dimensions", np.allclose(ts.dimensions[:3], lengths, rtol=1e-6)
              and np.allclose(ts.dimensions[3:5], 90.0) and abs(ts.dimensions[5] - angle) < 1e-3, ts.dimensions)
        times = [t.time for t in u.trajectory]
        check("MDAnalysis times = file, every frame read", np.allclose(times, g["position/time"][()]), times)
        # dt: MDAnalysis says 1.0 with a warning ("Reader has no dt information") unless the file gives it
        ft = g["position/time"][()]
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            u.trajectory[0]
            dt_read = u.trajectory.dt
            total = u.trajectory.totaltime
        said = [str(w.message) for w in caught if "dt" in str(w.message)]
        if len(ft) > 1:
            check("MDAnalysis dt = the time between frames, no warning", abs(dt_read - (ft[1] - ft[0])) < 1e-9 * abs(ft[1])
                  and not said, (dt_read, ft[1] - ft[0], said))
            check("MDAnalysis totaltime = last time - first", abs(total - (ft[-1] - ft[0])) < 1e-9 * abs(ft[-1]), (total, ft[-1] - ft[0]))
        f.close()
EOF

run_check() {   # run_check FILE KIND N FRAMES
    "$py" -W ignore "$tmp/check.py" "$@" > "$tmp/out" 2>&1 || echo "FAIL $2 $1: check.py exited ($(tail -1 "$tmp/out"))" >> "$tmp/out"
    cat "$tmp/out"
    pass=$((pass + $(grep -c '^PASS' "$tmp/out"))); fail=$((fail + $(grep -c '^FAIL' "$tmp/out")))
}

# a complete run: frames at steps 20, 40, 60, 80 in run.h5
"$DPD" run "$tmp/fluid.cfg" --out "$tmp/run" --threads 1 --quiet 2>"$tmp/err" \
    && ok "3D run with a trajectory" || bad "3D run with a trajectory" "$(cat "$tmp/err")"
run_check "$tmp/run/run.h5" 3d 120 4

# a sheared run, a frame every step (the offset wraps: rate 2, L_y 4, 80 steps of 0.01 move it
# 6.4 > L_x)
"$DPD" run "$tmp/fluid.cfg" --set shear_rate=2.0 --set output.trajectory_every=1 --out "$tmp/shear" --threads 1 \
    --quiet 2>"$tmp/err" && ok "sheared run with a trajectory" || bad "sheared run with a trajectory" "$(cat "$tmp/err")"
run_check "$tmp/shear/run.h5" sheared 120 80

# the segment files of a run stopped at a checkpoint (SIGTERM): each one valid on its own
d=$tmp/seg
"$DPD" run "$tmp/fluid.cfg" --set steps=100000 --set output.trajectory_every=10 --out "$d" --threads 1 --quiet \
    --checkpoint-every 20 2>/dev/null &
pid=$!
for _ in $(seq 6000); do [ -e "$d/trajectory-0002.h5" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.01; done
kill -TERM $pid 2>/dev/null; wait $pid; st=$?
segs=$(ls "$d"/trajectory-*.h5 2>/dev/null)
[ $st -eq 143 ] && [ -n "$segs" ] && ok "SIGTERM leaves trajectory segments ($(echo $segs | wc -w))" \
    || bad "SIGTERM leaves trajectory segments" "status $st, segments: $segs"
for s in $(echo "$segs" | head -3); do
    run_check "$s" 3d 120 "$(h5ls -d "$s/particles/all/position/step" | tail -n +3 | tr -d ' \n' | tr ',' '\n' | grep -c .)"
done

# a 2D run: H5MD with dimension 2
"$DPD" run "$tmp/fluid.cfg" --set dimension=2 --set 'box=[5.0,4.0]' --out "$tmp/2d" --threads 1 --quiet 2>"$tmp/err" \
    && ok "2D run with a trajectory" || bad "2D run with a trajectory" "$(cat "$tmp/err")"
run_check "$tmp/2d/run.h5" 2d 120 4

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
