#!/usr/bin/env bash
# precision.sh - issue 38 item 1: the standard error that decides each pan-2008 claim under the
# decision rule of issue 37, and the CPU-hours the plain time average needs for it in the paper's
# box, from the committed results alone (nothing is simulated).
#
#   precision.sh [CLAIMS]   TSV on stdout (CLAIMS: the table of claims below, default claim-runs.tsv here)
#   PRECISION_REL=R precision.sh ENTRIES
#                           the same for a relative stderr R of each entry instead of a band (item 5:
#                           Pan's 0.5 %): ENTRIES has a sixth column, the paper's value; se to reach is
#                           R x |paper's value| and R x |our value|; lo, hi and the verdict are "-"
#
# The rule: a claim's band [lo, hi] is never widened; with the run's stderr se the claim PASSes when
# value +- 2 se lies inside the band, FAILs when it lies wholly outside, else is UNRESOLVED. So a run
# whose true value is x decides the claim once se < d(x) / 2, d(x) the distance of x to the nearest
# band edge (inside or outside). The table gives that se for two assumed true values: the paper's
# own number (bands.tsv column `paper`) and our committed value.
#
# CPU-hours of the plain time average: the committed runs' variance per production CPU second,
# a = se_k^2 x CPU_k (production share of the runs' cpu_seconds, scaled to the current binary by the
# run's cost class in bench/speedup.tsv, as tools/cost does). A claim whose error has independent
# parts from separate simulations (tab02's drag: the sphere's run and the empty channel's u_h) needs,
# at the best split, (sum_k sqrt(a_k))^2 / se^2 CPU seconds; one part: a / se^2. Equilibration is
# added once per run as committed. The bands are the `paper` rows of each experiment's bands.tsv
# (the intervals, k_sigma ignored: the rule does not widen).
set -euo pipefail
root=${DPD_ROOT:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)}
here=$root/experiments/methods/pan-estimators
claims=${1:-$here/claim-runs.tsv}
speed=$root/bench/speedup.tsv

