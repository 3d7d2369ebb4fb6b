#!/bin/bash
# version.sh - the simulator's version is one string. After a rebuild in which only the version
# changed (Makefile: the objects that name DPD_GIT or DPD_CFLAGS depend on build/version), `dpd
# --version`, a run's provenance (git_commit) and its H5MD creator version all give the new one.
# Until 2026-12-06 the Makefile listed those objects by hand and missed run_output.o, so runs
# recorded an older commit than --version printed.
# A copy of build/release (when there is one) is rebuilt twice, with versions version-test-a and -b.
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh version
b=$tmp/build
[ -d build/release ] && cp -a build/release "$b"
# mk VERSION: build $tmp/dpd in the copy with that version (a make of its own, outside make test's)
mk() {
    env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s --no-print-directory SANITIZE= BUILD="$b" BIN="$tmp/dpd" \
        GIT_DESCRIBE="$1" "$tmp/dpd" > "$tmp/make.log" 2>&1
}
if mk version-test-a && mk version-test-b; then
    v=$("$tmp/dpd" --version)
    [ "$v" = "dpd version-test-b" ] && ok "--version gives the rebuilt version" || bad "--version" "got '$v'"
    if "$tmp/dpd" run tests/good-scene.cfg --out "$tmp/run" --quiet --set steps=20 --set equilibration=0 2> "$tmp/err"; then
        c=$(awk -F'\t' '$1 == "git_commit" { print $2 }' "$tmp/run/provenance.tsv")
        [ "$c" = version-test-b ] && ok "provenance git_commit is the rebuilt version" ||
            bad "provenance git_commit" "got '$c', want version-test-b (an object that prints it was not rebuilt)"
        h=$(h5dump -a /h5md/creator/version "$tmp/run/run.h5" 2>/dev/null | grep -o 'version-test-[ab]' | head -1)
        [ "$h" = version-test-b ] && ok "H5MD creator version is the rebuilt version" || bad "H5MD creator version" "got '$h'"
    else
        bad "a run of the rebuilt binary" "$(cat "$tmp/err")"
    fi
else
    bad "rebuild with another version" "$(tail -5 "$tmp/make.log")"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
