#!/usr/bin/python3
"""make-references.py - reference forces, virials and energies of small fixed
configurations from codes other than ours (issue 39, item 2), for
tests/test_reference_forces.c:

  standard DPD and the general weight exponent: LAMMPS `pair dpd` and
      `pair dpd/ext` (the peer build of bench/peer/build-lammps.sh, Debian's
      lammps source package), at kBT = 0;
  Lees-Edwards boxes with an offset: the same LAMMPS styles in a sheared
      triclinic box whose ghost images move with the shear (`fix deform ...
      remap v`);
  rotating particles (Pan, Pivkin & Karniadakis 2008, eqs 1 and 13-15): the
      paper's equations evaluated below with numpy (written from the paper,
      /work/shared/seeds/pan-2008-single-particle-dpd.txt; nothing taken from
      src/), in a periodic and in a sheared box, at kBT = 0.

At kBT = 0 the random parts vanish (sigma = sqrt(2 gamma kBT) = 0 in every
code), so the conservative and dissipative forces are deterministic functions
of positions and velocities.

Usage: tests/reference/make-references.py [LMP]   (LMP default build/peer/lmp)
Writes tests/reference/*.ref (committed); needs python3-numpy.

Conventions, ours -> LAMMPS
---------------------------
* Units: ours are DPD reduced units (m = 1, rc of the scene, kBT); LAMMPS runs
  in `units lj` with mass 1, where force, energy and length are the same
  numbers (no conversion).
* Weight exponent: ours w_D = (1 - r/rc)^s, w_R = sqrt(w_D) (Mai-Duy et al.
  2019 eqs 6-7). `pair dpd` has w_D = (1 - r/rc)^2 (s = 2 only). `pair dpd/ext`
  (LAMMPS docs, pair_dpd_ext): F^D = -gamma w_par^2 (e.v) e with
  w_par = (1 - r/rc)^ws, so ws = s / 2; its perpendicular friction gamma_perp
  is set to 0 (its exponent wsT is then irrelevant).
* Energy: LAMMPS' pair energy 0.5 a rc (1 - r/rc)^2 is ours (the potential of
  eq. 2); thermo `pe` with `thermo_modify norm no` (lj units normalise by N by
  default).
* Virial: ours W_ab = sum_{i<j} (r_i - r_j)_a F_ij,b with F_ij the force on i
  (PairVirial in src/pair/pair.h; positive for repulsion). LAMMPS' per-atom
  `compute stress/atom NULL virial` is minus half of each pair's
  delx*fx, ... (the same del = x_i - x_j, f on i) on each atom, so
  W = -sum over atoms of stress/atom; its six components are
  xx yy zz xy xz yz with xy = del_x f_y (ev_tally_xyz) or del_x del_y f/r.
  The global virial is not used: with newton on LAMMPS forms it as
  sum x . f over owned and ghost atoms (fdotr), which rounds at eps L |f|.
  Parts: one LAMMPS run with gamma = 0 (conservative part: forces, virial,
  energy), one with a = 0 (dissipative), one with both (the total forces).
* Lees-Edwards: ours has the image above the box shifted by +offset in x and
  moving with +shear_rate L_y (src/core/box.h); positions are in [0, L).
  LAMMPS: a triclinic cell with edges (Lx,0,0), (xy,Ly,0), (0,0,Lz): the image
  one row up is at +xy in x, the same lattice of images when xy = offset or
  offset - Lx (used when offset > Lx/2: LAMMPS refuses a tilt beyond Lx/2).
  `fix deform 1 xy vel V remap v` with V = shear_rate * Ly makes LAMMPS add
  V to the x velocity of every ghost one row up (h_rate[5]; atom_vec.cpp
  pack_border_vel), the image velocity. h_rate is (tilt_stop - tilt_start) /
  (run length), zero for `run 0`, so the input runs one step with no
  integrator (positions and velocities do not move; the dump and thermo of
  step 0 are the forces of the configuration as written) and a time step of
  1 (the rounding of h_rate, eps |xy| / (V dt), stays at eps).
  Why LAMMPS and not explicit images written by this script: the triclinic
  images, the minimum image and the image velocity are then LAMMPS' code,
  not a second implementation of ours.
* Pan 2008: the paper's f(r) = (1 - r/rc)^s_paper (its text recommends
  s_paper = 0.25) enters as f^2 in the friction; ours writes the exponent of
  w_D = f^2, so s = 2 s_paper (a scene's s = 0.5 is the paper's 0.25). Our
  gamma is the paper's gamma^C, gamma_shear its gamma^S. The Lees-Edwards case
  takes the nearest image by enumerating the images of j (rows up and down
  shifted by the offset, with the image velocity) and choosing the nearest.

Error model (written per particle into the files, used by the test)
-------------------------------------------------------------------
Both codes see the same doubles (positions and velocities written with 17
significant digits). They differ by rounding only:
  * separations: d = x_i - x_j, with a periodic shift, a triclinic remap
    (LAMMPS converts positions to lamda coordinates and back) and ghost
    positions x + L: each component within DELTA_X = 8 eps L_max of the exact
    difference, in each code;
  * velocities: v_i - v_j and the image velocity: within 4 eps (|v_i| + |v_j|
    + |v_image|);
  * each pair term: about 20 roundings in each code, K_OP = 32 eps of the sum
    of the absolute values of its parts; w^p (ours within 1 ulp, libm's
    pow within 1/2 ulp) counted there;
  * a particle's sum of n pair terms: n eps of the sum of their absolute values.
The force of a pair moves with d by at most |dF/dr| + |F|/r per unit length
(radial and angular) plus, for Pan, the rotational term; the test's
tolerance for each component of F_i is eps * scale_i with
  scale_i = sum_j [ (K_OP + n_i) B_ij + S_ij DELTA_X + G_ij DELTA_V ],
B the sum of the absolute values of the pair's parts, S its sensitivity to
d, G its friction coefficient. The same for torques (T = -(r/2) x F), the
virial (t_ab = d_a F_b: |d| dF + |F| dd, plus the sum over all pairs) and the
energy. Near the cutoff with s < 1, dw^s/dr = s w^(s-1)/rc is large: that is
the honest error of those pairs in both codes, not a tuned band.
"""
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

