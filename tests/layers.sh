#!/bin/bash
# layers.sh - the simulator's folders are layers (README.md, "The simulator"),
# lowest first: core pair dynamics bodies measure simd analysis io app (the
# order of LAYERS in the Makefile). A file includes only headers of its own
# layer and the layers below it, and no header of src/ exists twice; then the
# include graph has no cycle between layers. Also checks the include graph of
# the files themselves for cycles, that the Lees-Edwards image velocity, w_R and
# the r -> 0 guard each exist once, and that the vector code lives in one
# backend, src/simd/, with one dispatch point (simd.h). Prints "N passed, M
# failed"; exit status = verdict.
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh layers
layers=$(sed -n 's/^LAYERS := //p' Makefile)
[ -n "$layers" ] || { bad "LAYERS in the Makefile" "not found"; echo "$pass passed, $fail failed"; exit 1; }
declare -A rank where
r=0
for l in $layers; do
    rank[$l]=$r; r=$((r + 1))
    [ -d "src/$l" ] || bad "layer $l" "no folder src/$l"
done
# every source file lies in a layer's folder
for f in src/* src/*/*; do
    [ -f "$f" ] || continue
    d=$(basename "$(dirname "$f")")
    if [ -z "${rank[$d]+x}" ]; then bad "$f" "not in a layer's folder ($layers)"; continue; fi
    h=$(basename "$f")
    case $h in *.h)
        if [ -n "${where[$h]+x}" ]; then bad "$h" "in src/${where[$h]} and src/$d"; else where[$h]=$d; fi ;;
    esac
done
# each #include "x.h" resolves to a header of this layer or a lower one
viol=0
for f in src/*/*.[ch]; do
    d=$(basename "$(dirname "$f")")
    while read -r inc; do
        [ -n "$inc" ] || continue
        if [ -z "${where[$inc]+x}" ]; then bad "$f includes \"$inc\"" "no such header in src/"; viol=1; continue; fi
        l=${where[$inc]}
        if [ "${rank[$l]}" -gt "${rank[$d]}" ]; then
            bad "$f includes \"$inc\"" "src/$l is a higher layer than src/$d"; viol=1
        fi
    done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f")
done
[ $viol = 0 ] && ok "every include goes to the same or a lower layer"
# no include cycle among the headers (tsort reports a loop)
edges=$(for f in src/*/*.h; do
    for inc in $(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f"); do
        echo "$inc $(basename "$f")"; done; echo "$(basename "$f") $(basename "$f")"; done)
if err=$(tsort <<<"$edges" 2>&1 >/dev/null) && [ -z "$err" ]; then ok "no include cycle among the headers"
else bad "no include cycle among the headers" "$(head -c 300 <<<"$err")"; fi
# one copy each (issue 24): the Lees-Edwards image velocity (rate L_y) in the box,
# w_R = (1 - r/rc)^(s/2) and the r -> 0 guard in the pair driver's pair.h
once() {  # NAME PATTERN HOME...: PATTERN (grep -E) appears in src/ only in the HOME files
    local name=$1 pat=$2; shift 2
    local hits
    hits=$(grep -rlE "$pat" src | grep -vxF -f <(printf '%s\n' "$@") | tr '\n' ' ')
    if [ -z "$hits" ]; then ok "one copy: $name"; else bad "one copy: $name" "also in $hits"; fi
}
once "the Lees-Edwards image velocity" 'shear_rate \* [a-z>.-]*L\[1\]' src/core/box.h src/core/box.c
once "w_R" 'sqrt\(sqrt\(|pow\([a-z]+, 0\.5 \*' src/pair/pair.h
once "the r -> 0 guard" 'define [A-Z_]*EPSILON' src/pair/pair.h
# the physics layers (core, pair, dynamics, bodies) write no file: they hand their tables to io/
# (core/table.h; io/output.c writes them), which alone knows paths and file errors
for d in core pair dynamics bodies; do
    files=$(for f in src/$d/*.c; do perl -0pe 's{/\*.*?\*/}{$& =~ tr/\n//cdr}gse; s{//[^\n]*}{}g' "$f" \
           | grep -qE '(^|[^A-Za-z0-9_])(fopen|freopen|open|creat|mkstemp|rename|unlink|remove|write_file_atomic)[[:space:]]*\(' && printf '%s ' "$f"; done)
    if [ -z "$files" ]; then ok "src/$d writes no file (its tables go to io/)"
    else bad "src/$d writes files itself" "$files"; fi
done
# one vector backend (simd.h): every intrinsic (immintrin.h, __m256d, _mm512_add_pd, ...) and every
# target("avx...") attribute is in src/simd/; the guard DPD_HAVE_X86_SIMD only there and in simd.h and
# simd.c (the detection and the dispatch point); the backend's entry points (simd_x86.h) are included
# by simd.c and src/simd/ alone; and the level in use is read (simd_level(), SIMD_PICK) only by the
# dispatch points: simd.c's table (simd_kernels) and forces.c's choice of the pair styles'
# accelerators (pair_kernels). Code only: comments removed first.
mkdir -p "$tmp/code"
for f in src/*/*.[ch]; do
    mkdir -p "$tmp/code/$(dirname "$f")"
    perl -0pe 's{/\*.*?\*/}{$& =~ tr/\n//cdr}gse; s{//[^\n]*}{}g' "$f" > "$tmp/code/$f"
done
only_in() {  # NAME PATTERN ALLOWED: PATTERN (grep -E) in the code of files matching ALLOWED (bash regex) only
    local name=$1 pat=$2 allow=$3 hits=""
    for f in src/*/*.[ch]; do
        [[ $f =~ $allow ]] && continue
        grep -qE "$pat" "$tmp/code/$f" && hits+="$f "
    done
    if [ -z "$hits" ]; then ok "$name"; else bad "$name" "also in $hits"; fi
}
only_in "intrinsics only in the backend (src/simd/)" \
    '[a-z]*intrin\.h|__m(64|128|256|512)[a-z]*|__mmask|(^|[^A-Za-z0-9_])_mm(256|512)?_[a-z0-9_]+|__builtin_ia32' '^src/simd/'
only_in "target attributes only in the backend (src/simd/)" '(^|[^A-Za-z0-9_])(target|target_clones)[[:space:]]*\(|SIMD_TARGET' '^src/simd/'
only_in "the x86 guard only in the backend, simd.h and simd.c" 'DPD_HAVE_X86_SIMD' '^src/simd/|^src/core/simd\.[ch]$'
only_in "the backend's entry points (simd_x86.h) only in simd.c and the backend" \
    '#[[:space:]]*include[[:space:]]*"simd_x86\.h"' '^src/simd/|^src/core/simd\.c$'
only_in "the level read only at the dispatch points (simd.c, forces.c pair_kernels)" \
    'simd_level[[:space:]]*\(|SIMD_PICK' '^src/core/simd\.[ch]$|^src/pair/forces\.c$'
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
