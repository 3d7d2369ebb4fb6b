#!/usr/bin/env bash
# tools/test-harness.sh -- self-test of tools/check, the paper filter (tools/lib/paper-filter.lua,
# run by tools/render-paper) and the run-experiment tools on a fixture tree built in a temporary directory.
# usage: tools/test-harness.sh [-k] [--part 1|2]   (-k: keep the fixtures and print their paths)
# Its two parts run side by side, each on a fixture of its own (tests that share no state;
# the machine has two cores and each part is a serial chain of short processes): part 1 the
# check and the paper filter, part 2 the run-experiment tools. --part N runs one part alone.
set -uo pipefail
tools=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)
keep=0 part=
while [ $# -gt 0 ]; do
    case $1 in
        -k) keep=1; shift ;;
        --part) part=${2:-}; shift 2 || shift ;;
        *) echo "test-harness: unknown argument $1 (-k, --part 1|2)" >&2; exit 2 ;;
    esac
done
case $part in
    1|2) ;;
    "") # both parts, side by side; their outputs in order, then the sum
        d=$(mktemp -d "${TMPDIR:-/tmp}/dpd-harness-parts.XXXXXX"); trap 'rm -rf "$d"' EXIT
        k=(); [ "$keep" = 1 ] && k=(-k)
        for n in 1 2; do bash "${BASH_SOURCE[0]}" "${k[@]}" --part $n > "$d/$n" 2>&1 & done
        wait
        pass=0 fail=0
        for n in 1 2; do
            last=$(tail -n 1 "$d/$n")
            if [[ $last =~ ^([0-9]+)\ passed,\ ([0-9]+)\ failed$ ]]; then
                sed '$d' "$d/$n"; pass=$((pass + BASH_REMATCH[1])) fail=$((fail + BASH_REMATCH[2]))
            else
                cat "$d/$n"; echo "FAIL - part $n stopped before its count"; fail=$((fail + 1))
            fi
        done
        echo "$pass passed, $fail failed"
        [ "$fail" -eq 0 ]; exit ;;
    *) echo "test-harness: --part $part: 1 or 2" >&2; exit 2 ;;
esac
root=$(mktemp -d "${TMPDIR:-/tmp}/dpd-harness.XXXXXX")
[ "$keep" = 1 ] && echo "fixture: $root" || trap 'rm -rf "$root"' EXIT
export DPD_ROOT=$root
unset TIER MKPAPER_ALLOW_MISSING DPD_EXPERIMENTS_MD
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok   - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1"; [ -n "${2:-}" ] && sed 's/^/       | /' "$2" | head -40; }
T() { # T DESCRIPTION EXPECTED_RC COMMAND... ; output in $root/out
    local d=$1 want=$2 rc; shift 2
    "$@" > "$root/out" 2>&1; rc=$?
    if [ "$rc" = "$want" ]; then ok "$d (exit $rc)"; else bad "$d: exit $rc, wanted $want" "$root/out"; fi
}
has()   { if grep -q -e "$2" "$root/out"; then ok "$1"; else bad "$1: no match for '$2'" "$root/out"; fi; }
lacks() { if grep -q -e "$2" "$root/out"; then bad "$1: unexpected match for '$2'" "$root/out"; else ok "$1"; fi; }
in_file() { if grep -q -e "$3" "$2"; then ok "$1"; else bad "$1: no '$3' in ${2#"$root"/}" "$2"; fi; }
not_in_file() { if grep -q -e "$3" "$2"; then bad "$1: unexpected '$3' in ${2#"$root"/}" "$2"; else ok "$1"; fi; }

tab() { local IFS=$'\t'; printf '%s\n' "$*"; }
BANDS_HEADER=$(tab quantity tier kind lo hi k_sigma resolution paper source expect)
mkexp() { # mkexp ID ; bands rows on stdin (TSV: quantity tier kind lo hi k_sigma resolution paper source [expect])
    mkdir -p "$root/experiments/$1"
    { echo "$BANDS_HEADER"; cat; } > "$root/experiments/$1/bands.tsv"
    # its claims in one group (claims.tsv; tests below write their own)
    if awk -F'\t' 'NR > 1 && $3 == "claim" { f = 1 } END { exit !f }' "$root/experiments/$1/bands.tsv"; then
        { tab group quantities statement paper; tab all . 'every claim of the fixture' '-'; } > "$root/experiments/$1/claims.tsv"
    fi
}
mkres() { # mkres ID TIER CPU ; summary rows on stdin
    local d="$root/results/$1/$2"
    mkdir -p "$d"
    { tab quantity value stderr; cat; } > "$d/summary.tsv"
    { tab git_commit abc123; tab compiler gcc; tab flags -O2; tab threads 1
      tab cpu_seconds "$3"; tab wall_seconds "$3"; tab date 2024-01-01; tab tier "$2"; } > "$d/provenance.tsv"
}

C="$tools/check"
if [ "$part" = 1 ]; then
# ---------------------------------------------------------------- fixture
mkexp x/y <<EOF2
$(tab eta quick claim 28.5 30.5 - - 29.08 'fixture: paper +- 5 %')
$(tab eta paper claim 28.5 32.5 - - 29.08 'fixture')
$(tab ratio paper claim 3 inf - - 3.65 'one-sided')
EOF2
mkres x/y quick 1.5 <<EOF2
$(tab eta 29.3170 0.25)
EOF2
mkres x/y paper 4321.5 <<EOF2
$(tab eta 30.9 0.3)
$(tab ratio 3.71 0)
EOF2
{ tab group quantities statement paper; tab eta '^eta$' 'eta, "close to the input"' '29.08'
  tab ratio '^ratio$' 'the ratio' '3.65'; } > "$root/experiments/x/y/claims.tsv"
mkexp x/out  <<< "$(tab q quick claim 1 2 - - 1.5 fixture)"
mkres x/out quick 2 <<< "$(tab q 5.5 0.1)"
mkexp x/miss <<EOF2
$(tab a quick claim 1 2 - - - fixture)
$(tab b quick claim 1 2 - - - fixture)
EOF2
mkres x/miss quick 3 <<< "$(tab a 1.75 0)"
# the decision rule of a claim: value +- 2 se inside the band, wholly outside, or neither
mkexp x/rule <<EOF2
$(tab in quick claim 1 2 - - - '[1.1, 1.9] inside')
$(tab edge quick claim 1 2 - - - '[1.7, 2.1] straddles: factor (2 0.1 / 0.1)^2 = 4')
$(tab out quick claim 1 2 - - - '[2.1, 2.5] outside')
$(tab outwide quick claim 1 2 - - - '[1.9, 2.7]: passed under the old k = 2 widening, now unresolved')
$(tab lowside quick claim 3 inf - - - 'one-sided: [3.02, 3.18] inside')
$(tab nose quick claim 1 2 - - - 'no standard error: unresolved')
EOF2
mkres x/rule quick 4 <<EOF2
$(tab in 1.5 0.2)
$(tab edge 1.9 0.1)
$(tab out 2.3 0.1)
$(tab outwide 2.3 0.2)
$(tab lowside 3.1 0.04)
$(tab nose 1.5 nan)
EOF2
mkexp x/nan <<EOF2
$(tab vnan quick claim 0 1 - - - 'nan value')
$(tab vinf quick claim 0 1 - - - 'inf value')
$(tab vfin quick claim 0 1 - - - 'a finite value beside them, failing too: shown as the worst row')
EOF2
mkres x/nan quick 5 <<EOF2
$(tab vnan nan 0.1)
$(tab vinf inf 0)
$(tab vfin 1.5 0.1)
EOF2
# a group's worst row sets its outcome: an unresolved row near the centre before a pass near an edge
mkexp x/rank <<EOF2
$(tab p quick claim 0 10 - - - 'passes near an edge')
$(tab u quick claim 0 10 - - - 'unresolved at the centre')
EOF2
mkres x/rank quick 1 <<EOF2
$(tab p 9.5 0.1)
$(tab u 5 3)
EOF2
mkexp x/nores <<< "$(tab q quick claim 0 1 - - - fixture)"
mkexp x/incomplete <<< "$(tab q quick claim 0 1 - - - fixture)"
mkres x/incomplete quick 6 <<< "$(tab q 0.5 0)"
touch "$root/results/x/incomplete/quick/INCOMPLETE"
# a method study: no bands.tsv, a committed paper tier (no claims, not "not run")
mkdir -p "$root/experiments/x/method"; mkres x/method paper 7200 <<< "$(tab m 1 0)"
mkexp x/wide <<EOF2
$(tab tight quick claim 0.9 1.1 - - 1 'band 0.2 wide, error 0.5: unresolved')
$(tab zero quick gate 0 0 3 1 0 'an exact gate: |0.1| <= 3 x 0.5, se 0.5 <= resolution 1')
EOF2
mkres x/wide quick 2 <<EOF2
$(tab tight 1.0 0.5)
$(tab zero 0.1 0.5)
EOF2
# gates: a range gate by the claims' rule, exact gates by k se with a resolution
mkexp x/gates <<EOF2
$(tab t quick gate 0.99 1.01 - - 1 'temperature: [0.997, 1.005] inside')
$(tab z quick gate 0 0 3 0.1 0 'exact: |0.05| <= 3 x 0.02, 0.02 <= 0.1')
$(tab zres quick gate 0 0 3 0.01 0 'exact: se 0.02 above the resolution 0.01: undecided')
$(tab c quick claim 1 2 - - 1.5 'a claim that passes')
EOF2
mkres x/gates quick 3 <<EOF2
$(tab t 1.001 0.002)
$(tab z 0.05 0.02)
$(tab zres 0.05 0.02)
$(tab c 1.5 0.1)
EOF2
# regression references never enter the verdict
mkexp x/reg <<EOF2
$(tab r quick regression 2.5 2.5 4 0.2 - 'regression reference: quick tier at abc1234')
$(tab c quick claim 1 2 - - 1.5 'unresolved')
EOF2
mkres x/reg quick 3 <<EOF2
$(tab r 2.6 0.05)
$(tab c 1.9 0.1)
EOF2
# rows that break the format
mkexp x/badrow <<EOF2
$(tab zw quick claim 1 1 3 0.1 1 'a claim of zero width')
$(tab gx quick gate 0.9 1.1 - - 1 'a gate marked expect fail' fail)
$(tab kk quick foo 0 1 - - - 'an unknown kind')
$(tab kw quick claim 1 2 2 - - 'a claim band widened by k')
EOF2
mkres x/badrow quick 1 <<EOF2
$(tab zw 1 0.01)
$(tab gx 1 0.01)
$(tab kk 0.5 0.01)
$(tab kw 1.5 0.01)
EOF2
mkexp x/paperonly <<< "$(tab q paper claim 0 1 - - - fixture)"
mkres x/paperonly paper 7 <<EOF2
$(tab q 0.5 0)
$(tab q_tol1e-10 0.25 0.05)
EOF2
cat > "$root/EXPERIMENTS.md" <<'EOF2'
| experiment | what |
|---|---|
| `x/y` | fixture |
| `x/ghost` | listed, never built |
EOF2
mkdir -p "$root/figures/x/y" "$root/data"
# a 1x1 PNG
echo 'iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8DwHwAFBQIAX8jx0gAAAABJRU5ErkJggg==' \
    | base64 -d > "$root/figures/x/y/fig.png"