EPS = 2.0 ** -52
K_OP = 32.0
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))


# ------------------------------------------------------------ configurations

def configuration(seed, L, n, ntypes, dim, specials, rate=0.0):
    """n particles uniform in the box (types by turn), velocities uniform in
    [-1, 1] (plus the shear profile rate (y - Ly/2) in x), then the special
    pairs: (i, j, r, direction, at) puts j at distance r from i (i at `at`)."""
    rng = np.random.default_rng(seed)
    x = rng.uniform(0.0, 1.0, (n, 3)) * np.array(L)
    v = rng.uniform(-1.0, 1.0, (n, 3))
    w = rng.uniform(-1.0, 1.0, (n, 3))
    if dim == 2:
        x[:, 2] = 0.0
        v[:, 2] = 0.0
        w[:] = 0.0
    for (i, j, r, e, at) in specials:
        e = np.array(e, dtype=float)
        if dim == 2:
            e[2] = 0.0
        e /= np.linalg.norm(e)
        x[i] = np.array(at, dtype=float)
        if dim == 2:
            x[i, 2] = 0.0
        x[j] = np.mod(x[i] + r * e, np.array(L) if dim == 3 else np.array([L[0], L[1], 1.0]))
        if dim == 2:
            x[j, 2] = 0.0
    for a in range(3):  # positions in [0, L) exactly (a mod can round to L)
        if a < dim:
            x[:, a] = np.where(x[:, a] >= L[a], 0.0, x[:, a])
    v[:, 0] += rate * (x[:, 1] - 0.5 * L[1])
    types = np.arange(n) % ntypes
    return x, v, w, types


