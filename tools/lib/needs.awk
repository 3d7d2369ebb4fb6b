# tools/lib/needs.awk - the make prerequisites between experiments, from the `needs TIERS ID`
# lines of experiments/PAPER/EXP/run.sh (tools/lib/exp.sh needs): each result of a tier in TIERS
# ("any": every tier) depends on the same tier's result of ID. A dependency on a fixed tier
# (ID@TIER: a committed result read as a reference) orders nothing: it is never remade by the
# experiments that read it.
# usage: awk -f tools/lib/needs.awk experiments/*/*/run.sh > build/needs.mk
FNR == 1 { id = FILENAME; sub(/^(\.\/)?experiments\//, "", id); sub(/\/run\.sh$/, "", id) }
$1 == "needs" && NF >= 3 && $3 !~ /@/ {
    n = split($2, t, ",")
    for (i = 1; i <= n; i++) {
        tier = (t[i] == "any") ? "$(TIER)" : t[i]
        printf "results/%s/%s/summary.tsv: results/%s/%s/summary.tsv\n", id, tier, $3, tier
    }
}