touch -d '2001-01-01' "$root"/results/x/y/*/summary.tsv
touch -d '2002-01-01' "$root/figures/x/y/fig.png"
printf 'phi\teta_r\n0.0119\t1.0273\n0.4940\t5.1700\n' > "$root/data/t.tsv"
printf 'row\tours\tverdict@\n1\t30.9 +- 0.3\teta\n2\t3.71\tratio\n3\t7\tunbanded\n' > "$root/results/x/y/paper/rows.tsv"
printf '# eta(k) per shell; comment line skipped\nk\tn2\teta\teta_se\n0.418879\t1\t37.616704\t6.8\n0.592384\t2\t33.149762\t1.49\n' > "$root/results/x/y/paper/cells.tsv"
printf 'k\teta\n0.7\t26.901334\n' > "$root/results/x/incomplete/quick/cells.tsv"
mkdir -p "$root/bench"
printf 'measure\tvalue\tnote\ncost ratio\t1.81\tfixture\ndate, commit\t2026-01-01\tabc1234\n' > "$root/bench/rot.tsv"
cat > "$root/paper.md" <<'EOF2'
---
title: Fixture paper
---

# Summary

<!-- summary-table -->

# Results

<!-- results: x/y -->

<!-- figure: x/y/fig.png -->

<!-- tsv: data/t.tsv -->

Verdicts: y {{verdict:x/y}}; miss {{verdict:x/miss}}; out {{verdict:x/out}}.

Outcomes: in {{outcome:x/rule:in}}; edge {{outcome:x/rule:edge}}; out {{outcome:x/rule:out}}; pinned {{outcome:x/y@paper:eta}}.

CPU: y {{cpu:x/y}} s; out {{cpu:x/out}} s.

Values: {{x/y:eta}}; pinned quick {{x/y@quick:eta}}; pinned CPU {{cpu:x/y@quick}} s.

Formats: {{x/y:eta:%.1f}}; {{x/y:ratio:%.3f}}; {{x/y@quick:eta:%.0f}}; hours {{cpu-h:x/y}}; total {{cpu:x/y+x/out}} s, {{cpu-h:x/y@paper+x/paperonly}} h.

Cells: {{tsv:data/t.tsv:0.4940:eta_r}}; {{tsv:results/x/y/paper/cells.tsv:n2=2:eta+-eta_se}}; {{tsv:results/x/y/paper/cells.tsv:0.418879:eta}}; {{tsv:results/x/y/paper/cells.tsv:k=0.592384&n2=2:eta_se}}.

Bench: {{bench:rot.tsv:cost ratio:value}}; {{bench:none.tsv:cost ratio:value}}; {{bench:rot.tsv:no such row:value}}.

Quick: {{x/paperonly@quick:q}}; committed {{x/paperonly:q}}.

<!-- table: x/y/rows.tsv -->

## x/y: the fixture experiment as a card

<!-- verdict: x/y -->

<!-- claims: x/y -->

## x/rule: a card of one group of six rows

<!-- verdict: x/rule -->

<!-- claims: x/rule -->

# Environment

<!-- environment -->
EOF2

# ---------------------------------------------------------------- check
T "check: value inside band passes" 0 "$C" x/y
has "check: PASS row for eta" '^x/y  *eta .*claim .*PASS'
has "check: final count line" '^claims: 1 passed, 0 failed, 0 unresolved; gates: 0 of 0 passed; regression references: 0 of 0 passed$'
T "check: paper tier (one-sided band)" 0 "$C" --tier paper x/y
has "check: paper tier counted" '^claims: 2 passed, 0 failed, 0 unresolved'
T "check: TIER env picks the tier" 0 env TIER=paper "$C" x/y
has "check: TIER env count" '^claims: 2 passed'
T "check: value outside band fails" 1 "$C" x/out
has "check: FAIL row" 'q .*FAIL'
has "check: count for failure" '^claims: 0 passed, 1 failed, 0 unresolved'
has "check: a failure is named" '^FAILED: 1 row'
T "check: quantity missing from summary.tsv" 1 "$C" x/miss
has "check: MISSING row" '^x/miss  *b .*MISSING'
has "check: MISSING fails" '^FAILED: 1 row'
T "check: the decision rule (a claim FAIL fails)" 1 "$C" x/rule
has "check: value +- 2 se inside: PASS" 'x/rule  *in .*PASS'
has "check: straddling an edge: UNRESOLVED" 'x/rule  *edge .*UNRESOLVED'
has "check: the run length that decides it: (2 se / d)^2" 'x/rule  *edge .*a run 4 times as long would decide it'
has "check: wholly outside: FAIL" 'x/rule  *out  .*FAIL'
has "check: inside the band widened by 2 se is no longer a pass" 'x/rule  *outwide .*UNRESOLVED'
has "check: one-sided band" 'x/rule  *lowside .*PASS'
has "check: no standard error decides nothing" 'x/rule  *nose .*UNRESOLVED'
has "check: rule counts" '^claims: 2 passed, 1 failed, 3 unresolved'
T "check: nan / inf handling" 1 "$C" x/nan
has "check: nan value fails" 'vnan .*FAIL'
has "check: inf value fails" 'vinf .*FAIL'
T "check: no summary.tsv" 1 "$C" x/nores
has "check: no summary -> MISSING" 'nores .*MISSING'
T "check: INCOMPLETE result rejected" 1 "$C" experiments/x/incomplete/
has "check: INCOMPLETE -> MISSING" 'incomplete .*MISSING .*INCOMPLETE'
T "check: no bands for tier does not fail" 0 "$C" --tier quick x/paperonly
has "check: no-bands note" '(no bands for tier quick)'
has "check: zero count" '^claims: 0 passed, 0 failed, 0 unresolved'
T "check: an unresolved claim does not fail" 0 "$C" x/wide
has "check: error wider than the band is UNRESOLVED" 'x/wide  *tight .*UNRESOLVED'
has "check: an exact gate within k se and its resolution" 'x/wide  *zero .*gate .*PASS'
T "check: a gate its run cannot resolve fails check" 1 "$C" x/gates
has "check: range gate by the claims' rule" 'x/gates  *t  .*gate .*PASS'
has "check: exact gate" 'x/gates  *z  .*\[0, 0\] +-3 sigma, se <= 0.1 .*PASS'
has "check: exact gate above its resolution: UNRESOLVED" 'x/gates  *zres .*UNRESOLVED .*above the resolution'
has "check: gates counted apart" '^claims: 1 passed, 0 failed, 0 unresolved; gates: 2 of 3 passed'
T "check: a regression reference" 0 "$C" x/reg
has "check: regression row" 'x/reg  *r  .*regression .*PASS'
has "check: regressions counted apart" 'regression references: 1 of 1 passed'
T "check: malformed band rows fail" 1 "$C" x/badrow
has "check: a claim of zero width is BAD" 'x/badrow  *zw .*BAD .*nonzero width'
has "check: expect = fail on a gate is BAD" 'x/badrow  *gx .*BAD .*never a gate'
has "check: an unknown kind is BAD" 'x/badrow  *kk .*BAD .*bad kind'
has "check: a claim widened by k is BAD" "x/badrow  *kw .*BAD .*never widened"
T "check: unknown experiment fails" 1 "$C" x/nonesuch
T "check: all experiments by default" 1 "$C"
has "check: default run lists x/y" '^x/y '
lacks "check: no awk errors" 'awk:'
T "check: bad option" 2 "$C" --bogus
T "check --tsv: the band rows, exit 0 on a failure" 0 "$C" --tsv x/out
has "check --tsv: a row as lib/bands.awk gives it" "^x/out	q	5.5	0.1	1	2	-	1.5	FAIL	"
lacks "check --tsv: no table" 'passed'
T "check --verdicts" 0 "$C" --verdicts --tier auto x/y x/out x/rule x/gates x/reg x/wide x/nores x/badrow
has "check --verdicts: [Re] from the paper tier" '^x/y	paper	\[Re\]	2	0	0	0	0	0	0	0	-	'
has "check --verdicts: every claim fails: [¬Re]" '^x/out	quick	\[¬Re\]	0	1	0	0	'
has "check --verdicts: pass and fail: [~Re], the decide factor" '^x/rule	quick	\[~Re\]	2	1	3	0	0	0	0	0	inf	'
has "check --verdicts: a gate not passing: invalid" '^x/gates	quick	invalid	1	0	0	0	2	3	'
has "check --verdicts: regression references do not count" '^x/reg	quick	unresolved	0	0	1	0	0	0	1	1	4	'
has "check --verdicts: unresolved" '^x/wide	quick	unresolved	0	0	1	0	1	1	'
has "check --verdicts: not run" '^x/nores	-	not run	'
has "check --verdicts: bad bands" '^x/badrow	quick	bad bands	'
# claim groups (claims.tsv, lib/groups.awk): every claim row in exactly one group; a tree of its own,
# as a broken claims.tsv stops the paper filter
GR="$root/groups"
mkg() { # mkg ID ; claims.tsv rows (group quantities statement paper) on stdin, bands of three claims and a gate
    mkdir -p "$GR/experiments/$1"
    { echo "$BANDS_HEADER"; tab eta_a1 paper claim 1 2 - - 1.5 f; tab eta_a2 quick claim 1 2 - - 1.5 f
      tab k_eff paper claim 0 1 - - 0.5 f; tab temp paper gate 0.9 1.1 - - 1 'a gate is in no group'; } > "$GR/experiments/$1/bands.tsv"
    { tab group quantities statement paper; cat; } > "$GR/experiments/$1/claims.tsv"
}
mkg g/ok <<EOF2
$(tab eta '^eta_a' 'the eta column' '1.5')
$(tab k_eff '^k_eff$' 'the k_eff column' '0.5')
EOF2
T "check --groups: every claim (of every tier) in exactly one group" 0 env DPD_ROOT="$GR" "$C" --groups
has "check --groups: counts" '^g/ok: ok, 3 claim quantities in 2 groups$'
T "check --groups --tsv: the group of every claim quantity" 0 env DPD_ROOT="$GR" "$C" --groups --tsv
has "check --groups --tsv: a row per quantity" '^g/ok	eta_a2	1	eta$'
lacks "check --groups --tsv: no gate" 'temp'
mkg g/none <<< "$(tab eta '^eta_a' 'eta' '1.5')"
mkg g/two <<EOF2
$(tab eta '^eta' 'eta' '1.5')
$(tab all '.' 'all' '-')
EOF2
mkg g/empty <<EOF2
$(tab eta '^eta_a' 'eta' '1.5')
$(tab k '^k_eff$' 'k' '0.5')
$(tab ghost '^nonesuch' 'no such claim' '-')
EOF2
mkg g/malformed <<EOF2
$(tab eta '^eta_a' 'eta')
$(tab k '^k_eff$' 'k' '0.5')
$(tab k '^k' 'k again' '0.5')
EOF2
mkdir -p "$GR/experiments/g/noclaims"; cp "$GR/experiments/g/ok/bands.tsv" "$GR/experiments/g/noclaims/"
T "check --groups: a claim in no group, in two, an empty group, a malformed or missing claims.tsv fail" 1 env DPD_ROOT="$GR" "$C" --groups
has "check --groups: a claim in no group" '^g/none: claim k_eff belongs to no group of claims.tsv$'
has "check --groups: a claim in two groups" "^g/two: claim eta_a1 belongs to 2 groups: 'eta', 'all'$"
has "check --groups: a group that matches nothing" "^g/empty: claims.tsv line 4: group 'ghost' (^nonesuch) matches no claim quantity$"
has "check --groups: a row without four fields" '^g/malformed: claims.tsv line 2: expected 4 non-empty'
has "check --groups: a group named twice" "^g/malformed: claims.tsv line 4: group 'k' is named twice$"
has "check --groups: no claims.tsv" '^g/noclaims: bands.tsv has 3 claim quantities but there is no claims.tsv'
has "check --groups: the good one still ok" '^g/ok: ok'
has "check --groups: the verdict line" '^groups: FAILED'
T "check --groups on one experiment" 0 env DPD_ROOT="$GR" "$C" --groups g/ok
printf '%s\n' '# S' '' '<!-- summary-table -->' > "$GR/s.md"
if MKPAPER_ALLOW_MISSING= DPD_ROOT="$GR" "$tools/render-paper" -i "$GR/s.md" -o "$GR/x.md" > "$root/out" 2>&1; then
    bad "paper-filter: broken claim groups stop the paper" "$root/out"
else has "paper-filter: broken claim groups stop the paper, named" 'tools/check --groups'; fi

# ---------------------------------------------------------------- the paper filter
# M [-i IN] [-o OUT.md]: tools/render-paper's markdown output of the filter (default OUT: $G),
# made greppable: pandoc's escapes dropped and runs of spaces (table padding) made one
G="$root/build/paper.gen.md"; M="$root/fill"
cat > "$M" <<EOF2
#!/usr/bin/env bash
out="$G"; prev=
for a in "\$@"; do [ "\$prev" = -o ] && out=\$a; prev=\$a; done
"$tools/render-paper" -o "$G" "\$@" || exit
sed -i -e 's/\\\\\([^A-Za-z0-9 ]\)/\\1/g' -e 's/  */ /g' "\$out"
EOF2
chmod +x "$M"
T "paper-filter: builds the fixture paper" 0 "$M"
has "paper-filter: counts the placeholder awaiting the quick tier" '^paper-filter: 1 placeholder(s) await the quick tier of 1 experiment(s)'
if [ -f "$G" ]; then
    in_file "paper-filter: a quick-tier number not computed here is marked" "$G" '^Quick: \[---\]{\.quick-pending title="quick tier: run make figures"}; committed 0.5 +- 0\.$'
    in_file "paper-filter: its section gets the notice" "$G" '^This section quotes quick-tier numbers, which a fresh clone does not have: run `make figures`'
    if grep -q 'table-wrap' "$G"; then bad "paper-filter: the table wrapper is for HTML only" "$G"; else ok "paper-filter: no table wrapper in markdown"; fi
    in_file "paper-filter: placeholders replaced" "$G" '^| experiment | verdict'
    if grep -q '<!-- \(summary-table\|results:\|figure:\|tsv:\|table:\|environment\)' "$G"; then bad "paper-filter: placeholder left over" "$G"; else ok "paper-filter: no placeholder left"; fi
    in_file "paper-filter: summary x/y [Re] on paper tier" "$G" '^| `x/y` | \[Re\] | 2 / 0 / 0 | none | \*\*paper\*\* |'
    in_file "paper-filter: summary cpu seconds from provenance" "$G" '^| `x/y` .*| 4321.5 | - |$'
    in_file "paper-filter: summary: a missing claim value" "$G" '^| `x/miss` | missing | 1 / 0 / 0 (1 missing) | none | \*\*quick\*\*'
    in_file "paper-filter: summary [¬Re] for failing" "$G" '^| `x/out` | \[¬Re\] | 0 / 1 / 0 | none | \*\*quick\*\* | - | 2 | - |$'
    in_file "paper-filter: summary not run" "$G" '^| `x/nores` | not run |'
    in_file "paper-filter: summary INCOMPLETE counts as not run" "$G" '^| `x/incomplete` | not run |'
    in_file "paper-filter: summary not yet built (from EXPERIMENTS.md)" "$G" '^| `x/ghost` | not yet built |'
    in_file "paper-filter: inline outcomes of band rows follow the decision rule" "$G" '^Outcomes: in \[PASS\]{\.outcome \.pass} (quick tier); edge \[UNRESOLVED\]{\.outcome \.unresolved} (×4 run) (quick tier); out \[FAIL\]{\.outcome \.fail} (quick tier); pinned \[PASS\]{\.outcome \.pass}\.$'
    in_file "paper-filter: inline verdicts name their claims" "$G" '^Verdicts: y \*\*\[Re\]\*\* (paper tier: 2 of 2 claims pass); miss \*\*missing\*\* (quick tier: pass `a`); out \*\*\[¬Re\]\*\* (quick tier: fail `q`)\.$'
    in_file "paper-filter: summary [~Re], with the run length that decides" "$G" '^| `x/rule` | \[~Re\] | 2 / 1 / 3 | none | \*\*quick\*\* | inf |'
    in_file "paper-filter: an unresolved claim is not a pass" "$G" '^| `x/wide` | unresolved | 0 / 0 / 1 | 1 of 1 | \*\*quick\*\* | ×100 (0.056 CPU-h) |'
    in_file "paper-filter: a gate not passing makes the result invalid" "$G" '^| `x/gates` | invalid | 1 / 0 / 0 | 2 of 3 |'
    in_file "paper-filter: inline value from the paper tier" "$G" '^Values: 30.9 +- 0.3; '
    in_file "paper-filter: inline value pinned to the quick tier, marked" "$G" '; pinned quick 29.32 +- 0.25 (quick tier); '
    in_file "paper-filter: inline CPU pinned to the quick tier" "$G" '; pinned CPU 2 (quick tier) s\.$'
    in_file "paper-filter: tsv cell by first column" "$G" '^Cells: 5.17; '
    in_file "paper-filter: tsv cell by NAME=VALUE with its se, comment skipped" "$G" '; 33.15 +- 1.5; '
    in_file "paper-filter: tsv cell from a paper-tier result is not marked" "$G" '; 37.62; '
    in_file "paper-filter: tsv cell by two NAME=VALUE keys" "$G" '; 1.49\.$'
    in_file "paper-filter: a value in a printf format, its stderr after it" "$G" '^Formats: 30.9 +- 0.3; '
    in_file "paper-filter: a value in a format, no stderr of zero" "$G" '; 3.710; '
    in_file "paper-filter: a formatted value of a pinned tier, marked" "$G" '; 29 +- 0.25 (quick tier); '
    # 4321.5 s = 1.20 h; 4321.5 + 2 (quick) = 4323.5; 4321.5 + 7 = 4328.5 s = 1.20 h
    in_file "paper-filter: CPU-hours" "$G" '; hours 1.2; '
    in_file "paper-filter: CPU of several experiments summed, a tier other than paper marked" "$G" '; total 4324 (quick tier) s, 1.2 h\.$'
    in_file "paper-filter: one sentence per paper from the verdicts" "$G" '^- \*\*x\*\*: 2 of 15 experiments reproduce (\[Re\]), 1 in part (\[~Re\]), 2 not (\[¬Re\]), 3 undecided (unresolved), 1 invalid (a gate does not pass), 2 not run, 1 run without claims (a method study), 1 not yet built, '
    in_file "paper-filter: the summary's claims table" "$G" '^| experiment | claim | paper | ours | band | outcome | gates | tier | CPU-h |$'
    in_file "paper-filter: a claim group's row, the experiment linked to its section, its verdict coloured" "$G" \
        '^| \[`x/y`\](#exp-x-y) \[\[Re\]\]{\.verdict \.pass} | \*\*eta\*\*: eta, "close to the input" | 29.08 | 30.9 ± 0.3 | \[28.5, 32.5\] | \[PASS\]{\.outcome \.pass} | none | paper | 1.2 |$'
    in_file "paper-filter: the next group of the experiment on a row of its own" "$G" '^| | \*\*ratio\*\*: the ratio | 3.65 | 3.71 ± 0 | \[3, inf\] | \[PASS\]{\.outcome \.pass} | | | |$'
    in_file "paper-filter: a group of several rows: its counts and its worst row" "$G" \
        '^| \[`x/rule`\](#exp-x-rule) \[\[~Re\]\]{\.verdict \.partial} | \*\*all\*\*: every claim of the fixture | - | worst of 6: `out` 2.3 ± 0.1 | \[1, 2\] | \[2 PASS\]{\.outcome \.pass} \[1 FAIL\]{\.outcome \.fail} \[3 UNRESOLVED\]{\.outcome \.unresolved} | none | quick |'
    in_file "paper-filter: a gate that does not pass: invalid in the gates column" "$G" '^| `x/gates` \[invalid\]{\.verdict \.fail} | .* | \*\*invalid\*\* (2 / 3) | quick |'
    in_file "paper-filter: an experiment not run: one row" "$G" '^| `x/nores` \[not run\]{\.verdict \.other} | - | - | - | - | - | - | - | - |$'
    in_file "paper-filter: a group's worst row is one with a finite value; those without are counted" "$G" '^| `x/nan` \[\[¬Re\]\]{\.verdict \.fail} | \*\*all\*\*: every claim of the fixture | - | worst of 3: `vfin` 1.5 ± 0.1 (2 without a finite value) | \[0, 1\] | \[3 FAIL\]{\.outcome \.fail} | none | quick |'
    in_file "paper-filter: a group's worst row is one of its worst outcome (unresolved before a pass nearer an edge)" "$G" '^| `x/rank` \[unresolved\]{\.verdict \.unresolved} | \*\*all\*\*: every claim of the fixture | - | worst of 2: `u` 5 ± 3 | \[0, 10\] | \[1 PASS\]{\.outcome \.pass} \[1 UNRESOLVED\]{\.outcome \.unresolved} | none | quick |'
    in_file "paper-filter: a method study without bands: no claims, its tier and CPU" "$G" '^| `x/method` \[no claims\]{\.verdict \.other} | - | - | - | - | - | none | paper | 2 |$'
    in_file "paper-filter: the section's heading gets the anchor" "$G" '^## x/y: the fixture experiment as a card {#exp-x-y}$'
    in_file "paper-filter: a card's verdict line" "$G" '^\*\*Verdict:\*\* \[\[Re\]\]{\.verdict \.pass} (paper tier; claims 2 pass, 0 fail, 0 unresolved; gates none; 1.2 CPU-hours)$'
    in_file "paper-filter: a card's claims table" "$G" '^| \*\*eta\*\*: eta, "close to the input" | 29.08 | 30.9 ± 0.3 | \[28.5, 32.5\] | \[PASS\]{\.outcome \.pass} |$'
    in_file "paper-filter: a card's group of several rows" "$G" '^| \*\*all\*\*: every claim of the fixture | - | worst of 6: `out` 2.3 ± 0.1 | \[1, 2\] | \[2 PASS\]{\.outcome \.pass} \[1 FAIL\]{\.outcome \.fail} \[3 UNRESOLVED\]{\.outcome \.unresolved} |$'
    in_file "paper-filter: bench cell with its date and commit" "$G" '^Bench: 1.81 (`make bench` 2026-01-01, abc1234); '
    in_file "paper-filter: bench file absent: not measured" "$G" '; not measured (run `make bench`); '
    in_file "paper-filter: bench row absent: not measured" "$G" '; not measured (run `make bench`)\.$'
    # x/y 4321.5 s + x/paperonly 7 s = 1.2024 h
    in_file "paper-filter: paper-tier CPU hours per paper from provenance" "$G" "^Paper tier, CPU time.*\`x\` 3.20 h (3 experiments)\.$"
    # every number of the summary table traced to the files: the CPU seconds to the tier's
    # provenance.tsv, the claim and gate counts to the bands evaluated on its summary.tsv
    # (lib/bands.awk); then every provenance CPU changed: every CPU cell follows
    trace_summary() { # trace_summary GEN.md -> "rows bad" on stdout, a line per mismatch on stderr
        ( . "$tools/lib/common.sh"
          awk '/^\| experiment \| verdict/ { t = 1; next } t && !/^\|/ { exit } t && /^\| `/' "$1" |
          while IFS='|' read -r _ id verdict claims gates tier decide cpu _; do
            id=$(echo "$id" | tr -d ' `'); tier=$(echo "$tier" | tr -d ' *'); claims=$(echo "$claims" | sed 's/^ *//; s/ *$//')
            gates=$(echo "$gates" | sed 's/^ *//; s/ *$//'); cpu=$(echo "$cpu" | tr -d ' ')
            [ "$tier" = "-" ] && { echo "row"; continue; }
            want_cpu=$(provenance "$id" "$tier" cpu_seconds)
            want=$(evaluate "$id" "$tier" | awk -F '\t' '
                $9 == "BAD" { next }
                $13 == "claim" { if ($9 == "PASS") p++; else if ($9 == "FAIL" || $9 == "XFAIL") f++; else if ($9 == "UNRESOLVED") u++; else m++ }
                $13 == "gate" { g++; if ($9 == "PASS") gp++ }
                END { printf "%d / %d / %d%s|%s\n", p, f, u, m ? sprintf(" (%d missing)", m) : "", g ? sprintf("%d of %d", gp, g) : "none" }')
            echo "row"
            [ "$cpu" = "$want_cpu" ] || echo "bad $id cpu $cpu vs provenance $want_cpu" >&2
            [ "$claims|$gates" = "$want" ] || echo "bad $id claims/gates '$claims|$gates' vs bands '$want'" >&2
          done ) 2>&1 | awk '/^row$/ { r++ } /^bad/ { b++; print > "/dev/stderr" } END { printf "%d %d\n", r, b + 0 }'
    }
    read -r nrows nbad < <(trace_summary "$G" 2> "$root/trace.err")
    if [ "$nrows" -ge 8 ] && [ "$nbad" = 0 ]; then ok "paper-filter: every summary-table number traced to a result file ($nrows rows)"
    else bad "paper-filter: summary-table numbers not traced ($nrows rows, $nbad mismatches)" "$root/trace.err"; fi
    for p in "$root"/results/*/*/*/provenance.tsv; do cp "$p" "$p.keep"; sed -i 's/^cpu_seconds\t.*/cpu_seconds\t9876.5/' "$p"; done
    "$M" -o "$root/traced.md" > /dev/null 2>&1
    read -r nrows nbad < <(trace_summary "$root/traced.md" 2> "$root/trace.err")
    awk '/^\| experiment \| verdict/ { t = 1; next } t && !/^\|/ { exit } t && /^\| `/' "$root/traced.md" > "$root/traced.rows"
    ncpu=$(grep -c '| 9876.5 | [^|]* |$' "$root/traced.rows")
    nrun=$(grep -vc '| - | - | - | - | - | - |$' "$root/traced.rows")
    if [ "$nbad" = 0 ] && [ "$ncpu" = "$nrun" ] && [ "$ncpu" -gt 0 ]; then ok "paper-filter: changed provenance CPU shows in every row ($ncpu)"
    else bad "paper-filter: CPU cells did not follow provenance ($ncpu of $nrun rows, $nbad mismatches)" "$root/trace.err"; fi
    for p in "$root"/results/*/*/*/provenance.tsv; do mv "$p.keep" "$p"; done
    in_file "paper-filter: results row, paper tier value" "$G" '^| `eta` | claim | 29.08 | 30.9 ± 0.3 | \[28.5, 32.5\] | paper | pass |'
    in_file "paper-filter: results row, quick tier value" "$G" '^| `eta` | claim | 29.08 | 29.317 ± 0.25 | \[28.5, 30.5\] | quick | pass |'
    in_file "paper-filter: results one-sided row" "$G" '`ratio` | claim | 3.65 | 3.71 ± 0 | \[3, inf\]'
    in_file "paper-filter: results cpu per tier" "$G" 'CPU time: paper 4321.5 s, quick 1.5 s'
    in_file "paper-filter: table header drops the verdict marker" "$G" '^| row | ours | verdict |$'
    in_file "paper-filter: table verdict of a banded quantity" "$G" '^| 1 | 30.9 +- 0.3 | pass |$'
    in_file "paper-filter: table verdict of a one-sided band" "$G" '^| 2 | 3.71 | pass |$'
    in_file "paper-filter: table quantity without a band" "$G" '^| 3 | 7 | no band |$'
    in_file "paper-filter: figure line" "$G" '^!\[.*\](figures/x/y/fig.png)$'
    in_file "paper-filter: tsv table header" "$G" '^| phi | eta_r |$'
    in_file "paper-filter: tsv table row" "$G" '^| 0.4940 | 5.1700 |$'
    in_file "paper-filter: environment gcc row" "$G" '^| gcc | '
    in_file "paper-filter: environment nproc row" "$G" "^| cores (nproc) | $(nproc) |"
    in_file "paper-filter: front matter kept" "$G" '^title: Fixture paper$'
else
    bad "paper-filter: no output $G"
fi

# a heading glued to the paragraph before it (pandoc reads it as text): refused, named
printf '# A\n\ntext\n## B glued\n' > "$root/glued.md"
T "render-paper: a heading without a blank line before it fails" 1 "$tools/render-paper" -i "$root/glued.md" -o "$root/build/glued.html"
has "render-paper: names the line" 'glued.md:4: ## B glued'

# no expressions in the text (issue 40 item 7): arithmetic written in the text is refused everywhere,
# each placeholder named, in a draft too; by render-paper before pandoc runs (it writes nothing), and
# by the filter itself (pandoc with the filter alone), which counts them.
# refused_in_text WHAT FILE COUNT LINE... -- CELL...: LINE, a regex of the "FILE:N: text" render-paper
# names (the last one is checked in the draft too); CELL, a regex of a placeholder the filter refuses
refused_in_text() {
    local what=$1 file=$2 count=$3 base line cell; shift 3
    local -a lines=()
    while [ $# -gt 0 ] && [ "$1" != -- ]; do lines+=("$1"); shift; done
    shift
    base=$(basename "$file" .md)
    T "render-paper: $what: fails" 1 "$tools/render-paper" -i "$file" -o "$root/build/$base.md"
    for line in "${lines[@]}"; do has "render-paper: $what: names $line" "$line"; done
    has "render-paper: $what: says what to write instead" 'let the analysis write the quantity'
    if [ -e "$root/build/$base.md" ]; then bad "render-paper: $what: wrote output" "$root/build/$base.md"
    else ok "render-paper: $what: writes nothing"; fi
    T "render-paper: $what: fails in a draft (MKPAPER_ALLOW_MISSING=1)" 1 env MKPAPER_ALLOW_MISSING=1 "$tools/render-paper" -i "$file" -o "$root/build/$base.md"
    has "render-paper: $what: the draft names ${lines[-1]}" "${lines[-1]}"
    command -v pandoc >/dev/null || return 0
    T "paper-filter: $what: fails in the filter alone" 1 env DPD_ROOT="$root" pandoc "$file" --lua-filter "$tools/lib/paper-filter.lua" -t markdown -o "$root/build/$base.filter.md"
    for cell in "$@"; do has "paper-filter: $what: refused $cell" "$cell: no expressions in the text"; done
    has "paper-filter: $what: counts the $count" "^paper-filter: $count placeholder(s) could not be filled"
}
# {{calc:}}, the former expression language, in pan-2008's section too
printf '%s\n' '# A' '' 'a {{calc:%.1f:1+1}}' '' '## pan-2008/x: once kept' '' 'b {{calc:%.1f:[x/y:eta]*2}}' '' '## other/x: not' '' 'c {{calc:%.1f:2}}' > "$root/calcout.md"
refused_in_text '{{calc:}}' "$root/calcout.md" 3 'calcout.md:3: a {{calc' 'calcout.md:11: c {{calc' 'calcout.md:7: b {{calc' -- \
    '{{calc:%.1f:1+1}}' '{{calc:%.1f:\[x/y:eta\]\*2}}' '{{calc:%.1f:2}}'
# the derived values of the former text: {{pct:}}, {{ratio:}}, {{diff:}}, {{sigmas:}}
printf '%s\n' '# A' '' 'a {{pct:x/y:eta/29.08}}' '' 'b {{ratio:x/y:eta/ratio}} and {{diff:x/y:eta-ratio}}' '' '## other/x: not' '' \
    'c {{sigmas:x/y:eta-29.08}}' > "$root/derivedout.md"
refused_in_text 'derived values' "$root/derivedout.md" 4 'derivedout.md:3: a {{pct:' 'derivedout.md:5: b {{ratio:' 'derivedout.md:9: c {{sigmas:' -- \
    '{{pct:x/y:eta/29.08}}' '{{ratio:x/y:eta/ratio}}' '{{diff:x/y:eta-ratio}}' '{{sigmas:x/y:eta-29.08}}'

# figure missing
mv "$root/figures/x/y/fig.png" "$root/fig.bak"
rm -f "$G"
T "paper-filter: missing figure fails" 1 "$M"
has "paper-filter: message names the placeholder" 'figure: x/y/fig.png'
if [ -e "$G" ]; then bad "paper-filter: output written despite error"; else ok "paper-filter: no output on error"; fi
T "paper-filter: MKPAPER_ALLOW_MISSING=1 gives a draft" 0 env MKPAPER_ALLOW_MISSING=1 "$M"
in_file "paper-filter: draft marks the gap" "$G" 'missing: '
mv "$root/fig.bak" "$root/figures/x/y/fig.png"
touch -d '2002-01-01' "$root/figures/x/y/fig.png"
# figure older than a result
touch -d '2003-01-01' "$root/results/x/y/quick/summary.tsv"
T "paper-filter: stale figure fails" 1 "$M"
has "paper-filter: stale message" 'older than results/x/y/quick/summary.tsv'
touch -d '2004-01-01' "$root/figures/x/y/fig.png"
T "paper-filter: fresh figure passes again" 0 "$M"
# results / tsv missing
printf '%s\n' '<!-- results: x/nores -->' '<!-- tsv: data/none.tsv -->' '<!-- figure: x/nores/a.svg -->' > "$root/bad.md"
T "paper-filter: missing result, tsv and figure fail" 1 "$M" -i "$root/bad.md" -o "$root/build/bad.gen.md"
has "paper-filter: names results placeholder" 'results: x/nores'
has "paper-filter: names tsv placeholder" 'tsv: data/none.tsv'
has "paper-filter: names figure placeholder" 'figure: x/nores/a.svg'
printf '%s\n' 'a {{x/y@reduced:eta}} b {{cpu:x/y@reduced}} c {{x/y:nonesuch}}' \
    'd {{tsv:results/x/y/paper/cells.tsv:n2=9:eta}} e {{tsv:results/x/y/paper/cells.tsv:1:nocol}}' \
    'f {{tsv:results/x/incomplete/quick/cells.tsv:0.7:eta}} g {{tsv:data/none.tsv:1:a}} h {{tsv:data/t.tsv:0.4940}}' \
    'l {{tsv:results/x/y/paper/cells.tsv:k=0.592384&n2=1:eta}}' '' '## pan-2008/bad: more' '' \
    'q {{bench:../x.tsv:a:b}}' > "$root/bad.md"
T "paper-filter: missing inline values and cells fail" 1 "$M" -i "$root/bad.md" -o "$root/build/bad.gen.md"
has "paper-filter: names a pinned tier without results" '{{x/y@reduced:eta}}: no such quantity in results/x/y/{reduced}'
has "paper-filter: names a pinned CPU without results" '{{cpu:x/y@reduced}}'
has "paper-filter: names a missing quantity" '{{x/y:nonesuch}}'
has "paper-filter: names a missing tsv row" 'cells.tsv: no row n2=9'
has "paper-filter: names a missing tsv column" 'cells.tsv: no column nocol'
has "paper-filter: a cell of an INCOMPLETE result is refused" 'results/x/incomplete/quick is not a valid result'
has "paper-filter: names a missing tsv file" 'no file data/none.tsv'
has "paper-filter: a cell without a column is malformed" 'expected tsv:PATH:ROW:COL'
has "paper-filter: a row must match every NAME=VALUE key" 'cells.tsv: no row k=0.592384&n2=1'
has "paper-filter: bench file outside bench/ refused" '{{bench:../x.tsv:a:b}}: expected bench:FILE:ROW:COL'
has "paper-filter: counts every failed placeholder" '10 placeholder(s) could not be filled'
lacks "paper-filter: no quick-tier count without such placeholders" 'await the quick tier'

# the quick tier, never committed: x/paperonly has a paper tier and no quick tier; what names
# that quick tier is marked and counted, not an error; what is filled from it once it exists
QM='\[---\]{\.quick-pending title="quick tier: run make figures"}'
cat > "$root/quick.md" <<'EOF2'
## pan-2008/quick: one section

a {{x/paperonly@quick:q}} b {{cpu:x/paperonly@quick}}.
e {{tsv:results/x/paperonly/quick/cells.tsv:1:eta}}.
i {{x/paperonly:q}}.

<!-- figure: x/paperonly/plot-quick.png | q against nothing -->

<!-- tsv: results/x/paperonly/quick/table.tsv -->
EOF2
QG="$root/build/quick.gen.md"
T "paper-filter: placeholders of a quick tier not computed here are no error" 0 "$M" -i "$root/quick.md" -o "$QG"
has "paper-filter: one line counts them" '^paper-filter: 5 placeholder(s) await the quick tier of 1 experiment(s), which is not committed'
if [ "$(grep -c 'await the quick tier' "$root/out")" = 1 ]; then ok "paper-filter: the count is a single line"; else bad "paper-filter: count lines" "$root/out"; fi
in_file "paper-filter: quick value and CPU marked" "$QG" "^a $QM b $QM\\.\$"
in_file "paper-filter: quick tsv cell marked" "$QG" "^e $QM\\.\$"
in_file "paper-filter: a committed value beside them filled" "$QG" "^i 0.5 +- 0\\.\$"
in_file "paper-filter: quick figure marked with its path and caption" "$QG" "^\\*Figure\\* \`figures/x/paperonly/plot-quick.png\` (q against nothing) $QM\$"
in_file "paper-filter: quick tsv table marked" "$QG" "^\\*Table\\* \`results/x/paperonly/quick/table.tsv\` $QM\$"
# the notice: once per section that holds a mark (from its heading to the next), right after its heading
n_notice=$(grep -c '^This section quotes quick-tier numbers' "$QG")
if [ "$n_notice" = 1 ]; then ok "paper-filter: one notice for a document of one section"; else bad "paper-filter: notices in one section" "$n_notice in $QG"; fi
printf '%s\n' '# A' '' 'a {{x/paperonly@quick:q}} and {{cpu:x/paperonly@quick}}.' '' 'b {{x/paperonly:q}}.' '' \
    '# B' '' 'c {{x/paperonly:q}}.' '' '## C' '' '<!-- figure: x/paperonly/plot-quick.png -->' '' '# D' '' \
    '| x | y |' '|---|---|' '| {{x/paperonly@quick:q}} | 1 |' > "$root/qsec.md"
T "paper-filter: quick marks under headings" 0 "$M" -i "$root/qsec.md" -o "$root/build/qsec.gen.md"
awk '/^#/ { h = $0 } /^This section quotes quick-tier/ { printf "%s|", h } END { print "" }' "$root/build/qsec.gen.md" > "$root/qsec.notices"
if [ "$(cat "$root/qsec.notices")" = '# A|## C|# D|' ]; then ok "paper-filter: one notice in each section with a mark (a paragraph, a figure, a table), none elsewhere"
else bad "paper-filter: notices per section" "$(cat "$root/qsec.notices") in $root/build/qsec.gen.md"; fi
if awk '/^# A/ { getline; getline; ok = /^::: quick-notice/ } END { exit !ok }' "$root/build/qsec.gen.md"; then ok "paper-filter: the notice follows its heading"
else bad "paper-filter: the notice's place" "$root/build/qsec.gen.md"; fi
T "paper-filter: MKPAPER_ALLOW_MISSING=1 marks them the same" 0 env MKPAPER_ALLOW_MISSING=1 "$M" -i "$root/quick.md" -o "$QG"
has "paper-filter: draft counts them" '^paper-filter: 5 placeholder(s) await the quick tier'
if grep -q 'missing' "$QG"; then bad "paper-filter: draft calls a quick placeholder missing" "$QG"; else ok "paper-filter: draft does not call them missing"; fi
# still errors: committed tiers, a quick tier that exists, an unknown experiment
printf '%s\n' '## pan-2008/qbad: errors' '' 'a {{x/nonesuch@quick:q}} b {{cpu:x/nonesuch@quick}} c {{x/y@quick:nonesuch}} d {{x/incomplete@quick:q}}' \
    'e {{x/paperonly@reduced:q}} f {{x/paperonly:nonesuch}}' \
    'j {{tsv:results/x/y/quick/none.tsv:1:a}}' \
    'k {{tsv:results/x/paperonly/paper/none.tsv:1:a}} l {{verdict:x/nores}}' \
    'm {{outcome:x/rule:nosuch}} n {{outcome:x/rule}} o {{outcome:x/nores:q}}' \
    '<!-- figure: x/paperonly/other-paper.png -->' '<!-- figure: x/y/fig-quick.png -->' '<!-- figure: x/nores/fig-reduced.png -->' \
    '<!-- tsv: results/x/y/quick/none.tsv -->' '<!-- tsv: results/x/paperonly/paper/none.tsv -->' '<!-- tsv: results/x/nonesuch/quick/t.tsv -->' \
    '<!-- results: x/nores -->' '<!-- table: x/paperonly/none.tsv -->' > "$root/qbad.md"
T "paper-filter: missing results other than an uncomputed quick tier still fail" 1 "$M" -i "$root/qbad.md" -o "$root/build/qbad.gen.md"
has "paper-filter: an unknown experiment pinned to quick fails" '{{x/nonesuch@quick:q}}: no such quantity'
has "paper-filter: a CPU of an unknown experiment pinned to quick fails" '{{cpu:x/nonesuch@quick}}: no results'
has "paper-filter: a quantity absent from an existing quick tier fails" '{{x/y@quick:nonesuch}}: no such quantity'
has "paper-filter: an INCOMPLETE quick tier fails" '{{x/incomplete@quick:q}}: no such quantity'
has "paper-filter: a missing reduced tier fails" '{{x/paperonly@reduced:q}}: no such quantity'
has "paper-filter: a quantity absent from the paper tier fails" '{{x/paperonly:nonesuch}}: no such quantity'
has "paper-filter: a missing file of an existing quick tier fails" 'tsv:results/x/y/quick/none.tsv:1:a}}: no file'
has "paper-filter: a missing file of the paper tier fails" 'tsv:results/x/paperonly/paper/none.tsv:1:a}}: .*not a valid result\|no file results/x/paperonly/paper/none.tsv'
has "paper-filter: an unpinned verdict without results fails" '{{verdict:x/nores}}'
has "paper-filter: an outcome of no band row fails" '{{outcome:x/rule:nosuch}}: no claim or gate row nosuch of x/rule at tier quick'
has "paper-filter: an outcome without a quantity fails" '{{outcome:x/rule}}: expected outcome:PAPER/EXP\[@TIER\]:QUANTITY'
has "paper-filter: an outcome of an experiment without results fails" '{{outcome:x/nores:q}}: no results for x/nores'
has "paper-filter: a missing paper-tier figure fails" 'other-paper.png does not exist'
has "paper-filter: a missing quick figure of an existing quick tier fails" 'fig-quick.png does not exist'
has "paper-filter: a missing reduced-tier figure fails" 'fig-reduced.png does not exist'
has "paper-filter: a missing table of an existing quick tier fails" 'tsv: results/x/y/quick/none.tsv -->: no file'
has "paper-filter: a missing table of the paper tier fails" 'tsv: results/x/paperonly/paper/none.tsv -->: no file'
has "paper-filter: a table of an unknown experiment's quick tier fails" 'tsv: results/x/nonesuch/quick/t.tsv -->: no file'
has "paper-filter: counts them all as failures" '^paper-filter: 20 placeholder(s) could not be filled'
lacks "paper-filter: none of them counted as awaiting the quick tier" 'await the quick tier'
# once the quick tier exists, the same placeholders are filled from it (and marked as quick)
mkres x/paperonly quick 12.4 <<EOF2
$(tab q 0.75 0.05)
$(tab q_tol1e-10 0.5 0.05)
EOF2
printf 'k\teta\n1\t3.0\n' > "$root/results/x/paperonly/quick/cells.tsv"
printf 'a\tb\n1\t2\n' > "$root/results/x/paperonly/quick/table.tsv"
mkdir -p "$root/figures/x/paperonly"; cp "$root/figures/x/y/fig.png" "$root/figures/x/paperonly/plot-quick.png"
touch -d '2001-01-01' "$root"/results/x/paperonly/*/summary.tsv
touch -d '2002-01-01' "$root/figures/x/paperonly/plot-quick.png"
T "paper-filter: the quick tier computed, its placeholders are filled" 0 "$M" -i "$root/quick.md" -o "$QG"
lacks "paper-filter: nothing awaits the quick tier" 'await the quick tier'
in_file "paper-filter: quick value and CPU filled" "$QG" '^a 0.75 +- 0.05 (quick tier) b 12 (quick tier)\.$'
in_file "paper-filter: quick tsv cell filled" "$QG" '^e 3 (quick tier)\.$'
in_file "paper-filter: the committed value still filled" "$QG" '^i 0.5 +- 0\.$'
in_file "paper-filter: quick figure shown" "$QG" '^!\[q against nothing\](figures/x/paperonly/plot-quick.png)$'
in_file "paper-filter: quick tsv table shown" "$QG" '^| 1 | 2 |$'
if grep -q 'make figures' "$QG"; then bad "paper-filter: a mark left once the quick tier exists" "$QG"; else ok "paper-filter: no mark left once the quick tier exists"; fi
touch -d '2003-01-01' "$root/results/x/paperonly/quick/summary.tsv"
T "paper-filter: a stale quick figure stays an error" 1 "$M" -i "$root/quick.md" -o "$QG"
has "paper-filter: stale quick figure named" 'plot-quick.png is older than results/x/paperonly/quick/summary.tsv'
rm -rf "$root/results/x/paperonly/quick" "$root/figures/x/paperonly"

# emphasis and a superscript of the text around placeholders, table cells, a figure line inside a
# paragraph; a placeholder where the filter does not look (a heading, the metadata) is an error
cat > "$root/inline.md" <<'EOF2'
## x/inline: placeholders in running text

s1 {{x/y:eta:%.0f}} and x^2 y {{x/y:eta:%.1f}} s3 *{{x/y:eta}}* s4 {{tsv:results/x/y/paper/cells.tsv:k=0.592384&n2=2:eta_se}}.

| what | value |
|---|---|
| eta | {{x/y:eta}} |

before
<!-- figure: x/y/fig.png | inline -->
after
EOF2
CG="$root/build/inline.gen.md"
T "paper-filter: emphasis, a superscript, table cells, a figure line in a paragraph" 0 "$M" -i "$root/inline.md" -o "$CG"
in_file "paper-filter: the text's '*' and '^' around placeholders kept" "$CG" \
    '^s1 31 +- 0.3 and x^2 y 30.9 +- 0.3 s3 \*30.9 +- 0.3\* s4 1.49\.$'
in_file "paper-filter: a placeholder in a table cell" "$CG" '^| eta | 30.9 +- 0.3 |$'
if awk '/^before$/ { getline a; getline b; ok = (a == "![inline](figures/x/y/fig.png)" && b == "after") } END { exit !ok }' "$CG"; then
    ok "paper-filter: a figure line inside a paragraph stays in it"
else bad "paper-filter: a figure line inside a paragraph left it" "$CG"; fi
printf '%s\n' '---' 'subtitle: "{{x/y@paper:eta}}"' '---' '# Heading {{x/y:eta}}' '' '## x/inline: text' '' 'a {{x/y:eta}}' > "$root/placebad.md"
T "paper-filter: placeholders where the filter does not look fail" 1 "$M" -i "$root/placebad.md" -o "$root/build/placebad.gen.md"
has "paper-filter: a placeholder in a heading is an error" 'placebad.md:4: {{x/y:eta}}: placeholder in a place the filter does not fill'
has "paper-filter: a placeholder in the metadata is an error" 'placebad.md:2: {{x/y@paper:eta}}: placeholder in a place the filter does not fill'
has "paper-filter: counts them" '^paper-filter: 2 placeholder(s) could not be filled'

# ---------------------------------------------------------------- render
if command -v pandoc >/dev/null; then
    T "render-paper: HTML" 0 "$tools/render-paper"
    has "render-paper: passes on the quick-tier count" '^paper-filter: 1 placeholder(s) await the quick tier'
    H="$root/build/paper.html"
    if [ -f "$H" ]; then
        in_file "render-paper: title from front matter" "$H" '<title>Fixture paper</title>'
        in_file "render-paper: image embedded" "$H" 'data:image/png;base64'
        in_file "render-paper: table rendered" "$H" '<table'
        in_file "render-paper: quick-tier mark rendered" "$H" '<span class="quick-pending" title="quick tier: run make figures">—</span>'
        in_file "render-paper: its notice rendered" "$H" '<div class="quick-notice">'
        in_file "render-paper: a table in its scrolling wrapper" "$H" '<div class="table-wrap">'
        if grep -q '(quick tier: run' "$H"; then bad "render-paper: the old in-sentence mark left" "$H"; else ok "render-paper: no in-sentence mark"; fi
    else bad "render-paper: no $H"; fi
else
    echo "skip - render-paper (no pandoc)"
fi

# ---------------------------------------------------------------- tools/cost and tools/progress
# tools/cost class: the factor a projected run gets follows the walk it takes (one type in 3D without
# shear: the AVX-512 evaluators; several types, shear or 2D: the generic walk)
cc=$tools/cost
printf 'dimension = 3;\ntypes = ( { name = "f"; density = 3.0; } );\npairs = ( { types = ["f", "f"]; a = 25.0; gamma = 4.5; s = 0.42; } );\n' > "$root/one.cfg"
sed 's/types = ( { name = "f"; density = 3.0; } );/types = ( { name = "f"; density = 3.0; }, { name = "g"; count = 2; } );/' "$root/one.cfg" > "$root/two.cfg"
T "cost class: one type, a power" 0 "$cc" class "$root/one.cfg"; has "cost class: pow" '^pow$'
T "cost class: two types" 0 "$cc" class "$root/two.cfg"; has "cost class: pow-generic (types)" '^pow-generic$'
T "cost class: shear by --set" 0 "$cc" class "$root/one.cfg" --set shear_rate=0.1; has "cost class: pow-generic (shear)" '^pow-generic$'
T "cost class: shear rate 0 is no shear" 0 "$cc" class "$root/one.cfg" --set shear_rate=0.0; has "cost class: pow (rate 0)" '^pow$'
sed 's/s = 0.42; //' "$root/one.cfg" > "$root/std.cfg"
T "cost class: s = 2" 0 "$cc" class "$root/std.cfg"; has "cost class: standard" '^standard$'

# tools/cost rates: a committed run's CPU is brought to the scale of the binary bench/speedup.tsv
# measures against. A git history base -> new -> later, and a side branch off base: speedup.tsv names
# new (with -dirty, as bench.sh writes it) and pow's factor 0.5. Four runs of one pow scene, 100 CPU s
# for 1000 particle-steps each: made at base (0.1 per particle-step), at new and at later
# (descendants: 0.1 / 0.5 = 0.2), and on the side branch (not a descendant: 0.1); and one at later whose
# scene its analysis made (not in the experiment: kept at 0.1). Each run its own experiment, so the
# rate of each is printed alone.
CR=$root/cost-git; rm -rf "$CR"; mkdir -p "$CR/tools/lib" "$CR/bench"
cp "$tools/cost" "$CR/tools/"; cp "$tools/lib/common.sh" "$CR/tools/lib/"
gitq() { git -C "$CR" -c user.name=t -c user.email=t@t -c init.defaultBranch=main "$@" >/dev/null; }
gitq init; gitq commit --allow-empty -m base; c_base=$(git -C "$CR" rev-parse HEAD)
gitq commit --allow-empty -m new; c_new=$(git -C "$CR" rev-parse HEAD)
gitq commit --allow-empty -m later; c_later=$(git -C "$CR" rev-parse HEAD)
gitq checkout -b side "$c_base"; gitq commit --allow-empty -m side; c_side=$(git -C "$CR" rev-parse HEAD)
printf 'class\tcpu_time_new_over_base\trange\tscene\npow\t0.5\t0.5-0.5\ts.cfg\ndate, commits\t2026-01-01\t%s-dirty\n' "$c_new" > "$CR/bench/speedup.tsv"
costrun() { # costrun EXP COMMIT SCENE
    local e=$CR/experiments/c/$1 r=$CR/results/c/$1/paper/runs/a
    mkdir -p "$e" "$r"; cp "$root/one.cfg" "$e/s.cfg"
    printf '%s\n' "$3" > "$r/.args"
    printf 'key\tvalue\ngit_commit\t%s\n' "$2" > "$r/provenance.tsv"
    printf 'quantity\tvalue\tstderr\nparticles\t10\t0\nsteps\t100\t0\ncpu_seconds\t100\t0\n' > "$r/summary.tsv"
    cp "$r/summary.tsv" "$CR/results/c/$1/paper/summary.tsv"
}
costrun at-base "$c_base" s.cfg; costrun at-new "$c_new-dirty" s.cfg; costrun at-later "$c_later" s.cfg
costrun at-side "$c_side" s.cfg; costrun made "$c_later" made-by-analysis.cfg
T "cost rates: a git history with bench/speedup.tsv" 0 "$CR/tools/cost" rates
rate_of() { awk -F'\t' -v e="c/$1" '$1 == e { print $4 }' "$root/out"; }
for x in "at-base 0.1" "at-new 0.2" "at-later 0.2" "at-side 0.1" "made 0.1"; do
    read -r e want <<< "$x"
    [ "$(rate_of "$e")" = "$want" ] && ok "cost rates: run made at $e: $want CPU-s per particle-step" || bad "cost rates: $e: $(rate_of "$e"), wanted $want" "$root/out"
done
T "cost rates: COST_SPEEDUP=0" 0 env COST_SPEEDUP=0 "$CR/tools/cost" rates
[ "$(rate_of at-later)" = 0.1 ] && ok "cost rates: COST_SPEEDUP=0, no scaling" || bad "cost rates: COST_SPEEDUP=0: $(rate_of at-later)" "$root/out"
# tools/cost estimate and table: a planned run of at-later's pow scene, 10 particles for 10 steps
# (a fake simulator's dry run), at the rate 0.2 times pow's factor 0.5: 10 CPU s; a run of a scene
# of the experiment 'made' without a committed rate for it takes the experiment's (0.1 x 0.5 x 100);
# one whose scene does not set up is named in the table's note, not counted
printf '#!/bin/sh\nfor a; do [ "$a" = --dry-run ] && { [ -f "$2" ] || exit 2; printf "particles\\t10\\nequilibration\\t4\\nsteps\\t6\\n"; exit 0; }; done; exit 1\n' > "$CR/fake-dpd"
chmod +x "$CR/fake-dpd"
pr=$CR/planned; mkdir -p "$pr"; printf 's.cfg\n--set\nseed=3\n' > "$pr/.args"; echo "$CR/experiments/c/at-later" > "$pr/.cwd"
T "cost estimate: a planned run" 0 env DPD_BIN="$CR/fake-dpd" "$CR/tools/cost" estimate c/at-later "$pr"
[ "$(cat "$root/out")" = "$(printf '10\t10\t10\t64')" ] && ok "cost estimate: 10 particles, 10 steps, 10 CPU s (rate x class factor), 64 MB" ||
    bad "cost estimate: a planned run" "$root/out"
printf 'missing.cfg\n' > "$pr/.args"
T "cost estimate: a scene that does not set up fails" 1 env DPD_BIN="$CR/fake-dpd" "$CR/tools/cost" estimate c/at-later "$pr"
cat > "$CR/experiments/c/made/run.sh" <<'EOF2'
#!/usr/bin/env bash
mkdir -p "$OUT/runs/a" "$OUT/runs/b" "$OUT/runs/c"
for n in a b c; do pwd > "$OUT/runs/$n/.cwd"; done
printf 's.cfg\n' > "$OUT/runs/a/.args"; printf 's.cfg\n--set\nseed=2\n' > "$OUT/runs/b/.args"; printf 'gone.cfg\n' > "$OUT/runs/c/.args"
printf 'a\nb\nc\n' > "$OUT/.plan"; printf 'rounds\t1\n' > "$OUT/.declared"
EOF2
chmod +x "$CR/experiments/c/made/run.sh"; cp "$tools/plan" "$CR/tools/"
printf 'key\tvalue\ncpu_seconds\t3600\n' > "$CR/results/c/made/paper/provenance.tsv"
T "cost table: an experiment of three planned runs" 0 env DPD_BIN="$CR/fake-dpd" COST_JOBS="$CR/jobs" "$CR/tools/cost" table paper c/made
awk -F'\t' '$1 == "c/made" { found = $2 == 2 && $3 == 200 && $4 == "0.00278" && $10 ~ /^a scene does not set up; rates x pow x0\.5$/ } END { exit !found }' "$root/out" &&
    ok "cost table: 2 simulations, 200 particle-steps, 10 CPU s (the experiment's rate 0.1 x 0.5), the failed scene named" ||
    bad "cost table: c/made" "$root/out"
[ "$(cut -f2,3 "$CR/jobs" | tr '\t\n' ' ')" = "a 5 b 5 " ] && ok "cost table: COST_JOBS lists each projected simulation" || bad "cost table: COST_JOBS" "$CR/jobs"

# tools/progress: the line of make figures / make reproduce from a projection, the plans and the ledger.
# A: three projected simulations (100, 100, 200 CPU s), of which a1 and a2 are planned (a3 was kept
# from an earlier attempt); B: two (50, 50). a1 finishes after two attempts, 150 CPU s, 50 s after the
# start: 1 of 4, spent 150 s; the cost model's finished share 100 s, so the rest (a2 100, b 100) is
# scaled by 1.5: 150 + 300 = 450 s = 7.5 CPU-min; ETA: the rest's 200 s at 100 projected per 50 s = 100 s
PG=$root/progress; PT=$tools/progress; PO=$root/prog-out
mkdir -p "$PG/plan" "$PO/runs/a1" "$PO/runs/a9"
printf 'A\nB\n' > "$PG/experiments"; : > "$PG/ledger"
now=$(date +%s); echo $((now - 50)) > "$PG/t0"
printf 'A\ta1\t100\nA\ta2\t100\nA\ta3\t200\nB\tb1\t50\nB\tb2\t50\n' > "$PG/jobs"
printf 'a1\na2\n' > "$PO/.plan"; printf '100\n50\n' > "$PO/runs/a1/.cpu_seconds"
T "progress: a plan registered" 0 env DPD_PROGRESS="$PG" "$PT" plan A "$PO"
T "progress: a simulation done" 0 env DPD_PROGRESS="$PG" "$PT" done A "$PO" a1
# (the tool reads the clock a moment later: either minute)
has "progress: counts, CPU scaled by the model's error, ETA" "^pool: A a1 done: \[1/4 simulations, 2.5 of 7.5 CPU-min, ETA \($(date -d @$((now + 100)) +%H:%M)\|$(date -d @$((now + 110)) +%H:%M)\)\]$"
T "progress: B finished without running (its projection no longer waited for)" 0 env DPD_PROGRESS="$PG" "$PT" finish B
printf 'a9\n' > "$PO/.plan"; printf '120\n' > "$PO/runs/a9/.cpu_seconds"
DPD_PROGRESS="$PG" "$PT" plan A "$PO"
# a9, a later round's, counts at A's mean projection (400 / 3): spent 270 of 270 + (100 x 270 / 233.3)
T "progress: a later round's simulation" 0 env DPD_PROGRESS="$PG" "$PT" done A "$PO" a9
has "progress: it counts, B does not" '^pool: A a9 done: \[2/3 simulations, 4.5 of 6.4 CPU-min, ETA '
rm -f "$PG/jobs"
T "progress: before the projection is there" 0 env DPD_PROGRESS="$PG" "$PT" done A "$PO" a9
has "progress: says so" '^pool: A a9 done: \[3 simulations, 390 CPU-s; projecting the total\]$'
T "progress: without DPD_PROGRESS, nothing" 0 env -u DPD_PROGRESS "$PT" done A "$PO" a9
if [ -s "$root/out" ]; then bad "progress: printed without DPD_PROGRESS" "$root/out"; else ok "progress: silent without DPD_PROGRESS"; fi

fi # part 1

if [ "$part" = 2 ]; then
# ---------------------------------------------------------------- run-experiment: resume
# A fixture repository with a fake simulator: an interrupted experiment leaves
# no result (check: MISSING), keeps its finished simulations, and the next
# attempt reruns only the unfinished one (with --resume); a simulation whose
# scene or arguments changed reruns; another binary starts afresh; --reanalyse.
rx="$root/rx"
mkdir -p "$rx/experiments/t/e"
cp -r "$tools" "$rx/tools"
cat > "$rx/fake-dpd" <<'EOF2'
#!/usr/bin/env bash
[ "${1:-}" = --version ] && { echo "dpd fake1"; exit 0; }
out=; resume=0; args=("$@")
for ((i = 0; i < $#; i++)); do
    case ${args[i]} in --out) out=${args[i + 1]} ;; --resume) resume=1 ;; esac
done
mkdir -p "$out"; echo run > "$out/INCOMPLETE"
echo "$(basename "$out") resume=$resume" >> "$FAKE_LOG"
[ "$(basename "$out")" = "${FAKE_FAIL:-}" ] && exit 137
code=FAKE_EXIT_$(basename "$out"); [ -n "${!code:-}" ] && exit "${!code}"
sleep "${FAKE_SLEEP:-0}"
printf 'quantity\tvalue\tstderr\nq\t1.5\t0.1\n' > "$out/summary.tsv"
printf 'key\tvalue\ncpu_seconds\t1\ndate\t2020-0%s-01T00:00:00Z\n' "$(( $(basename "$out" | cksum | cut -c1) % 9 + 1 ))" > "$out/provenance.tsv"
rm "$out/INCOMPLETE"
EOF2
cat > "$rx/experiments/t/e/run.sh" <<'EOF2'
#!/usr/bin/env bash
. "$DPD_ROOT/tools/lib/exp.sh"
simulations() {
dpd_run a s.cfg --set x=1
dpd_run b s.cfg --set x=2
}
analysis() {
emit_from a q q_a
emit_from b q q_b
}
experiment
EOF2
chmod +x "$rx/fake-dpd" "$rx/experiments/t/e/run.sh"
echo 'x = 1;' > "$rx/experiments/t/e/s.cfg"
{ echo "$BANDS_HEADER"; tab q_a quick claim 1 2 - - - fixture; tab q_b quick claim 1 2 - - - fixture; } > "$rx/experiments/t/e/bands.tsv"
{ tab group quantities statement paper; tab q '^q_' 'the fixture' '-'; } > "$rx/experiments/t/e/claims.tsv"
log="$root/fake.log"
RX() { env -u DPD_ROOT DPD_BIN="$rx/fake-dpd" FAKE_LOG="$log" "$@"; }
( cd "$rx" && git init -q . 2>/dev/null ) || true
: > "$log"
T "run-experiment: interrupted run fails" 1 RX FAKE_FAIL=b "$rx/tools/run-experiment" t/e quick
if [ ! -e "$rx/results/t/e/quick/summary.tsv" ]; then ok "run-experiment: no result after the interruption"; else bad "run-experiment: result after the interruption"; fi
T "check: interrupted experiment is MISSING" 1 env DPD_ROOT="$rx" "$rx/tools/check" t/e
has "check: interrupted -> MISSING" 'MISSING'
: > "$log"
T "run-experiment: second attempt completes" 0 RX "$rx/tools/run-experiment" t/e quick
if [ "$(cat "$log")" = "b resume=1" ]; then ok "run-experiment: resumed, reran only the unfinished simulation"
else bad "run-experiment: resume reran: $(tr '\n' ' ' < "$log")"; fi
T "check: resumed experiment passes" 0 env DPD_ROOT="$rx" "$rx/tools/check" t/e
in_file "run-experiment: provenance counts the simulations" "$rx/results/t/e/quick/provenance.tsv" '^simulations	2$'
in_file "run-experiment: provenance counts the one finished by the earlier attempt" "$rx/results/t/e/quick/provenance.tsv" '^simulations_from_earlier_attempts	1$'
if [ "$(grep -c '^q_' "$rx/results/t/e/quick/summary.tsv")" = 2 ]; then ok "run-experiment: no duplicate summary rows after resume"
else bad "run-experiment: summary rows" "$rx/results/t/e/quick/summary.tsv"; fi
: > "$log"
T "run-experiment: interrupted again" 1 RX FAKE_FAIL=b "$rx/tools/run-experiment" t/e quick
echo 'x = 2;' > "$rx/experiments/t/e/s.cfg"
: > "$log"
T "run-experiment: partial result with a changed scene completes" 0 RX "$rx/tools/run-experiment" t/e quick
if [ "$(sort "$log" | tr '\n' ' ')" = "a resume=1 b resume=1 " ]; then ok "run-experiment: a changed scene reruns the simulations that use it"
else bad "run-experiment: after a change ran: $(tr '\n' ' ' < "$log")"; fi
# the stamp is the binary and the tier: a change of the analysis alone keeps the finished
# simulations of an interrupted attempt; another binary starts afresh
cp "$rx/experiments/t/e/run.sh" "$root/run.sh.orig"
T "run-experiment: interrupted once more" 1 RX FAKE_FAIL=b "$rx/tools/run-experiment" t/e quick
sed -i 's/^emit_from b q q_b$/&\nemit extra 1 0/' "$rx/experiments/t/e/run.sh"
: > "$log"
T "run-experiment: resumes after a change of the analysis" 0 RX "$rx/tools/run-experiment" t/e quick
if [ "$(tr '\n' ' ' < "$log")" = "b resume=1 " ]; then ok "run-experiment: analysis change keeps the finished simulation"
else bad "run-experiment: after an analysis change ran: $(tr '\n' ' ' < "$log")"; fi
in_file "run-experiment: the changed analysis is applied" "$rx/results/t/e/quick/summary.tsv" '^extra	1	0$'
T "run-experiment: interrupted with the old binary" 1 RX FAKE_FAIL=b "$rx/tools/run-experiment" t/e quick
{ cat "$rx/fake-dpd"; echo '# another build'; } > "$rx/fake-dpd2"; chmod +x "$rx/fake-dpd2"
: > "$log"
T "run-experiment: another binary" 0 env -u DPD_ROOT DPD_BIN="$rx/fake-dpd2" FAKE_LOG="$log" "$rx/tools/run-experiment" t/e quick
if [ "$(sort "$log" | tr '\n' ' ')" = "a resume=1 b resume=1 " ]; then ok "run-experiment: another binary starts afresh"
else bad "run-experiment: with another binary ran: $(tr '\n' ' ' < "$log")"; fi
# --reanalyse: the complete result's simulations, only those whose arguments changed rerun
cp "$root/run.sh.orig" "$rx/experiments/t/e/run.sh"
# (the provenance before: its date and host made distinct, as if the run were made elsewhere)
sed -i 's/^date	.*/date	2001-01-01T00:00:00Z/; s/^host_cpu	.*/host_cpu	somewhere else/' "$rx/results/t/e/quick/provenance.tsv"
cp "$rx/results/t/e/quick/provenance.tsv" "$rx/prov.before"
: > "$log"
T "run-experiment --reanalyse: analysis only" 0 RX "$rx/tools/run-experiment" t/e quick --reanalyse
if [ ! -s "$log" ]; then ok "run-experiment --reanalyse: no simulation"; else bad "run-experiment --reanalyse ran: $(tr '\n' ' ' < "$log")"; fi
if grep -q '^extra' "$rx/results/t/e/quick/summary.tsv"; then bad "run-experiment --reanalyse: old analysis kept" "$rx/results/t/e/quick/summary.tsv"
else ok "run-experiment --reanalyse: the current analysis"; fi
# a reanalysis simulates nothing: where and when the simulations ran stays as recorded
prov=$rx/results/t/e/quick/provenance.tsv
in_file "run-experiment --reanalyse: says when it reanalysed" "$prov" '^reanalysed	'
in_file "run-experiment --reanalyse: the simulations' date range" "$prov" '^simulated	.* [.][.] .* (2 simulations)$'
if [ "$(awk -F'\t' '$1 == "date" { print $2 }' "$prov")" = "$(awk -F'\t' '$1 == "date" { print $2 }' "$rx/prov.before")" ] &&
   [ "$(awk -F'\t' '$1 == "host_cpu" { print $2 }' "$prov")" = "$(awk -F'\t' '$1 == "host_cpu" { print $2 }' "$rx/prov.before")" ]; then
    ok "run-experiment --reanalyse: keeps the run's date and host"
else bad "run-experiment --reanalyse: date or host replaced" "$prov"; fi
sed -i 's/--set x=2/--set x=3/' "$rx/experiments/t/e/run.sh"
: > "$log"
T "run-experiment --reanalyse: changed arguments" 0 RX "$rx/tools/run-experiment" t/e quick --reanalyse
if [ "$(tr '\n' ' ' < "$log")" = "b resume=1 " ]; then ok "run-experiment --reanalyse: reruns only the changed simulation"
else bad "run-experiment --reanalyse ran: $(tr '\n' ' ' < "$log")"; fi
T "run-experiment: unknown option refused" 1 RX "$rx/tools/run-experiment" t/e quick --reanalyze
cp "$root/run.sh.orig" "$rx/experiments/t/e/run.sh"
T "run-experiment --reanalyse: back to the original arguments" 0 RX "$rx/tools/run-experiment" t/e quick --reanalyse
# declare, then dispatch: a plan pass records the simulations, the pool runs them at once, the
# next pass plans again; a run.sh whose later simulations take arguments from its analysis declares rounds
mkdir -p "$rx/experiments/t/p"
cat > "$rx/experiments/t/p/run.sh" <<'EOF2'
#!/usr/bin/env bash
. "$DPD_ROOT/tools/lib/exp.sh"
simulations() { for x in 1 2 3; do dpd_run p$x s.cfg --set x=$x; done; }
analysis() { emit_from p1 q q_p1; }
# round 2: its argument from the analysis of round 1 (declared twice: planned once)
simulations_2() {
    dpd_run late s.cfg --set x=$(from_analysis q_p1 | cut -f1)
    dpd_run late s.cfg --set x=$(from_analysis q_p1 | cut -f1)
}
analysis_2() { emit_from late q q_late; }
experiment
EOF2
chmod +x "$rx/experiments/t/p/run.sh"; cp "$rx/experiments/t/e/s.cfg" "$rx/experiments/t/p/"
T "plan: lists the first round without running anything" 0 env -u DPD_ROOT DPD_BIN="$rx/fake-dpd" FAKE_LOG="$log" "$rx/tools/plan" t/p quick
has "plan: the three declared simulations" '^p3	s.cfg	--set	x=3$'
lacks "plan: not the one that needs an analysis" '^late'
has "plan: says the experiment declares a later round" 'simulations in the first round; 1 later round'
: > "$log"
T "run-experiment: rounds until a pass plans nothing" 0 RX FAKE_SLEEP=1 "$rx/tools/run-experiment" t/p quick
if [ "$(sort "$log" | tr '\n' ' ')" = "late resume=1 p1 resume=1 p2 resume=1 p3 resume=1 " ]; then ok "run-experiment: every simulation ran once"
else bad "run-experiment: rounds ran: $(tr '\n' ' ' < "$log")"; fi
in_file "run-experiment: two rounds and the analysis" "$rx/results/t/p/quick/provenance.tsv" '^rounds	3$'
in_file "run-experiment: the late simulation's argument came from the first round" "$rx/results/t/p/quick/runs/late/.args" '^x=1.5$'
# the plan is declared: tools/plan calls the declaration of the first round alone, so an analysis
# that would fail, or take long, never runs (the former planner ran run.sh until a step failed,
# analysis included); a simulation declared in the analysis is refused
mkdir -p "$rx/experiments/t/s"
cat > "$rx/experiments/t/s/run.sh" <<'EOF2'
#!/usr/bin/env bash
. "$DPD_ROOT/tools/lib/exp.sh"
simulations() { dpd_run s1 s.cfg --set x=1; dpd_run s2 s.cfg --set x=2; }
# an analysis that reads no simulation, takes a minute and fails
analysis() { : > "$FAKE_LOG.analysis"; sleep "${FAKE_ANALYSIS_SLEEP:-0}"; echo "the analysis failed" >&2; exit 1; }
experiment
EOF2
chmod +x "$rx/experiments/t/s/run.sh"; cp "$rx/experiments/t/e/s.cfg" "$rx/experiments/t/s/"
rm -f "$log.analysis"
T "plan: a slow, failing analysis is not run" 0 env -u DPD_ROOT DPD_BIN="$rx/fake-dpd" FAKE_LOG="$log" FAKE_ANALYSIS_SLEEP=60 timeout 20 "$rx/tools/plan" t/s quick
has "plan: its declared simulations listed" '^s2	s.cfg	--set	x=2$'
if [ -e "$log.analysis" ]; then bad "plan: ran the analysis"; else ok "plan: no analysis step ran"; fi
sed -i 's/^analysis() { /&dpd_run s3 s.cfg --set x=3; /' "$rx/experiments/t/s/run.sh"
T "run-experiment: a simulation in the analysis is refused" 1 RX "$rx/tools/run-experiment" t/s quick
has "run-experiment: says where to declare it" 'dpd_run s3 in the analysis of .*: declare it in its simulations'
# an analysis that runs simulations itself (declared: analysis_runs_simulations=1, the stability
# map's bisections): the declared ones on the pool first, then the analysis in the normal mode
mkdir -p "$rx/experiments/t/d"
cat > "$rx/experiments/t/d/run.sh" <<'EOF2'
#!/usr/bin/env bash
. "$DPD_ROOT/tools/lib/exp.sh"
analysis_runs_simulations=1
simulations() { dpd_run a s.cfg --set x=1; }
analysis() {
    emit_from a q q_a
    "$DPD" run s.cfg --out "$OUT/runs/direct" --set x=9
    emit_from direct q q_direct
}
experiment
EOF2
chmod +x "$rx/experiments/t/d/run.sh"; cp "$rx/experiments/t/e/s.cfg" "$rx/experiments/t/d/"
T "plan: an analysis that runs simulations itself" 0 env -u DPD_ROOT DPD_BIN="$rx/fake-dpd" FAKE_LOG="$log" "$rx/tools/plan" t/d quick
has "plan: says so" '1 simulations in the first round; its analysis runs simulations itself'
: > "$log"
T "run-experiment: an analysis that runs simulations itself" 0 RX "$rx/tools/run-experiment" t/d quick
if [ "$(tr '\n' ' ' < "$log")" = "a resume=1 direct resume=0 " ]; then ok "run-experiment: the declared simulation on the pool, then the analysis's own"
else bad "run-experiment: ran: $(tr '\n' ' ' < "$log")"; fi
in_file "run-experiment: the analysis read its own simulation" "$rx/results/t/d/quick/summary.tsv" '^q_direct	1.5	0.1$'
in_file "run-experiment: an analysis's own simulations: their simulator recorded" "$rx/results/t/d/quick/provenance.tsv" '^analysis_simulator	fake1$'
# its reanalysis runs them again, here: a run, whose provenance is this attempt's (not the old
# date and host a reanalysis of declared simulations keeps)
sed -i 's/^date	.*/date	2001-01-01T00:00:00Z/; s/^host_cpu	.*/host_cpu	somewhere else/' "$rx/results/t/d/quick/provenance.tsv"
: > "$log"
T "run-experiment --reanalyse: an analysis that runs simulations itself" 0 RX "$rx/tools/run-experiment" t/d quick --reanalyse
if [ "$(tr '\n' ' ' < "$log")" = "direct resume=0 " ]; then ok "run-experiment --reanalyse: the analysis's own simulation ran again, the declared one kept"
else bad "run-experiment --reanalyse: ran: $(tr '\n' ' ' < "$log")"; fi
not_in_file "run-experiment --reanalyse: simulations in the analysis, so not the old date" "$rx/results/t/d/quick/provenance.tsv" '^date	2001-01-01T00:00:00Z$'
not_in_file "run-experiment --reanalyse: simulations in the analysis, so not the old host" "$rx/results/t/d/quick/provenance.tsv" '^host_cpu	somewhere else$'
in_file "run-experiment --reanalyse: simulations in the analysis: their simulator" "$rx/results/t/d/quick/provenance.tsv" '^analysis_simulator	fake1$'
# every experiment of the repository declares its simulations (functions simulations and analysis,
# run.sh ending with the line experiment: tools/lib/exp.sh), or runs another's run.sh that does
# (fig05-relative-viscosity-a650: fig04's with another repulsion)
: > "$root/out"
for f in "$tools"/../experiments/*/*/run.sh; do
    last=$(grep -v '^[[:space:]]*\(#\|$\)' "$f" | tail -1)
    case $last in 'exec "$(dirname "$0")/../'*'/run.sh" "$@"') continue ;; esac
    grep -q '^simulations() {' "$f" && grep -q '^analysis() {' "$f" &&
        [ "$last" = experiment ] || echo "${f#"$tools"/../}" >> "$root/out"
done
if [ ! -s "$root/out" ] && [ -n "$(ls "$tools"/../experiments/*/*/run.sh)" ]; then ok "experiments: every run.sh declares its simulations and analysis"
else bad "experiments: run.sh without the declaration (simulations, analysis, experiment)" "$root/out"; fi
# the pool: the first round's three one-second simulations overlap on two slots
cat > "$root/overlap.sh" <<'EOF2'
#!/usr/bin/env bash
echo "start $(date +%s.%N)" >> "$FAKE_LOG.t"; "$FAKE_REAL" "$@"; st=$?; echo "end $(date +%s.%N)" >> "$FAKE_LOG.t"; exit $st
EOF2
chmod +x "$root/overlap.sh"; rm -rf "$rx/results/t/p"; : > "$log.t"
T "run-experiment: a pool of two slots" 0 env -u DPD_ROOT DPD_BIN="$root/overlap.sh" FAKE_REAL="$rx/fake-dpd" FAKE_LOG="$log" FAKE_SLEEP=1 DPD_JOBS=2 "$rx/tools/run-experiment" t/p quick
if awk '{ d = ($1 == "start") ? 1 : -1; n += d; if (n > m) m = n } END { exit !(m == 2) }' "$log.t"; then ok "pool: two simulations ran at once, never three"
else bad "pool: concurrency not 2" "$log.t"; fi
# a simulation that ended unstable (exit 3) is an outcome: not rerun, its status returned
mkdir -p "$rx/experiments/t/u"
cat > "$rx/experiments/t/u/run.sh" <<'EOF2'
#!/usr/bin/env bash
. "$DPD_ROOT/tools/lib/exp.sh"
simulations() {
    dpd_run ok s.cfg --set x=1
    dpd_run bad s.cfg --set x=2 || true
    st=0; dpd_run bad s.cfg --set x=2 || st=$?
}
analysis() { emit bad_status $st 0; }
experiment
EOF2
chmod +x "$rx/experiments/t/u/run.sh"; cp "$rx/experiments/t/e/s.cfg" "$rx/experiments/t/u/"
: > "$log"
T "run-experiment: an unstable simulation is an outcome" 0 RX FAKE_EXIT_bad=3 "$rx/tools/run-experiment" t/u quick
if [ "$(sort "$log" | tr '\n' ' ')" = "bad resume=1 ok resume=1 " ]; then ok "run-experiment: the unstable simulation ran once"
else bad "run-experiment: with an unstable simulation ran: $(tr '\n' ' ' < "$log")"; fi
in_file "run-experiment: its status reaches the analysis" "$rx/results/t/u/quick/summary.tsv" '^bad_status	3	0$'
# an analysis that emits an empty value (a computation in $(...) that failed, whose status an
# argument loses) fails the experiment, naming the quantity; no result is written
mkdir -p "$rx/experiments/t/v"
cat > "$rx/experiments/t/v/run.sh" <<'EOF2'
#!/usr/bin/env bash
. "$DPD_ROOT/tools/lib/exp.sh"
simulations() { dpd_run ok s.cfg --set x=1; }
analysis() { emit fine 1 0; emit lost "$(false)"; }
experiment
EOF2
chmod +x "$rx/experiments/t/v/run.sh"; cp "$rx/experiments/t/e/s.cfg" "$rx/experiments/t/v/"
T "run-experiment: an empty value emitted fails the experiment" 1 RX "$rx/tools/run-experiment" t/v quick
has "run-experiment: the empty value named" "emit lost: no value"
[ ! -e "$rx/results/t/v/quick" ] && ok "run-experiment: no result with an empty value" || bad "run-experiment: a result with an empty value" "$rx/results/t/v/quick/summary.tsv"
# tsv_lookup and get read a row alike (one parser): an empty field stays a field, a row with the
# quantity's name as a prefix is not the quantity's, a missing row is an error naming the file
mkdir -p "$rx/experiments/t/w"
cat > "$rx/experiments/t/w/run.sh" <<'EOF2'
#!/usr/bin/env bash
. "$DPD_ROOT/tools/lib/exp.sh"
simulations() { dpd_run ok s.cfg --set x=1; }
analysis() {
    printf 'q_long\t9\t9\nq\t\t0.5\textra\nr\t2\n' > "$OUT/t.tsv"
    cp "$OUT/t.tsv" "$OUT/runs/ok/summary.tsv"
    local l g w m
    l=$(tsv_lookup "$OUT/t.tsv" q); g=$(get ok q); w=$(getv ok r)
    m=$(tsv_lookup "$OUT/t.tsv" nope who 2>&1) || true
    [ "$l" = $'\t0.5' ] && emit lookup_empty_field 1 0 || emit lookup_empty_field 0 0
    [ "$g" = "$l" ] && emit get_as_lookup 1 0 || emit get_as_lookup 0 0
    [ "$w" = 2 ] && [ "$(tsv_lookup "$OUT/t.tsv" r)" = $'2\t' ] && emit short_row 1 0 || emit short_row 0 0
    [ "$m" = "who: no nope in $OUT/t.tsv" ] && emit missing_named 1 0 || emit missing_named 0 0
}
experiment
EOF2
chmod +x "$rx/experiments/t/w/run.sh"; cp "$rx/experiments/t/e/s.cfg" "$rx/experiments/t/w/"
T "run-experiment: tsv_lookup and get read one table" 0 RX "$rx/tools/run-experiment" t/w quick
for q in lookup_empty_field get_as_lookup short_row missing_named; do
    in_file "tsv_lookup / get: $q" "$rx/results/t/w/quick/summary.tsv" "^$q	1	0$"
done
# a failure that persists (exit 4, I/O) is retried DPD_MAX_FAILURES times, then fails the experiment
rm -rf "$rx/results/t/e/.quick.partial"; : > "$log"
T "run-experiment: a persistent I/O failure fails the experiment" 1 RX FAKE_EXIT_b=4 "$rx/tools/run-experiment" t/e quick
if [ "$(grep -c '^b' "$log")" = 3 ]; then ok "run-experiment: retried three times"; else bad "run-experiment: I/O failure ran: $(tr '\n' ' ' < "$log")"; fi
: > "$log"
T "run-experiment: a new attempt retries it" 0 RX "$rx/tools/run-experiment" t/e quick
if [ "$(tr '\n' ' ' < "$log")" = "b resume=1 " ]; then ok "run-experiment: the new attempt ran only the failed one"; else bad "run-experiment: new attempt ran: $(tr '\n' ' ' < "$log")"; fi
# needs / upstream: one declaration; an undeclared read is refused; needs.awk orders make
mkdir -p "$rx/experiments/t/n"
cat > "$rx/experiments/t/n/run.sh" <<'EOF2'
#!/usr/bin/env bash
. "$DPD_ROOT/tools/lib/exp.sh"
needs any t/e
needs paper t/p
needs any t/p@paper
simulations() { :; }
analysis() {
emit up "$(awk -F'\t' '$1 == "q_a" { print $2 }' "$(upstream t/e)/summary.tsv")" 0
[ -z "$(upstream_if t/p@paper)" ] && emit optional_absent 1 0
upstream t/u
}
experiment
EOF2
chmod +x "$rx/experiments/t/n/run.sh"
T "needs: an undeclared upstream result is refused" 1 RX "$rx/tools/run-experiment" t/n quick
has "needs: says what to declare" "read but not declared (add a line 'needs quick t/u'"
sed -i '/^upstream t\/u$/d' "$rx/experiments/t/n/run.sh"
T "needs: declared upstream results read" 0 RX "$rx/tools/run-experiment" t/n quick
in_file "needs: the same tier's result" "$rx/results/t/n/quick/summary.tsv" '^up	1.5	0$'
in_file "needs: an absent optional result" "$rx/results/t/n/quick/summary.tsv" '^optional_absent	1	0$'
( cd "$rx" && awk -f tools/lib/needs.awk experiments/t/n/run.sh ) > "$root/out"
has "needs.awk: any -> the make rule at every tier" '^results/t/n/$(TIER)/summary.tsv: results/t/e/$(TIER)/summary.tsv$'
has "needs.awk: a listed tier" '^results/t/n/paper/summary.tsv: results/t/p/paper/summary.tsv$'
lacks "needs.awk: a fixed-tier reference orders nothing" 't/p@paper'

# carry-partial: an interrupted run's finished simulations committed (not the unfinished one,
# not run.h5 or checkpoints) and resumed from a clone of that commit on "another machine"
T "run-experiment: interrupted before carrying" 1 RX FAKE_FAIL=b "$rx/tools/run-experiment" t/e quick
echo big > "$rx/results/t/e/.quick.partial/runs/a/run.h5"; echo big > "$rx/results/t/e/.quick.partial/runs/b/checkpoint.dpd"
cp "$tools/../.gitignore" "$rx/.gitignore"
T "carry-partial: refuses another binary" 1 env DPD_BIN="$rx/fake-dpd2" "$rx/tools/carry-partial" t/e quick
printf 'the run.sh change of an extension\n' > "$rx/results/t/e/.quick.partial/extension.patch"
T "carry-partial: stages the finished simulations" 0 env DPD_BIN="$rx/fake-dpd" "$rx/tools/carry-partial" t/e quick
staged=$(git -C "$rx" diff --cached --name-only | tr '\n' ' ')
case $staged in *.quick.partial/extension.patch*) ok "carry-partial: an extension's run.sh patch staged" ;; *) bad "carry-partial: extension.patch not staged: $staged" ;; esac
in_file "carry-partial: RESUME.txt names the extension's patch" "$rx/results/t/e/.quick.partial/RESUME.txt" '^extension.patch: .*git apply'
case $staged in
    *.quick.partial/.stamp*.quick.partial/RESUME.txt*runs/a/summary.tsv*) ok "carry-partial: stamp, RESUME.txt and the finished run staged" ;;
    *) bad "carry-partial: staged: $staged" ;;