def specials_for(rc, L, exact_rc):
    """Pairs near the cutoff, at small r, coincident, exactly at rc along an
    axis (exact_rc: only in orthogonal boxes, where both codes form that
    separation exactly; LAMMPS' triclinic cell moves positions through lamda
    coordinates, which can put the pair an ulp inside rc, where w^s with
    s < 1 is not small: see the error model), and across the periodic faces
    (y: the Lees-Edwards boundary)."""
    skew = (0.48, 0.6, 0.64)
    mid = [0.5 * L[0], 0.5 * L[1], 0.5 * L[2]]
    return [
        (0, 1, rc * (1.0 - 1e-7), skew, [0.3 * L[0], 0.4 * L[1], 0.5 * L[2]]),
        (2, 3, rc * (1.0 - 1e-3), (-0.6, 0.0, 0.8), [0.7 * L[0], 0.2 * L[1], 0.3 * L[2]]),
        (4, 5, rc * (1.0 + 1e-7), (0.0, 1.0, 0.0), [0.2 * L[0], 0.8 * L[1], 0.8 * L[2]]),
        (6, 7, 1e-3, skew, [0.1 * L[0], 0.6 * L[1], 0.2 * L[2]]),
        (8, 9, 1e-6, (0.3, -0.4, 1.2), mid),
        (10, 11, 0.0, skew, [0.9 * L[0], 0.1 * L[1], 0.6 * L[2]]),
        (12, 13, rc if exact_rc else 0.95 * rc, (1.0, 0.0, 0.0), [1.0, 0.55 * L[1], 0.45 * L[2]]),   # r = rc: no force
        (14, 15, 0.6 * rc, (0.3, -1.0, 0.2), [0.35 * L[0], 0.1 * rc, 0.7 * L[2]]),   # across y = 0
        (16, 17, 0.9 * rc, (-0.5, 1.0, 0.1), [0.6 * L[0], L[1] - 0.2 * rc, 0.15 * L[2]]),   # across y = L
        (18, 19, 0.8 * rc, (-1.0, 0.2, -0.3), [0.05 * rc, 0.3 * L[1], 0.9 * L[2]]),   # across x = 0
        (20, 21, 0.7 * rc, (0.2, 0.1, -1.0), [0.45 * L[0], 0.65 * L[1], 0.1 * rc]),   # across z = 0
    ]


# ------------------------------------------------------------------ the pairs

def images(L, dim, offset):
    """image shifts (dx, dy, dz, row) of j: rows in y carry the offset"""
    out = []
    for ny in (-1, 0, 1):
        for nx in (-2, -1, 0, 1, 2):
            for nz in ((-1, 0, 1) if dim == 3 else (0,)):
                out.append((nx * L[0] + ny * offset, ny * L[1], nz * L[2], ny))
    return out


def pairs(x, v, L, dim, rcmax, offset, rate):
    """Every pair i < j within rcmax of the nearest image of j (brute force
    over images): i, j, d = x_i - x_j(image), dv = v_i - v_j(image)."""
    n = len(x)
    imgs = images(L, dim, offset)
    out = []
    for i in range(n):
        for j in range(i + 1, n):
            best = None
            for (sx, sy, sz, row) in imgs:
                d = x[i] - (x[j] + np.array([sx, sy, sz]))
                r2 = float(d @ d)
                if best is None or r2 < best[0]:
                    best = (r2, d, row)
            r2, d, row = best
            if r2 < (rcmax * (1.0 + 1e-12)) ** 2:
                dv = v[i] - v[j]
                dv[0] -= row * rate * L[1]   # the image row up moves with +rate Ly
                out.append((i, j, d, dv, abs(row * rate * L[1])))
    return out


def wvec(s, wc):
    return wc ** s


def dpd_pair(p, d, dv):
    """Standard DPD with a general exponent (Mai-Duy et al. 2019 eqs 2-7) at
    kBT = 0: the error scale of one pair (the values come from LAMMPS)."""
    a, gamma, s, rc = p["a"], p["gamma"], p["s"], p["rc"]
    r = math.sqrt(float(d @ d))
    if r >= rc or r < 1e-10:
        return None
    e = d / r
    wc = 1.0 - r / rc
    wd = wc ** s
    edv = float(e @ dv)
    fc, fd = a * wc, -gamma * wd * edv
    F = {"C": fc * e, "D": fd * e}
    B = abs(fc) + abs(fd)
    S = a / rc + gamma * s * wc ** (s - 1.0) / rc * abs(edv) + B / r + gamma * wd * np.linalg.norm(dv) / r
    return dict(r=r, F=F, B=B, S=S, G=gamma * wd, energy=0.5 * a * rc * wc * wc, tauB=0.0, tauS=0.0)


