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
# the analysis layer (tools/analysis.py): through the analysis server of the experiment that runs
# this script, when it has one (tools/lib/exp.sh, analyse_serve), else tools/analyse
ANALYSE=$root/tools/analyse
[ -n "${DPD_ANALYSE_SOCKET:-}" ] && [ -x "$root/build/analyse-client" ] && ANALYSE=$root/build/analyse-client

# the factor of every committed run of the claims' results (tools/cost run-factors: its class's
# factor, or 1 for a run whose binary has the speed-up already), in one call for all of them
declare -A run_factor_of=()
while IFS=$'\t' read -r d f; do run_factor_of[$d]=$f; done < <(
    awk -F'\t' '$1 != "" && $1 !~ /^#/ && $1 != "experiment" { print $1 "\t" $2 }' "$claims" | LC_ALL=C sort -u |
    while IFS=$'\t' read -r exp tier; do
        for d in "$root/results/$exp/$tier/runs"/*/; do [ -s "$d.args" ] && printf '%s\t%s\n' "$exp" "${d%/}"; done
    done | "$root/tools/cost" run-factors)

# run_cost_args DIR EXP: appends to cost_args the arguments of `analyse run-costs-sum` for one
# committed run (prod_cpu_s, eq_cpu_s and prod_time_units, summed over a group's runs in one call):
# its CPU on this build's scale (its factor, above); equilibration and dt from its arguments, else
# its scene
run_cost_args() {
    local dir=$1 exp=$2 fac a
    mapfile -t a < "$dir/.args"
    fac=${run_factor_of[$dir]:-}
    [ -n "$fac" ] || fac=$("$root/tools/cost" run-factor "$exp" "$dir")
    cost_args+=($(( ${#a[@]} - 1 )) "$root/experiments/$exp/${a[0]}" "$dir/summary.tsv" "$fac" "${a[@]:1}")
}

out=$(mktemp); trap 'rm -f "$out"' EXIT
{
printf 'experiment@tier\tquantity\tlo\thi\tpaper\tvalue\tse\tverdict_now\tse_decides_paper\tse_decides_ours\tprod_time_now\tcpu_h_now\tcpu_h_paper\tcpu_h_ours\tlongest_sim_h_paper\tnote\n'
while IFS= read -r line; do
    # fields split at tabs, empty ones kept (a tab in IFS would merge them)
    IFS=$'\037' read -r exp tier q groups note paper_value <<< "$(printf '%s' "$line" | tr '\t' '\037')"
    case $exp in ''|'#'*|experiment) continue ;; esac
    res=$root/results/$exp/$tier expdir=$root/experiments/$exp
    if [ -n "${PRECISION_REL:-}" ]; then band="-	-	${paper_value:--}"
    else band=$("$ANALYSE" paper-band "$expdir/bands.tsv" "$q"); fi   # columns by name (issue 37 adds some)
    vs=$("$ANALYSE" lookup "$res/summary.tsv" "$q" || true)
    [ -n "$band" ] && [ -n "$vs" ] || { echo "precision.sh: $exp $q: no paper band or no committed value" >&2; exit 1; }
    # each group: its runs' production CPU (a_k = se_k^2 x CPU_k), equilibration CPU, time units
    parts=""
    IFS=';' read -ra gs <<< "$groups"
    for g in "${gs[@]}"; do
        runs=${g%%|*} relq=${g#*|}; [ "$relq" = "$g" ] && relq=-
        # the group's runs: names, each a committed run, or shell patterns (row1r*: the replicas
        # committed, maybe none); a group of no run is refused
        names=""
        IFS=',' read -ra toks <<< "$runs"
        for tok in "${toks[@]}"; do
            case $tok in
                *[*?[]*) names="$names $(cd "$res/runs" 2>/dev/null && { compgen -G "$tok" || true; } | LC_ALL=C sort | tr '\n' ' ')" ;;
                *) [ -s "$res/runs/$tok/.args" ] || { echo "precision.sh: $exp $q: no committed run $res/runs/$tok" >&2; exit 1; }
                   names="$names $tok" ;;
            esac
        done
        [ -n "${names// /}" ] || { echo "precision.sh: $exp $q: no committed run matches $runs in $res/runs" >&2; exit 1; }
        cost_args=()
        for r in $names; do run_cost_args "$res/runs/$r" "$exp"; done
        pc= ec= tu=
        read -r pc ec tu < <("$ANALYSE" run-costs-sum "${cost_args[@]}") || true
        [ -n "$tu" ] || { echo "precision.sh: $exp $q: no cost of the runs $names" >&2; exit 1; }
        # the group's share of the claim's error: the whole se, or the relative error of one summary quantity
        rel=-; [ "$relq" != - ] && rel=$("$ANALYSE" rel-error-of "$res/summary.tsv" "$relq")
        parts="$parts $pc:$ec:$tu:$rel:$(echo $names | wc -w)"
    done
    "$ANALYSE" precision-row "${PRECISION_REL:-}" "$(printf '%s\t%s\t%s\t%s\t%s\t%s' "$exp@$tier" "$q" "$band" "$vs" "$parts" "${note:-}")"
done < "$claims"
} > "$out"
cat "$out"   # written only when every claim was found: a failure leaves no table