esac
case $staged in
    *runs/b/*|*run.h5*|*checkpoint*) bad "carry-partial: staged the unfinished run or a large file: $staged" ;;
    *) ok "carry-partial: no unfinished run, run.h5 or checkpoint staged" ;;
esac
case $staged in
    */.cwd*) bad "carry-partial: staged a file that names this machine's paths (.cwd): $staged" ;;
    *) ok "carry-partial: no .cwd (this machine's paths) staged" ;;
esac
in_file "carry-partial: RESUME.txt names the binary's commit" "$rx/results/t/e/.quick.partial/RESUME.txt" 'built from commit fake1'
( cd "$rx" && git add .gitignore experiments tools && git -c user.name=t -c user.email=t@t commit -qm carry ) >/dev/null 2>&1
rm -rf "$root/rx2"; git clone -q "$rx" "$root/rx2" 2>/dev/null
T "carry-partial: an interrupted resume in a clone" 1 env -u DPD_ROOT DPD_BIN="$rx/fake-dpd" FAKE_LOG="$log" FAKE_FAIL=b "$root/rx2/tools/run-experiment" t/e quick
if git -C "$root/rx2" diff --quiet -- results; then ok "carry-partial: the interrupted resume kept every carried file (RESUME.txt too)"
else bad "carry-partial: the interrupted resume changed carried files: $(git -C "$root/rx2" diff --name-status -- results | tr '\n' ' ')"; fi
: > "$log"
T "carry-partial: resumed in a clone" 0 env -u DPD_ROOT DPD_BIN="$rx/fake-dpd" FAKE_LOG="$log" "$root/rx2/tools/run-experiment" t/e quick
if [ "$(tr '\n' ' ' < "$log")" = "b resume=1 " ]; then ok "carry-partial: the clone reran only the unfinished simulation"
else bad "carry-partial: the clone ran: $(tr '\n' ' ' < "$log")"; fi
in_file "carry-partial: the clone's result is complete" "$root/rx2/results/t/e/quick/summary.tsv" '^q_b	1.5	0.1$'
# an extension carried as extension.patch (the run.sh change that declares its runs): refused until
# the patch is applied, --reanalyse refused (it would discard the carried runs), kept through the
# passes, left out of the result
( cd "$rx" && printf '# the extension\n' >> experiments/t/e/run.sh && git diff experiments/t/e/run.sh > "$root/ext.patch" \
    && git checkout -q experiments/t/e/run.sh )