def cross(a, b):
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def pan_pair(p, d, dv, wsum):
    """Pan, Pivkin & Karniadakis 2008 at kBT = 0, from the paper:
    eq. 7  F^C = a (1 - r/rc) e;
    eq. 13 F^T = -gC f^2 (v.e) e - gS f^2 [v - (v.e) e];
    eq. 14 F^R = -gS f^2 (r/2) x (Omega_i + Omega_j);
    eq. 15 the random force, zero at kBT = 0 (sigma^C = sigma^S = 0);
    eq. 1  T_i = -(r_ij / 2) x F_ij, and T_j = -(r_ji / 2) x F_ji = T_i.
    f = (1 - r/rc)^s_paper with s_paper = s / 2 (module docstring)."""
    a, gC, gS, s, rc = p["a"], p["gamma"], p["gamma_shear"], p["s"], p["rc"]
    r = math.sqrt(float(d @ d))
    if r >= rc or r < 1e-10:
        return None
    e = d / r
    wc = 1.0 - r / rc
    f = wc ** (0.5 * s)
    f2 = f * f
    ve = float(dv @ e)
    FC = a * wc * e                                        # eq. 7
    FT = -gC * f2 * ve * e - gS * f2 * (dv - ve * e)       # eq. 13
    FR = -gS * f2 * cross(0.5 * d, wsum)                   # eq. 14
    Fij = FC + FT + FR
    T = -cross(0.5 * d, Fij)                               # eq. 1
    B = np.linalg.norm(FC) + np.linalg.norm(FT) + np.linalg.norm(FR)
    spin = np.linalg.norm(wsum)
    S = (a / rc + (gC + gS) * s * wc ** (s - 1.0) / rc * (np.linalg.norm(dv) + 0.5 * r * spin)
         + 2.0 * B / r + (gC + 2.0 * gS) * f2 * np.linalg.norm(dv) / r + gS * f2 * spin)
    return dict(r=r, F={"C": FC, "D": FT + FR}, B=B, S=S, G=(gC + gS) * f2,
                energy=0.5 * a * rc * wc * wc, T=T, tauB=0.5 * r * B, tauS=0.5 * (B + r * S))


# ----------------------------------------------------------- reference sums

def references(conf, x, v, w, types, plist, style):
    """per particle forces (and torques), virial by part, energy, with their
    error scales, from the pair terms (Pan) or only the scales (LAMMPS)"""
    n = len(x)
    L = conf["box"]
    dx = 8.0 * max(L[:conf["dim"]])                 # DELTA_X / eps
    F = np.zeros((n, 3))
    T = np.zeros((n, 3))
    Fs = np.zeros(n)
    Ts = np.zeros(n)
    npairs = np.zeros(n)
    W = {q: np.zeros((3, 3)) for q in ("C", "D", "R")}
    Wabs = 0.0
    Wsc = 0.0
    E = 0.0
    Esc = 0.0
    terms = []
    for (i, j, d, dv, vimg) in plist:
        pp = conf["pair"][(min(types[i], types[j]), max(types[i], types[j]))]
        r = math.sqrt(float(d @ d))
        if abs(r - pp["rc"]) <= 2.0 * dx * EPS:
            # within rounding of the cutoff: either code may count the pair
            # or not; its whole force at r = rc - 2 DELTA_X is the error
            wj = 2.0 * dx * EPS / pp["rc"]
            jump = pp["a"] * wj + (pp["gamma"] + pp["gamma_shear"]) * wj ** pp["s"] * (
                np.linalg.norm(dv) + 0.5 * r * np.linalg.norm(w[i] + w[j]))
            for k in (i, j):
                Fs[k] += jump / EPS
                Ts[k] += 0.5 * r * jump / EPS
            Wsc += r * jump / EPS
            Esc += 0.5 * pp["a"] * pp["rc"] * wj * wj / EPS
        t = pan_pair(pp, d, dv, w[i] + w[j]) if style == "pan" else dpd_pair(pp, d, dv)
        if t is None:
            continue
        npairs[i] += 1
        npairs[j] += 1
        terms.append((i, j, d, dv, vimg, t))
    for (i, j, d, dv, vimg, t) in terms:
        dvs = 4.0 * (np.linalg.norm(v[i]) + np.linalg.norm(v[j]) + vimg)
        for k in (i, j):
            Fs[k] += (K_OP + npairs[k]) * t["B"] + t["S"] * dx + t["G"] * dvs
            if style == "pan":
                Ts[k] += (K_OP + npairs[k]) * t["tauB"] + t["tauS"] * dx + 0.5 * t["r"] * t["G"] * dvs
        Fij = t["F"]["C"] + t["F"]["D"]
        F[i] += Fij
        F[j] -= Fij
        if style == "pan":
            T[i] += t["T"]
            T[j] += t["T"]
        for q in ("C", "D"):
            W[q] += np.outer(d, t["F"][q])
        Wabs += t["r"] * t["B"]
        Wsc += t["r"] * (K_OP * t["B"] + t["S"] * dx + t["G"] * dvs) + t["B"] * dx
        E += t["energy"]
        Esc += K_OP * t["energy"] + t["B"] * dx
    m = len(terms)
    return dict(F=F, T=T, Fscale=Fs, Tscale=Ts, W=W, Wscale=Wsc + m * Wabs, E=E, Escale=Esc + m * E,
                npairs=m)


