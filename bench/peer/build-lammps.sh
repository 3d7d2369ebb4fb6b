#!/usr/bin/env bash
# Build a LAMMPS "peer" binary (DPD-BASIC + OPENMP, no MPI) from Debian's own
# lammps source package, into build/peer/ (git-ignored).
# Idempotent: exits 0 at once if build/peer/lmp already exists and runs.
# Usage: bash bench/peer/build-lammps.sh        (run as root; unattended)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
PEER="$ROOT/build/peer"
LMP="$PEER/lmp"
LOG="$PEER/build.log"
JOBS="${JOBS:-2}"
export DEBIAN_FRONTEND=noninteractive

lmp_runs() { [ -x "$LMP" ] && "$LMP" -h >/dev/null 2>&1; }

if lmp_runs; then
    echo "build-lammps: $LMP already exists and runs; nothing to do."
    exit 0
fi

mkdir -p "$PEER"
# progress on the caller's stderr, which the log's tee does not take (make bench-peer sends this
# script's output to /dev/null: the build takes minutes and would otherwise say nothing)
exec 3>&2
t_start=$(date +%s)
step() { printf 'build-lammps: [%s] %s (%d s so far; log %s)\n' "$1" "$2" $(( $(date +%s) - t_start )) "$LOG" >&3; }
exec > >(tee -a "$LOG") 2>&1
echo "=== build-lammps.sh started $(date -u +%FT%TZ) ==="
step 1/4 "LAMMPS for make bench-peer: Debian's source package and its build tools"

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# ---------------------------------------------------------------- deb-src
have_debsrc() {
    grep -rqsE '^[[:space:]]*(deb-src[[:space:]]|Types:.*deb-src)' \
        /etc/apt/sources.list /etc/apt/sources.list.d/ 2>/dev/null
}
if ! have_debsrc; then
    echo "build-lammps: enabling deb-src entries for the existing deb sources"
    # deb822 files: copy each 'Types: deb' stanza as a 'Types: deb-src' stanza
    # (same URIs / Suites / Components / Signed-By), into a separate file.
    out=/etc/apt/sources.list.d/peer-deb-src.sources
    tmp="$(mktemp)"
    for f in /etc/apt/sources.list.d/*.sources; do
        [ -e "$f" ] || continue
        [ "$f" = "$out" ] && continue
        awk '
            BEGIN { RS=""; ORS="\n\n" }
            {
                n = split($0, lines, "\n"); isdeb = 0; body = ""
                for (i = 1; i <= n; i++) {
                    l = lines[i]
                    if (l ~ /^[[:space:]]*#/) continue
                    if (l ~ /^Types:/) { if (l ~ /(^|[[:space:]])deb([[:space:]]|$)/) isdeb = 1; continue }
                    if (l ~ /^Enabled:[[:space:]]*no/) { isdeb = 0; break }
                    body = body l "\n"
                }
                if (isdeb) printf "Types: deb-src\n%s\n", body
            }' "$f" >> "$tmp"
    done
    if [ -s "$tmp" ]; then
        $SUDO install -m 0644 "$tmp" "$out"
        echo "build-lammps: wrote $out:"; cat "$out"
    fi
    rm -f "$tmp"
    # one-line style sources.list: add deb-src twins of the deb lines
    if [ -f /etc/apt/sources.list ] && grep -qE '^[[:space:]]*deb[[:space:]]' /etc/apt/sources.list; then
        sed -nE 's/^[[:space:]]*deb[[:space:]]/deb-src /p' /etc/apt/sources.list \
            | $SUDO tee /etc/apt/sources.list.d/peer-deb-src.list
    fi
    have_debsrc || { echo "build-lammps: could not enable deb-src" >&2; exit 1; }
fi

# ------------------------------------------------------------ build deps
# Only what a minimal cmake build needs (not 'apt-get build-dep lammps').
# --no-upgrade and only-missing: do not touch packages that are already there.
DEPS=(cmake make g++ dpkg-dev patch xz-utils)
missing=()
for p in "${DEPS[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'ok installed' || missing+=("$p")
done
SRC="$PEER/src"
have_src() { find "$SRC" -mindepth 2 -maxdepth 3 -path '*/cmake/CMakeLists.txt' 2>/dev/null | grep -q .; }
if [ "${#missing[@]}" -gt 0 ] || ! have_src; then
    $SUDO apt-get update