T "run-experiment: interrupted again (extension)" 1 RX FAKE_FAIL=b "$rx/tools/run-experiment" t/e quick
cp "$root/ext.patch" "$rx/results/t/e/.quick.partial/extension.patch"
T "run-experiment: an unapplied extension.patch is refused" 1 RX "$rx/tools/run-experiment" t/e quick
has "run-experiment: names the patch to apply" 'extension.patch is not applied'
T "run-experiment: --reanalyse refused beside an extension" 1 RX "$rx/tools/run-experiment" t/e quick --reanalyse
has "run-experiment: says the carried runs would be lost" 'extension in progress'
in_file "run-experiment: the refusals kept the patch" "$rx/results/t/e/.quick.partial/extension.patch" 'the extension'
git -C "$rx" apply "$root/ext.patch"
T "run-experiment: resumes once the patch is applied" 0 RX "$rx/tools/run-experiment" t/e quick
if [ ! -e "$rx/results/t/e/quick/extension.patch" ] && [ ! -e "$rx/results/t/e/.quick.partial" ]; then
    ok "run-experiment: the result leaves the patch out"
else bad "run-experiment: extension.patch left in the result or partial"; fi
git -C "$rx" checkout -q experiments/t/e/run.sh
# with another binary the carried runs are not used: it starts afresh from run.sh as it stands (make
# reproduce on a new build) and keeps the patch beside the next partial
T "run-experiment: interrupted again (extension, another binary)" 1 RX FAKE_FAIL=b "$rx/tools/run-experiment" t/e quick
cp "$root/ext.patch" "$rx/results/t/e/.quick.partial/extension.patch"
T "run-experiment: another binary beside an extension runs afresh" 0 env -u DPD_ROOT DPD_BIN="$rx/fake-dpd2" FAKE_LOG="$log" "$rx/tools/run-experiment" t/e quick
if [ -f "$rx/results/t/e/.quick.partial/extension.patch" ] && [ ! -e "$rx/results/t/e/quick/extension.patch" ]; then
    ok "run-experiment: the unapplied patch kept beside the next partial, not in the result"