# --------------------------------------------------------------------- LAMMPS

def lammps(lmp, conf, x, v, types, parts):
    """run the LAMMPS peer once per set of parts ("C", "D", "CD"); returns
    forces by atom, the virial (from stress/atom) and pe of each run"""
    L, dim, off, rate = conf["box"], conf["dim"], conf["offset"], conf["rate"]
    n = len(x)
    ntypes = conf["ntypes"]
    tri = rate != 0.0
    xy = off if off <= 0.5 * L[0] else off - L[0]
    res = {}
    with tempfile.TemporaryDirectory() as tmp:
        data = os.path.join(tmp, "data")
        with open(data, "w") as f:
            f.write("reference configuration (tests/reference/make-references.py)\n\n")
            f.write("%d atoms\n%d atom types\n\n" % (n, ntypes))
            f.write("0 %.17g xlo xhi\n0 %.17g ylo yhi\n" % (L[0], L[1]))
            if dim == 3:
                f.write("0 %.17g zlo zhi\n" % L[2])
            else:
                f.write("-0.5 0.5 zlo zhi\n")
            if tri:
                f.write("%.17g 0 0 xy xz yz\n" % xy)
            f.write("\nMasses\n\n")
            for t in range(ntypes):
                f.write("%d 1.0\n" % (t + 1))
            f.write("\nAtoms # atomic\n\n")
            for k in range(n):
                f.write("%d %d %.17g %.17g %.17g\n" % (k + 1, types[k] + 1, x[k, 0], x[k, 1], x[k, 2]))
            f.write("\nVelocities\n\n")
            for k in range(n):
                f.write("%d %.17g %.17g %.17g\n" % (k + 1, v[k, 0], v[k, 1], v[k, 2]))
        for part in parts:
            inp = os.path.join(tmp, "in." + part)
            dump = os.path.join(tmp, "forces." + part)
            with open(inp, "w") as f:
                f.write("units lj\natom_style atomic\ndimension %d\nboundary p p p\n" % dim)
                f.write("comm_modify vel yes\nread_data %s\n" % data)
                rcmax = max(p["rc"] for p in conf["pair"].values())
                if conf["lammps"] == "dpd":
                    f.write("pair_style dpd 0.0 %.17g 4928459\n" % rcmax)
                else:
                    f.write("pair_style dpd/ext 0.0 %.17g 4928459\n" % rcmax)
                for (ti, tj), p in sorted(conf["pair"].items()):
                    a = p["a"] if "C" in part else 0.0
                    g = p["gamma"] if "D" in part else 0.0
                    if conf["lammps"] == "dpd":
                        assert p["s"] == 2.0
                        f.write("pair_coeff %d %d %.17g %.17g %.17g\n" % (ti + 1, tj + 1, a, g, p["rc"]))
                    else:   # a gamma_par gamma_perp ws wsT rc; ws = s / 2
                        f.write("pair_coeff %d %d %.17g %.17g 0.0 %.17g %.17g %.17g\n"
                                % (ti + 1, tj + 1, a, g, 0.5 * p["s"], 0.5 * p["s"], p["rc"]))
                f.write("neighbor 0.3 bin\nneigh_modify every 1 delay 0 check no\ntimestep 1.0\n")
                f.write("compute sa all stress/atom NULL virial\n")
                f.write("compute W all reduce sum c_sa[1] c_sa[2] c_sa[3] c_sa[4] c_sa[5] c_sa[6]\n")
                f.write("thermo_style custom step pe c_W[1] c_W[2] c_W[3] c_W[4] c_W[5] c_W[6]\n")
                f.write("thermo_modify format float %.17g norm no\n")
                f.write("dump d all custom 1 %s id fx fy fz\ndump_modify d format float %%.17g sort id\n" % dump)
                if tri:
                    f.write("fix def all deform 1 xy vel %.17g remap v\n" % (rate * L[1]))
                    f.write("run 1\n")
                else:
                    f.write("run 0\n")
            out = subprocess.run([lmp, "-in", inp, "-log", "none", "-nocite", "-screen", os.path.join(tmp, "screen")],
                                 capture_output=True, text=True)
            screen = open(os.path.join(tmp, "screen")).read()
            if out.returncode != 0:
                sys.exit("make-references: LAMMPS failed on %s part %s:\n%s" % (conf["name"], part, screen[-3000:]))
            m = re.search(r"^\s*Step\s+PotEng.*\n\s*0\s+(.*)$", screen, re.M)
            vals = [float(t) for t in m.group(1).split()]
            pe, st = vals[0], vals[1:7]
            Wl = -np.array([[st[0], st[3], st[4]], [st[3], st[1], st[5]], [st[4], st[5], st[2]]])
            forces = np.zeros((n, 3))
            with open(dump) as f:
                lines = f.read().split("ITEM: TIMESTEP\n")[1].splitlines()   # step 0 only
            k0 = lines.index("ITEM: ATOMS id fx fy fz") + 1
            for line in lines[k0:k0 + n]:
                t = line.split()
                forces[int(t[0]) - 1] = [float(t[1]), float(t[2]), float(t[3])]
            res[part] = dict(F=forces, W=Wl, pe=pe, version=re.search(r"LAMMPS \((.*)\)", screen).group(1))
    return res


