# paper-points.awk -- the paper's values and their tolerance for a plot (experiments/plot-style.gp,
# PAPER_POINTS): from the claim rows of one bands.tsv whose quantity matches RE and whose tier is
# TIER or "*" (if there are none, the paper tier's), one line per row: x, value, lo, hi, quantity.
# x: the number that follows RE's match in the quantity name ("-" if none); value: the paper column
# if it is a number, else the band's centre (else its finite edge); lo, hi: the band, an infinite
# side replaced by the value (a one-sided band is drawn as a bar to its edge).
# usage: awk -F'\t' -v re=REGEX -v tier=TIER -f paper-points.awk bands.tsv
function isnum(s) { return s ~ /^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$/ }
NR == 1 { for (i = 1; i <= NF; i++) C[$i] = i; next }
/^#/ || $(C["kind"]) != "claim" { next }
{
    q = $(C["quantity"]); t = $(C["tier"])
    if (!match(q, re)) next
    rest = substr(q, RSTART + RLENGTH); x = "-"
    if (match(rest, /^[0-9]+\.?[0-9]*([eE][+-]?[0-9]+)?/)) x = substr(rest, RSTART, RLENGTH)
    lo = $(C["lo"]); hi = $(C["hi"]); p = $(C["paper"])
    if (isnum(p)) v = p
    else if (isnum(lo) && isnum(hi)) v = (lo + hi) / 2
    else if (isnum(lo)) v = lo
    else if (isnum(hi)) v = hi
    else next
    if (!isnum(lo)) lo = v
    if (!isnum(hi)) hi = v
    line = x "\t" v "\t" lo "\t" hi "\t" q
    if (t == tier || t == "*") { mine[++nm] = line }
    else if (t == "paper") { fallback[++nf] = line }
}
END {
    if (nm > 0) for (i = 1; i <= nm; i++) print mine[i]
    else for (i = 1; i <= nf; i++) print fallback[i]
}
