#!/usr/bin/env bash
# tests/bands_diff.sh - tools/bands-diff on a fixture repository: a widened band, a narrowed one, a
# claim newly expected to fail, a gate so marked, a row gone and a claim turned regression are each
# named; an unchanged row is not.
set -u
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
t=$(mktemp -d "${TMPDIR:-/tmp}/bands-diff.XXXXXX"); trap 'rm -rf "$t"' EXIT
pass=0 fail=0
check() { if grep -qP "$2" "$t/out"; then pass=$((pass + 1)); echo "PASS $1"; else fail=$((fail + 1)); echo "FAIL $1: no /$2/ in"; cat "$t/out"; fi; }
absent() { if grep -qP "$2" "$t/out"; then fail=$((fail + 1)); echo "FAIL $1: /$2/ listed"; else pass=$((pass + 1)); echo "PASS $1"; fi; }
mkdir -p "$t/experiments/p/e" && cd "$t" && git init -q && git config user.email t@t && git config user.name t
H='quantity\ttier\tkind\tlo\thi\tk_sigma\tresolution\tpaper\tsource\texpect\n'
printf "$H"'wide\tpaper\tclaim\t0.9\t1.1\t-\t-\t1\ts\t\nnarrow\tpaper\tclaim\t0.9\t1.1\t-\t-\t1\ts\t\nsame\tpaper\tclaim\t0.9\t1.1\t-\t-\t1\ts\t\nxf\tpaper\tclaim\t0.9\t1.1\t-\t-\t1\ts\t\ng\tpaper\tgate\t0.99\t1.01\t-\t-\t1\ts\t\ngone\tpaper\tclaim\t0\t1\t-\t-\t1\ts\t\nq\tquick\tclaim\t0.9\t1.1\t-\t-\t1\ts\t\n' > experiments/p/e/bands.tsv
git add -A && git commit -qm base
printf "$H"'wide\tpaper\tclaim\t0.8\t1.1\t-\t-\t1\ts\t\nnarrow\tpaper\tclaim\t0.95\t1.05\t-\t-\t1\ts\t\nsame\tpaper\tclaim\t0.9\t1.1\t-\t-\t1\ts\t\nxf\tpaper\tclaim\t0.9\t1.1\t-\t-\t1\ts\tfail\ng\tpaper\tgate\t0.99\t1.01\t-\t-\t1\ts\tfail\nq\tquick\tregression\t1.2\t1.2\t4\t0.1\t-\ts\t\n' > experiments/p/e/bands.tsv
"$root/tools/bands-diff" HEAD > "$t/out"
check "a widened band is WIDER" '^WIDER\tp/e\twide\tpaper\t0.9\t1.1\t0.8\t1.1'
check "a narrowed band is NARROWER" '^NARROWER\tp/e\tnarrow\t'
check "a claim newly expected to fail is EXPECT" '^EXPECT\tp/e\txf\t'
check "a gate marked expect fail is named" '^EXPECT-ON-NON-CLAIM\tp/e\tg\t'
check "a row whose quantity is gone is GONE-ALL" '^GONE-ALL\tp/e\tgone\t'
check "a claim turned regression is KIND" '^KIND claim->regression\tp/e\tq\tquick'
absent "an unchanged row is not listed" '\tp/e\tsame\t'
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