else bad "run-experiment: the unapplied patch lost or in the result"; fi
rm -rf "$rx/results/t/e/.quick.partial"
# carry-partial runs the run.sh's keep_run for every finished simulation (what its analysis reads
# from run.h5, which is not carried): made from run.h5 and staged; a finished one with neither
# stops the carry with nothing staged; a run.sh without keep_run carries as before (t/e above)
mkdir -p "$rx/experiments/t/k"
cat > "$rx/experiments/t/k/run.sh" <<'EOF2'
#!/usr/bin/env bash
. "$DPD_ROOT/tools/lib/exp.sh"
keep_run() {
    [ -f "$OUT/runs/$1/blocks.tsv" ] && return 0
    [ -f "$OUT/runs/$1/run.h5" ] || { echo "t/k: runs/$1 has neither blocks.tsv nor run.h5" >&2; return 1; }
    sed 's/^/block /' "$OUT/runs/$1/run.h5" > "$OUT/runs/$1/blocks.tsv"
}
simulations() { echo "t/k: simulations in a keep pass" >&2; exit 9; }
analysis() { echo "t/k: analysis in a keep pass" >&2; exit 9; }
experiment
EOF2
chmod +x "$rx/experiments/t/k/run.sh"
kp=$rx/results/t/k/.quick.partial
mkdir -p "$kp/runs/a" "$kp/runs/b" "$kp/runs/c"
( . "$tools/lib/common.sh"; partial_stamp quick "$rx/fake-dpd" ) > "$kp/.stamp"
for n in a b c; do printf 'quantity\tvalue\tstderr\nq\t1\t0\n' > "$kp/runs/$n/summary.tsv"; done
echo series > "$kp/runs/a/run.h5"; echo 'block kept' > "$kp/runs/b/blocks.tsv"; echo run > "$kp/runs/c/INCOMPLETE"
T "carry-partial: keep_run for each finished simulation" 0 env DPD_BIN="$rx/fake-dpd" "$rx/tools/carry-partial" t/k quick
in_file "carry-partial: keep_run made a's table from its run.h5" "$kp/runs/a/blocks.tsv" '^block series$'
staged=$(git -C "$rx" diff --cached --name-only -- results/t/k | tr '\n' ' ')
case $staged in
    *runs/a/blocks.tsv*runs/b/blocks.tsv*) ok "carry-partial: the kept tables staged" ;;
    *) bad "carry-partial: kept tables not staged: $staged" ;;