fi
if [ "${#missing[@]}" -gt 0 ]; then
    $SUDO apt-get install -y --no-install-recommends --no-upgrade "${missing[@]}"
fi

# ---------------------------------------------------------------- source
mkdir -p "$SRC"
srcdir="$(find "$SRC" -mindepth 1 -maxdepth 1 -type d -name 'lammps-*' | head -n1 || true)"
if [ -z "$srcdir" ] || [ ! -f "$srcdir/cmake/CMakeLists.txt" ]; then
    step 2/4 "fetching and unpacking the lammps source package (apt-get source lammps)"
    ( cd "$SRC" && apt-get source lammps )
    srcdir="$(find "$SRC" -mindepth 1 -maxdepth 1 -type d -name 'lammps-*' | head -n1)"
fi
[ -f "$srcdir/cmake/CMakeLists.txt" ] || { echo "build-lammps: no cmake/ in $srcdir" >&2; exit 1; }
echo "build-lammps: source tree $srcdir"

# ----------------------------------------------------------------- build
BLD="$PEER/cmake-build"
mkdir -p "$BLD"
CMAKE_ARGS=(
    -S "$srcdir/cmake" -B "$BLD"
    -D CMAKE_BUILD_TYPE=Release
    -D "CMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG"
    -D LAMMPS_MACHINE=
    -D BUILD_MPI=off
    -D BUILD_OMP=on
    -D PKG_DPD-BASIC=on
    -D PKG_OPENMP=on
    -D BUILD_SHARED_LIBS=off
    -D BUILD_TOOLS=off
    -D BUILD_LAMMPS_SHELL=off
    -D BUILD_DOC=off
    -D ENABLE_TESTING=off
    -D FFT=KISS
    -D WITH_JPEG=off
    -D WITH_PNG=off
    -D WITH_GZIP=off
    -D WITH_FFMPEG=off
)
echo "build-lammps: cmake ${CMAKE_ARGS[*]}"
step 3/4 "configuring (cmake: DPD-BASIC and OPENMP, no MPI)"
cmake "${CMAKE_ARGS[@]}"

echo "build-lammps: compiler flags used:"
grep -E '^CMAKE_CXX_COMPILER:|^CMAKE_CXX_FLAGS(_RELEASE)?:|^CMAKE_BUILD_TYPE:' "$BLD/CMakeCache.txt" || true
find "$BLD" -name flags.make -path '*lammps.dir*' -exec grep -H 'CXX_FLAGS' {} \; || true

# the compilation, the long part: make's "[ NN%]" lines become a line on fd 3 at every 5 %, with
# the time the rest should take at the pace so far
step 4/4 "compiling with $JOBS jobs"
t_make=$(date +%s) last=-5
# (a shell loop, not awk: mawk reads a pipe in blocks, and would print the lines at the end)
make -C "$BLD" -j"$JOBS" 2>&1 | while IFS= read -r line; do
    printf '%s\n' "$line"
    [[ $line =~ ^\[\ *([0-9]+)%\] ]] || continue
    p=${BASH_REMATCH[1]}
    if [ "$p" -ge $((last + 5)) ] || { [ "$p" = 100 ] && [ "$last" != 100 ]; }; then
        last=$p el=$(( $(date +%s) - t_make ))
        left=; [ "$p" -ge 5 ] && left=", about $(( (el * (100 - p) / p + 59) / 60 )) min left"
        printf 'build-lammps: [4/4] compiling LAMMPS: %d %% after %d min %02d s%s\n' "$p" $((el / 60)) $((el % 60)) "$left" >&3
    fi
done

bin="$BLD/lmp"
[ -x "$bin" ] || { echo "build-lammps: no binary at $bin" >&2; exit 1; }
ln -sf "cmake-build/lmp" "$LMP"
"$LMP" -h | sed -n '1,40p' | grep -iE 'LAMMPS|OS:|Compiler|C\+\+ standard|OpenMP|Installed packages' -A2 || true
lmp_runs || { echo "build-lammps: $LMP does not run" >&2; exit 1; }
echo "=== build-lammps.sh done $(date -u +%FT%TZ): $LMP ==="
step done "built $LMP"
