#!/bin/bash
# layers.sh - the simulator's folders are layers (README.md, "The simulator"),
# lowest first: core pair dynamics bodies measure analysis io app (the order
# of LAYERS in the Makefile). A file includes only headers of its own layer and
# the layers below it, and no header of src/ exists twice; then the include
# graph has no cycle between layers. Also checks the include graph of the
# files themselves for cycles, and that the Lees-Edwards image velocity, w_R and
# the r -> 0 guard each exist once. Prints "N passed, M failed"; exit status = verdict.
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
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