esac
[ ! -e "$kp/summary.tsv" ] && ok "carry-partial: the keep pass wrote nothing else (no summary.tsv)" || bad "carry-partial: the keep pass wrote summary.tsv"
git -C "$rx" reset -q -- results/t/k
rm "$kp/runs/a/blocks.tsv" "$kp/runs/a/run.h5"
T "carry-partial: a finished simulation with neither its table nor run.h5 stops the carry" 1 env DPD_BIN="$rx/fake-dpd" "$rx/tools/carry-partial" t/k quick
has "carry-partial: names the simulation" 'runs/a has neither blocks.tsv nor run.h5'
[ -z "$(git -C "$rx" diff --cached --name-only -- results/t/k)" ] && ok "carry-partial: nothing staged when keep_run fails" ||
    bad "carry-partial: staged despite keep_run failing: $(git -C "$rx" diff --cached --name-only -- results/t/k | tr '\n' ' ')"
rm -rf "$rx/results/t/k" "$rx/experiments/t/k"

# ---------------------------------------------------------------- verify-result
# The analysis redone from the kept runs (no simulation): fresh while nothing
# changed; stale when a scene's content, a run's arguments, the analysis or the
# stored table changed; unverifiable when run.sh simulates outside dpd_run.
V() { env -u DPD_ROOT DPD_BIN="$rx/fake-dpd" FAKE_LOG="$log" "$rx/tools/verify-result" t/e quick; }
e="$rx/experiments/t/e"
: > "$log"
T "verify-result: unchanged result is fresh" 0 V
has "verify-result: says fresh" '^fresh'
if [ ! -s "$log" ]; then ok "verify-result: ran no simulation"; else bad "verify-result: simulated: $(tr '\n' ' ' < "$log")"; fi
cp "$e/s.cfg" "$root/s.cfg.keep"; echo 'x = 3;' > "$e/s.cfg"
T "verify-result: changed scene content is stale" 1 V
has "verify-result: names the rerun" "would be rerun"
cp "$root/s.cfg.keep" "$e/s.cfg"; cp "$e/run.sh" "$root/run.sh.keep"
sed -i 's/--set x=2/--set x=5/' "$e/run.sh"
T "verify-result: changed run arguments are stale" 1 V
cp "$root/run.sh.keep" "$e/run.sh"; sed -i 's/^emit_from b q q_b$/&\nemit extra 1 0/' "$e/run.sh"
T "verify-result: changed analysis is stale" 1 V
has "verify-result: names the summary" "another summary.tsv"
cp "$root/run.sh.keep" "$e/run.sh"
T "verify-result: restored inputs are fresh again" 0 V
sed -i 's/^q_a\t1.5/q_a\t1.6/' "$rx/results/t/e/quick/summary.tsv"
T "verify-result: an edited result is stale" 1 V
sed -i 's/^q_a\t1.6/q_a\t1.5/' "$rx/results/t/e/quick/summary.tsv"
echo '"$DPD" run s.cfg --out "$OUT/runs/direct"' >> "$e/run.sh"
T "verify-result: simulations outside dpd_run are unverifiable" 3 V
if [ ! -s "$log" ]; then ok "verify-result: the direct run was refused"; else bad "verify-result: simulated: $(tr '\n' ' ' < "$log")"; fi
cp "$root/run.sh.keep" "$e/run.sh"
T "verify-results: all fresh, exit 0" 0 env -u DPD_ROOT DPD_BIN="$rx/fake-dpd" "$rx/tools/verify-results" -o "$root/fresh.tsv"
in_file "verify-results: table row" "$root/fresh.tsv" '^t/e	quick	fresh'
# a verification that stops without a verdict (here: no simulator) is not a pass
T "verify-results: a verification without a verdict fails" 1 env -u DPD_ROOT DPD_BIN="$rx/no-such-dpd" "$rx/tools/verify-results" -o "$root/fresh.tsv"
in_file "verify-results: it counts as stale, with the reason" "$root/fresh.tsv" '^t/e	quick	stale	tools/verify-result stopped without a verdict (exit 2)'
echo 'x = 4;' > "$e/s.cfg"
T "verify-results: a stale result fails" 1 env -u DPD_ROOT DPD_BIN="$rx/fake-dpd" "$rx/tools/verify-results" -o "$root/fresh.tsv"
has "verify-results: names it" 'STALE t/e \[quick\]'
printf "<!-- summary-table -->\n" > "$root/fresh.in.md"
T "paper-filter: summary shows the stale result" 0 env MKPAPER_FRESHNESS="$root/fresh.tsv" DPD_ROOT="$rx" "$rx/tools/render-paper" -i "$root/fresh.in.md" -o "$root/fresh.md"
in_file "paper-filter: inputs column STALE" "$root/fresh.md" '^| `t/e` .*| \*\*STALE\*\* *|$'
cp "$root/s.cfg.keep" "$e/s.cfg"