# run_cost DIR EXPDIR -> "prod_cpu_s<TAB>eq_cpu_s<TAB>prod_time_units" of one committed run, its CPU
# scaled by its class factor; equilibration and dt from its arguments, else its scene
run_cost() {
    local dir=$1 expdir=$2 scene cls fac
    mapfile -t a < "$dir/.args"
    scene=$expdir/${a[0]}
    cls=$(cd "$expdir" && "$root/tools/cost" class "${a[@]}")
    fac=$(awk -F'\t' -v c="$cls" '$1 == c { v = $2 } END { print (v == "" ? 1 : v) }' "$speed" 2>/dev/null || echo 1)
    printf '%s\n' "${a[@]:1}" | awk -F'\t' -v scene="$scene" -v fac="$fac" -v sum="$dir/summary.tsv" '
        BEGIN { while ((getline l < scene) > 0) { sub(/#.*/, "", l)
                    if (match(l, /^[ \t]*equilibration[ \t]*=[ \t]*[0-9]+/)) { e = l; sub(/.*=[ \t]*/, "", e); eq = e + 0 }
                    if (match(l, /^[ \t]*dt[ \t]*=[ \t]*[0-9.eE+-]+/)) { e = l; sub(/.*=[ \t]*/, "", e); dt = e + 0 } }
                while ((getline l < sum) > 0) { split(l, f, "\t"); v[f[1]] = f[2] } }
        /^equilibration=/ { sub(/^[^=]*=/, ""); eq = $0 + 0 }
        /^dt=/ { sub(/^[^=]*=/, ""); dt = $0 + 0 }
        END { n = v["steps"]; c = v["cpu_seconds"] * fac; p = (n - eq) / n
              printf "%.6g\t%.6g\t%.6g\n", c * p, c * (1 - p), (n - eq) * dt }'
}

out=$(mktemp); trap 'rm -f "$out"' EXIT
{
printf 'experiment\tquantity\tlo\thi\tpaper\tvalue\tse\tverdict_now\tse_decides_paper\tse_decides_ours\tprod_time_now\tcpu_h_now\tcpu_h_paper\tcpu_h_ours\tlongest_sim_h_paper\tnote\n'
while IFS= read -r line; do
    # fields split at tabs, empty ones kept (a tab in IFS would merge them)
    IFS=$'\037' read -r exp tier q groups note paper_value <<< "$(printf '%s' "$line" | tr '\t' '\037')"
    case $exp in ''|'#'*|experiment) continue ;; esac
    res=$root/results/$exp/$tier expdir=$root/experiments/$exp
    if [ -n "${PRECISION_REL:-}" ]; then band="-	-	${paper_value:--}"
    else band=$(awk -F'\t' -v q="$q" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }   # columns by name (issue 37 adds some)
        $1 == q && $2 == "paper" && (!("kind" in c) || $c["kind"] == "claim") { print $c["lo"] "\t" $c["hi"] "\t" $c["paper"]; exit }' "$expdir/bands.tsv"); fi
    vs=$(awk -F'\t' -v q="$q" '$1 == q { print $2 "\t" $3; exit }' "$res/summary.tsv")
    [ -n "$band" ] && [ -n "$vs" ] || { echo "precision.sh: $exp $q: no paper band or no committed value" >&2; exit 1; }
    # each group: its runs' production CPU (a_k = se_k^2 x CPU_k), equilibration CPU, time units
    parts=""
    IFS=';' read -ra gs <<< "$groups"
    for g in "${gs[@]}"; do
        runs=${g%%|*} relq=${g#*|}; [ "$relq" = "$g" ] && relq=-
        pc=0 ec=0 tu=0
        for r in ${runs//,/ }; do
            read -r p e t < <(run_cost "$res/runs/$r" "$expdir")
            pc=$(awk -v a=$pc -v b=$p 'BEGIN { print a + b }'); ec=$(awk -v a=$ec -v b=$e 'BEGIN { print a + b }')
            tu=$(awk -v a=$tu -v b=$t 'BEGIN { print a + b }')
        done
        # the group's share of the claim's error: the whole se, or the relative error of one summary quantity
        rel=-; [ "$relq" != - ] && rel=$(awk -F'\t' -v q="$relq" '$1 == q { print $3 / ($2 < 0 ? -$2 : $2); exit }' "$res/summary.tsv")
        parts="$parts $pc:$ec:$tu:$rel:$(echo "$runs" | tr ',' ' ' | wc -w)"
    done
    printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$exp" "$q" "$band" "$vs" "$parts" "${note:-}" | awk -F'\t' -v relmode="${PRECISION_REL:-}" '
        function dist(x) { return x < lo ? lo - x : (x > hi ? x - hi : (x - lo < hi - x ? x - lo : hi - x)) }
        function hours(se,    c) { if (se <= 0) return "inf"; c = S * S / (se * se) + EQ; return sprintf("%.4g", c / 3600) }
        function longest(se,    c) { if (se <= 0) return "inf"; c = S * S / (se * se) / NR_ + EQ / NR_; return sprintf("%.4g", c / 3600) }
        { ex = $1; q = $2; lo = $3; hi = $4; paper = $5; v = $6; se = $7; note = $9
          n = split($8, g, " "); S = 0; EQ = 0; T = 0; NR_ = 0; var = se * se; fixed = 0
          # the groups: a part given by a relative error is that share of se^2; a part "-" takes
          # what the others leave (one group: all of it)
          for (i = 1; i <= n; i++) { split(g[i], f, ":"); pc[i] = f[1]; ec[i] = f[2]; rel[i] = f[4]; nr[i] = f[5]
              if (rel[i] != "-") { s2[i] = (v * rel[i]) ^ 2; fixed += s2[i] } }
          for (i = 1; i <= n; i++) { if (rel[i] == "-") s2[i] = var - fixed; if (s2[i] < 0) s2[i] = 0
              S += sqrt(s2[i] * pc[i]); EQ += ec[i]; if (i == 1) { T = f[3] + 0; split(g[1], f1, ":"); T = f1[3]; NR_ = nr[1] } }
          if (relmode != "") { verdict = "-"; sp = paper == "-" ? -1 : relmode * (paper < 0 ? -paper : paper); so = relmode * (v < 0 ? -v : v) } else {
          verdict = (v - 2 * se >= lo && v + 2 * se <= hi) ? "PASS" : ((v + 2 * se < lo || v - 2 * se > hi) ? "FAIL" : "UNRESOLVED")
          sp = paper == "-" ? -1 : dist(paper) / 2; so = dist(v) / 2 }
          cnow = 0; for (i = 1; i <= n; i++) cnow += pc[i] + ec[i]
          printf "%s\t%s\t%s\t%s\t%s\t%.6g\t%.4g\t%s\t%.3g\t%.3g\t%.6g\t%.3g\t%s\t%s\t%s\t%s\n", ex, q, lo, hi, paper, v, se, verdict,
                 sp, so, T, cnow / 3600, hours(sp), hours(so), longest(sp), note }'
done < "$claims"
} > "$out"
cat "$out"   # written only when every claim was found: a failure leaves no table