# ---------------------------------------------------------------------- cases

def params(a, gamma, s, rc, gamma_shear=0.0):
    return dict(a=a, gamma=gamma, s=s, rc=rc, gamma_shear=gamma_shear)


CASES = [
    dict(name="lammps-dpd", source="lammps", lammps="dpd", dim=3, box=(4.0, 4.5, 5.0), n=48, ntypes=2,
         seed=101, rate=0.0, offset=0.0,
         pair={(0, 0): params(25.0, 4.5, 2.0, 1.0), (0, 1): params(30.0, 3.0, 2.0, 0.9),
               (1, 1): params(15.0, 6.0, 2.0, 1.0)},
         what="LAMMPS pair dpd (w_D = (1 - r/rc)^2), two types, three type pairs, periodic 3D box"),
    dict(name="lammps-dpd-ext-mai-duy", source="lammps", lammps="dpd/ext", dim=3, box=(5.0, 5.5, 6.0), n=60,
         ntypes=1, seed=202, rate=0.0, offset=0.0,
         pair={(0, 0): params(3.53, 6.97, 0.42, 1.5)},
         what="LAMMPS pair dpd/ext, the mai-duy-2019 solvent (s = 0.42, rc = 1.5: ws = 0.21), one type"),
    dict(name="lammps-dpd-ext-exponents", source="lammps", lammps="dpd/ext", dim=3, box=(5.0, 5.5, 6.0), n=60,
         ntypes=2, seed=303, rate=0.0, offset=0.0,
         pair={(0, 0): params(25.0, 4.5, 1.0, 1.0), (0, 1): params(20.0, 3.0, 0.5, 1.2),
               (1, 1): params(18.0, 6.0, 0.42, 1.5)},
         what="LAMMPS pair dpd/ext, exponents s = 1, 0.5, 0.42 and three cutoffs, two types"),
    dict(name="lammps-dpd-2d", source="lammps", lammps="dpd/ext", dim=2, box=(5.0, 4.0, 0.0), n=40,
         ntypes=1, seed=404, rate=0.0, offset=0.0,
         pair={(0, 0): params(18.75, 4.5, 0.5, 1.0)},
         what="LAMMPS pair dpd/ext in 2D (s = 0.5)"),
    dict(name="lammps-dpd-lees-edwards", source="lammps", lammps="dpd", dim=3, box=(4.5, 4.0, 5.0), n=48,
         ntypes=1, seed=505, rate=0.7, offset=1.3,
         pair={(0, 0): params(25.0, 4.5, 2.0, 1.0)},
         what="LAMMPS pair dpd, Lees-Edwards offset 1.3 (triclinic xy = 1.3), shear rate 0.7"),
    dict(name="lammps-dpd-ext-lees-edwards", source="lammps", lammps="dpd/ext", dim=3, box=(6.0, 5.0, 5.5),
         n=60, ntypes=1, seed=606, rate=-0.4, offset=4.9,
         pair={(0, 0): params(3.53, 6.97, 0.42, 1.5)},
         what="LAMMPS pair dpd/ext (s = 0.42, rc = 1.5), Lees-Edwards offset 4.9 > Lx/2 (xy = -1.1), rate -0.4"),
    dict(name="pan2008", source="pan", dim=3, box=(4.0, 4.5, 5.0), n=48, ntypes=2, seed=707, rate=0.0,
         offset=0.0,
         pair={(0, 0): params(25.0, 4.5, 0.5, 1.0, 4.5), (0, 1): params(25.0, 3.5, 0.5, 1.0, 5.5),
               (1, 1): params(25.0, 4.5, 2.0, 1.0, 0.0)},
         what="Pan et al. 2008 eqs 1, 13-15 (numpy): fluid gC = gS = 4.5, fluid-colloid gC = 3.5, gS = 5.5 "
              "(s = 0.5, the paper's f = w^0.25), colloid-colloid gS = 0 (s = 2)"),
    dict(name="pan2008-lees-edwards", source="pan", dim=3, box=(4.5, 4.0, 5.0), n=48, ntypes=1, seed=808,
         rate=0.6, offset=3.1,
         pair={(0, 0): params(25.0, 4.5, 0.42, 1.0, 4.5)},
         what="Pan et al. 2008 (numpy), one type, s = 0.42, Lees-Edwards offset 3.1, rate 0.6 (nearest image by "
              "enumeration)"),
]