# reuse_run: another experiment's simulation copied, not rerun, its CPU not counted twice
mkdir -p "$rx/experiments/t/r"
cat > "$rx/experiments/t/r/run.sh" <<'EOF2'
#!/usr/bin/env bash
. "$DPD_ROOT/tools/lib/exp.sh"
needs any t/e
simulations() { reuse_run a t/e quick; }
analysis() { emit_from a q q_a; }
experiment
EOF2
chmod +x "$rx/experiments/t/r/run.sh"
: > "$log"
T "reuse_run: experiment made from another's simulation" 0 RX "$rx/tools/run-experiment" t/r quick
if [ ! -s "$log" ]; then ok "reuse_run: no simulation"; else bad "reuse_run: simulated: $(tr '\n' ' ' < "$log")"; fi
in_file "reuse_run: origin recorded" "$rx/results/t/r/quick/runs/a/REUSED_FROM" '^results/t/e/quick/runs/a$'
in_file "reuse_run: its CPU not counted again" "$rx/results/t/r/quick/provenance.tsv" '^cpu_seconds	0.000$'
T "reuse_run: the reusing result verifies fresh" 0 env -u DPD_ROOT DPD_BIN="$rx/fake-dpd" "$rx/tools/verify-result" t/r quick
sed -i 's/^q\t1.5/q\t1.7/' "$rx/results/t/e/quick/runs/a/summary.tsv"
T "reuse_run: stale when the reused simulation changed" 1 env -u DPD_ROOT DPD_BIN="$rx/fake-dpd" "$rx/tools/verify-result" t/r quick
sed -i 's/^q\t1.7/q\t1.5/' "$rx/results/t/e/quick/runs/a/summary.tsv"
mv "$rx/results/t/e" "$rx/results/t/e.away"
T "reuse_run: fails clearly without the other result" 1 RX "$rx/tools/run-experiment" t/r quick
has "reuse_run: names what to make" 'make results/t/e/quick/summary.tsv'
mv "$rx/results/t/e.away" "$rx/results/t/e"

# a paper tier never run whose reduced tier is committed: NOTRUN, not a failure; a paper tier
# that was started and left incomplete still fails (MISSING)
mkdir -p "$root/experiments/x/nr"
{ echo "$BANDS_HEADER"; tab q paper claim 1 2 - - 1.5 fixture; tab q reduced claim 1 2 - - 1.5 fixture; } > "$root/experiments/x/nr/bands.tsv"
mkres x/nr reduced 1 <<< "$(tab q 1.6 0.1)"
T "check: paper tier not run, reduced committed: exit 0" 0 "$C" --tier paper x/nr
has "check: NOTRUN shown" "NOTRUN"
has "check: NOTRUN counted apart" "1 rows not run"
T "check: the reduced tier itself" 0 "$C" --tier reduced x/nr
mkdir -p "$root/results/x/nr/paper"; : > "$root/results/x/nr/paper/INCOMPLETE"
T "check: a paper tier left incomplete fails" 1 "$C" --tier paper x/nr
has "check: MISSING, not NOTRUN" "MISSING"
rm -rf "$root/results/x/nr/paper"

# known non-reproductions: expect = fail (8th column) -> XFAIL, not a failure; XPASS is one
mkdir -p "$root/experiments/x/xf" "$root/experiments/x/xp"
{ echo "$BANDS_HEADER"; tab q quick claim 0 inf - - '>0' 'paper claim' fail; } > "$root/experiments/x/xf/bands.tsv"
mkres x/xf quick 1 <<< "$(tab q -3.2 1.0)"
T "check: known non-reproduction (expect fail) is XFAIL, exit 0" 0 "$C" x/xf
has "check: XFAIL shown" "XFAIL"
has "check: XFAIL counted apart" "1 of them known non-reproductions"
{ echo "$BANDS_HEADER"; tab q quick claim 0 inf - - '>0' 'paper claim' fail; } > "$root/experiments/x/xp/bands.tsv"
mkres x/xp quick 1 <<< "$(tab q 3.2 0.5)"
T "check: a known non-reproduction that passes is XPASS, exit 1" 1 "$C" x/xp
has "check: XPASS shown" "XPASS"

# tools/regression-refs: the quick tier's references from its own result
mkdir -p "$root/experiments/x/rr"
{ echo "$BANDS_HEADER"; tab q paper claim 1 4 - - 2.4 'a claim'; tab t quick gate 0.9 1.1 - - 1 'a gate'
  tab old quick regression 7 7 4 0.2 - 'an earlier reference'; } > "$root/experiments/x/rr/bands.tsv"
mkres x/rr quick 1 <<EOF3
$(tab q 2.5 0.1)
$(tab t 1.0 0.01)
$(tab old 7.1 0.05)
$(tab nose 3 0)
EOF3
RR=$tools/regression-refs
T "regression-refs: takes the references" 0 "$RR" x/rr
has "regression-refs: counts them" 'x/rr: 2 reference'
in_file "regression-refs: a claim's quantity referenced, k = 4, resolution twice its stderr" "$root/experiments/x/rr/bands.tsv" '^q	quick	regression	2.5	2.5	4	0.2	-	regression reference: the quick tier at tree , binary abc123 (2.5 +- 0.1)'
in_file "regression-refs: an earlier reference retaken" "$root/experiments/x/rr/bands.tsv" '^old	quick	regression	7.1	7.1	4	0.1	'
if grep -q '^old	quick	regression	7	7' "$root/experiments/x/rr/bands.tsv"; then bad "regression-refs: the earlier row removed"; else ok "regression-refs: the earlier row removed"; fi
if grep -q '^t	quick	regression' "$root/experiments/x/rr/bands.tsv"; then bad "regression-refs: a gate's quantity is not referenced"; else ok "regression-refs: a gate's quantity is not referenced"; fi
T "regression-refs: the tier passes its own references" 0 "$C" x/rr
has "regression-refs: counted" 'regression references: 2 of 2 passed'
mkres x/rr quick 1 <<EOF3
$(tab q 2.95 0.1)
$(tab t 1.0 0.01)
$(tab old 7.1 0.05)
EOF3
T "regression-refs: a value 4.5 se away fails check" 1 "$C" x/rr
has "regression-refs: the moved value FAILs" '^x/rr  *q  .*regression .*FAIL'

# ---------------------------------------------------------------- one driver at a time, and its children end with it
# A slow fake simulator (sleeps; on SIGTERM it logs "NAME TERM" and exits 143, as dpd does after
# its checkpoint). (1) A second tools/run-experiment of the same experiment and tier stops at once
# naming the holder, and the first completes. (2) A SIGKILLed tools/run-experiment, and a SIGKILLed
# make driving it (experiments.mk), leave no process of the fixture running (its path in the
# command line: run-experiment, the pool's make, run-simulation, the fake simulator), and the
# simulators got SIGTERM (a real one writes its checkpoint). (3) The same with the Slurm engine
# (fake sbatch, squeue, scontrol): no slurm-sim left polling. (4) A Slurm job cancelled (scancel)
# and not requeued within DPD_SLURM_CANCEL_GRACE: the experiment stops, saying so, and does not
# submit it again; run again, it resubmits and completes.
cat > "$rx/fake-slow" <<'EOF2'
#!/usr/bin/env bash
[ "${1:-}" = --version ] && { echo "dpd fake1"; exit 0; }
out=; args=("$@")
for ((i = 0; i < $#; i++)); do case ${args[i]} in --out) out=${args[i + 1]} ;; --dry-run) out=- ;; esac; done
[ "$out" = - ] && { printf 'particles\t10\nequilibration\t0\nsteps\t10\noverdamped\t0\n'; exit 0; }   # tools/cost
mkdir -p "$out"; echo run > "$out/INCOMPLETE"
echo "$(basename "$out") start $$" >> "$FAKE_LOG"
trap 'echo "$(basename "$out") TERM" >> "$FAKE_LOG"; exit 143' TERM
sleep "${FAKE_SLEEP:-60}" & wait $!
printf 'quantity\tvalue\tstderr\nq\t1.5\t0.1\n' > "$out/summary.tsv"
printf 'key\tvalue\ncpu_seconds\t1\ndate\t2020-0%s-01T00:00:00Z\n' "$(( $(basename "$out" | cksum | cut -c1) % 9 + 1 ))" > "$out/provenance.tsv"
rm "$out/INCOMPLETE"
EOF2
chmod +x "$rx/fake-slow"
# gone PATTERN: no process whose command line holds PATTERN within 15 s (prints those left)
gone() { local k; for k in $(seq 150); do pgrep -f -- "$1" >/dev/null || return 0; sleep 0.1; done; pgrep -af -- "$1"; return 1; }
started() { local k; for k in $(seq 300); do [ "$(grep -c ' start ' "$log" 2>/dev/null)" -ge "$1" ] && return 0; sleep 0.1; done; return 1; }
SLOW=(env -u DPD_ROOT -u MAKEFLAGS -u MAKELEVEL DPD_BIN="$rx/fake-slow" FAKE_LOG="$log" DPD_JOBS=2)
rm -rf "$rx/results/t/e"
: > "$log"
"${SLOW[@]}" FAKE_SLEEP=4 "$rx/tools/run-experiment" t/e quick > "$root/first.out" 2>&1 & first=$!
started 1 || bad "lock: the first run-experiment did not start a simulation" "$root/first.out"
T "lock: a second run-experiment of the same experiment and tier stops" 1 "${SLOW[@]}" "$rx/tools/run-experiment" t/e quick
has "lock: it names the holder (pid, host, start time)" "t/e \[quick\] is being run by pid $first on $(hostname) since 20[0-9-]*T[0-9:]*Z"
if wait $first; then ok "lock: the first completes"; else bad "lock: the first failed" "$root/first.out"; fi
T "lock: free again once the first ended" 0 "${SLOW[@]}" FAKE_SLEEP=0 "$rx/tools/run-experiment" t/e quick
rm -rf "$rx/results/t/e"
: > "$log"
"${SLOW[@]}" "$rx/tools/run-experiment" t/e quick > "$root/killed.out" 2>&1 & drv=$!
if started 2; then
    kill -KILL $drv; wait $drv 2>/dev/null
    if gone "$rx/"; then ok "SIGKILLed run-experiment: no process of it left"; else bad "SIGKILLed run-experiment: processes left running"; pgrep -f -- "$rx/" | xargs -r kill -KILL; fi
    [ "$(grep -c ' TERM$' "$log")" = 2 ] && ok "SIGKILLed run-experiment: both simulators got SIGTERM (checkpoint)" || bad "SIGKILLed run-experiment: simulators' signals: $(tr '\n' ' ' < "$log")"
else bad "SIGKILLed run-experiment: simulations did not start" "$root/killed.out"; fi
cp "$tools/../experiments/experiments.mk" "$rx/experiments/experiments.mk"
printf 'SHELL := /bin/bash\nTIER ?= quick\ninclude experiments/experiments.mk\n' > "$rx/Makefile"
rm -rf "$rx/results/t/e"
: > "$log"
( cd "$rx" && exec "${SLOW[@]}" make results EXPERIMENTS=t/e TIER=quick BIN="$rx/fake-slow" > "$root/make.out" 2>&1 ) & drv=$!
if started 2; then
    mk=$(pgrep -f "make results EXPERIMENTS=t/e TIER=quick BIN=$rx/fake-slow" | head -1)
    kill -KILL "$mk"; wait $drv 2>/dev/null
    if gone "$rx/"; then ok "SIGKILLed make figures: no process of it left"; else bad "SIGKILLed make: processes left running"; pgrep -f -- "$rx/" | xargs -r kill -KILL; fi
    [ "$(grep -c ' TERM$' "$log")" = 2 ] && ok "SIGKILLed make: both simulators got SIGTERM (checkpoint)" || bad "SIGKILLed make: simulators' signals: $(tr '\n' ' ' < "$log")"
else bad "SIGKILLed make: simulations did not start" "$root/make.out"; fi
# fake Slurm: sbatch runs nothing and logs; squeue reports each job in the state of $FAKE_SQ/ID
# (RUNNING unless set); a job named like a simulation is found while its state file says so
sq=$root/fake-slurm; mkdir -p "$sq/bin"
cat > "$sq/bin/sbatch" <<'EOF2'
#!/usr/bin/env bash
# two simulations submit at once: the job number is read and written under a lock, or both read
# a half-written file and one gets job 1, which no state file names (it then runs for ever)
exec 9> "$FAKE_SQ/next.lock"; flock 9
n=$(( $(cat "$FAKE_SQ/next" 2>/dev/null || echo 100) + 1 )); echo $n > "$FAKE_SQ/next"
for a in "$@"; do case $a in --job-name=*) echo "${a#--job-name=}" > "$FAKE_SQ/$n.name" ;; esac; done
echo "sbatch $n" >> "$FAKE_LOG"; echo "$n"
EOF2
cat > "$sq/bin/squeue" <<'EOF2'
#!/usr/bin/env bash
j=; for a in "$@"; do case $a in --name=*) exit 0 ;; esac; done
while [ $# -gt 0 ]; do [ "$1" = -j ] && j=$2; shift; done
[ -n "$j" ] && cat "$FAKE_SQ/$j.state" 2>/dev/null || { [ -n "$j" ] && echo RUNNING; }
EOF2
printf '#!/bin/sh\necho "scontrol $*" >> "$FAKE_LOG"\n' > "$sq/bin/scontrol"
chmod +x "$sq/bin/"*
SQ=(PATH="$sq/bin:$PATH" FAKE_SQ="$sq" DPD_ENGINE=slurm DPD_SLURM_POLL=0.2 DPD_SLURM_ANALYSIS=local)
rm -rf "$rx/results/t/e"; rm -f "$sq"/*.state "$sq"/*.name "$sq/next"
: > "$log"
"${SLOW[@]}" "${SQ[@]}" "$rx/tools/run-experiment" t/e quick > "$root/slurm-killed.out" 2>&1 & drv=$!
for _ in $(seq 300); do [ "$(grep -c '^sbatch' "$log")" -ge 2 ] && break; sleep 0.1; done
if [ "$(grep -c '^sbatch' "$log")" -ge 2 ]; then
    kill -KILL $drv; wait $drv 2>/dev/null
    if gone "$rx/tools/slurm-sim"; then ok "SIGKILLed run-experiment (Slurm engine): no slurm-sim left polling"
    else bad "SIGKILLed run-experiment (Slurm engine): slurm-sim left running"; pgrep -f -- "$rx/" | xargs -r kill -KILL; fi
else bad "Slurm engine: the jobs were not submitted" "$root/slurm-killed.out"; fi
# scancel without requeue: the state CANCELLED for good
rm -rf "$rx/results/t/e"; rm -f "$sq"/*.state "$sq"/*.name "$sq/next"
: > "$log"
for n in 101 102 103 104 105 106; do echo CANCELLED > "$sq/$n.state"; done
T "scancel, no requeue within the grace: the experiment stops" 1 timeout 60 "${SLOW[@]}" "${SQ[@]}" DPD_SLURM_CANCEL_GRACE=1 "$rx/tools/run-experiment" t/e quick
has "scancel: says that the job was cancelled and not requeued" "was cancelled (scancel) and not requeued within DPD_SLURM_CANCEL_GRACE"
[ "$(grep -c '^sbatch' "$log")" = 2 ] && ok "scancel: each simulation submitted once, none again" || bad "scancel: submissions: $(grep -c '^sbatch' "$log") ($(tr '\n' ' ' < "$log"))"
rm -f "$sq"/*.state
: > "$log"
# run again: resubmitted; the fake jobs then "complete" (a finished simulation in their directory)
( sleep 1; for r in "$rx"/results/t/e/.quick.partial/runs/*/; do printf 'quantity\tvalue\tstderr\nq\t1.5\t0.1\n' > "$r/summary.tsv"; printf 'key\tvalue\ncpu_seconds\t1\n' > "$r/provenance.tsv"; rm -f "$r/INCOMPLETE"; done
  for n in $(seq 101 110); do echo COMPLETED > "$sq/$n.state"; done ) &
T "scancel: run again, the experiment resubmits and completes" 0 timeout 60 "${SLOW[@]}" "${SQ[@]}" "$rx/tools/run-experiment" t/e quick
wait
pgrep -f -- "$rx/" | xargs -r kill -KILL   # nothing of a failed check outlives the harness

fi # part 2

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