def write(conf, x, v, w, types, ref, lmp_parts, lmp_version):
    n = len(x)
    path = os.path.join(HERE, conf["name"] + ".ref")
    with open(path, "w") as f:
        f.write("# %s\n" % conf["what"])
        f.write("# made by tests/reference/make-references.py (the conventions and the error model: its docstring)\n")
        if conf["source"] == "lammps":
            f.write("# reference: LAMMPS (%s), pair_style %s at kBT = 0, runs for the parts C, D and CD\n"
                    % (lmp_version, conf["lammps"]))
        else:
            f.write("# reference: the script's numpy evaluation of Pan et al. 2008 eqs 1, 7, 13-15 at kBT = 0\n")
        f.write("# the test's tolerance of each value: 2^-52 x its scale (last column)\n")
        f.write("dim %d\n" % conf["dim"])
        L = conf["box"]
        f.write("box %.17g %.17g %.17g\n" % (L[0], L[1], L[2] if conf["dim"] == 3 else 0.0))
        f.write("shear %.17g %.17g\n" % (conf["rate"], conf["offset"]))
        f.write("rotation %d\n" % (conf["source"] == "pan"))
        f.write("types %d\n" % conf["ntypes"])
        f.write("# pair ti tj a gamma s rc gamma_shear\n")
        for (ti, tj), p in sorted(conf["pair"].items()):
            f.write("pair %d %d %.17g %.17g %.17g %.17g %.17g\n" % (ti, tj, p["a"], p["gamma"], p["s"], p["rc"],
                                                                      p["gamma_shear"]))
        f.write("particles %d\n" % n)
        f.write("# p id type x y z vx vy vz wx wy wz\n")
        for k in range(n):
            f.write("p %d %d %s\n" % (k, types[k], " ".join("%.17g" % c for c in list(x[k]) + list(v[k]) + list(w[k]))))
        f.write("# force id fx fy fz scale; torque id tx ty tz scale (rotation)\n")
        F = lmp_parts["CD"]["F"] if lmp_parts else ref["F"]
        for k in range(n):
            f.write("force %d %.17g %.17g %.17g %.17g\n" % (k, F[k, 0], F[k, 1], F[k, 2], ref["Fscale"][k]))
        if conf["source"] == "pan":
            for k in range(n):
                T = ref["T"][k]
                f.write("torque %d %.17g %.17g %.17g %.17g\n" % (k, T[0], T[1], T[2], ref["Tscale"][k]))
        f.write("# virial part(C D R) xx xy xz yx yy yz zx zy zz scale\n")
        for q in ("C", "D", "R"):
            if lmp_parts:
                Wq = lmp_parts[q]["W"] if q != "R" else np.zeros((3, 3))
            else:
                Wq = ref["W"][q]
            f.write("virial %s %s %.17g\n" % (q, " ".join("%.17g" % c for c in Wq.flatten()), ref["Wscale"]))
        E = lmp_parts["C"]["pe"] if lmp_parts else ref["E"]
        f.write("energy %.17g %.17g\n" % (E, ref["Escale"]))
        f.write("pairs %d\n" % ref["npairs"])
    return path


def main():
    lmp = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "peer", "lmp")
    for conf in CASES:
        L = conf["box"]
        rcmax = max(p["rc"] for p in conf["pair"].values())
        rc0 = conf["pair"][(0, 0)]["rc"]
        x, v, w, types = configuration(conf["seed"], L, conf["n"], conf["ntypes"], conf["dim"],
                                       specials_for(rc0, L, conf["rate"] == 0.0), conf["rate"])
        if conf["source"] != "pan":
            w[:] = 0.0
        if conf["dim"] == 2:
            x[:, 2] = 0.0
            v[:, 2] = 0.0
        plist = pairs(x, v, L, conf["dim"], rcmax, conf["offset"], conf["rate"])
        ref = references(conf, x, v, w, types, plist, "pan" if conf["source"] == "pan" else "dpd")
        lmp_parts, version = None, None
        if conf["source"] == "lammps":
            lmp_parts = lammps(lmp, conf, x, v, types, ("C", "D", "CD"))
            version = lmp_parts["C"]["version"]
            # the script's own sums of the same pairs agree with LAMMPS to
            # within the error model (a check of the script, not the reference)
            for q in ("C", "D"):
                dW = np.abs(lmp_parts[q]["W"] - ref["W"][q]).max()
                assert dW <= EPS * ref["Wscale"], (conf["name"], q, dW, EPS * ref["Wscale"])
            dF = np.abs(lmp_parts["CD"]["F"] - ref["F"]).max(axis=1)
            bad = np.nonzero(dF > EPS * ref["Fscale"])[0]
            assert len(bad) == 0, (conf["name"], bad, dF[bad], EPS * ref["Fscale"][bad])
            dE = abs(lmp_parts["C"]["pe"] - ref["E"])
            assert dE <= EPS * ref["Escale"], (conf["name"], dE)
        path = write(conf, x, v, w, types, ref, lmp_parts, version)
        print("%s: %d particles, %d pairs in range -> %s" % (conf["name"], conf["n"], ref["npairs"],
                                                            os.path.relpath(path, ROOT)))


if __name__ == "__main__":
    main()
