# groups.awk -- the claim groups of one experiment: every claim row of its bands.tsv in exactly one
# group of its claims.tsv. POSIX awk (mawk and gawk). Run by tools/check --groups.
#
# usage: awk -v eid=ID [-v tsv=1] -f groups.awk CLAIMS_TSV BANDS_TSV
#   CLAIMS_TSV may be /dev/null (the experiment has no claims.tsv: an error if it has a claim row).
#
# claims.tsv ('#' lines and blank lines skipped; the first other line is the header
# "group quantities statement paper", tab-separated, in that order), one row per group:
#   group       its short name (unique in the file)
#   quantities  an awk regular expression (ERE) matched against the quantity names of the claim rows
#   statement   the paper's claim in words, quoted where the paper states it
#   paper       the number as the paper prints it (text)
# The groups of a summary row are the claims of the paper that a reader judges together (a table
# column, a statement with several numbers); the summary and the cards of paper.md show one row per
# group (tools/lib/paper-filter.lua).
#
# Errors (one line each, "ID: message"; exit 1): no claims.tsv while bands.tsv has claims; a header
# other than the four columns; a row without four non-empty fields; a group named twice; a regular
# expression that matches no claim quantity; a claim quantity (of any tier) that no group or more than
# one group matches.
# -v tsv=1: instead of "ok"/errors on stdout, for every claim quantity (in the order of bands.tsv, each
# once) "ID <TAB> quantity <TAB> group number <TAB> group" on stdout, the errors on stderr (exit 1 if any).

function trim(s) { sub(/^[ \t\r]+/, "", s); sub(/[ \t\r]+$/, "", s); return s }
function err(msg) { nerr++; if (tsv) print eid ": " msg > "/dev/stderr"; else print eid ": " msg }
BEGIN { FS = "\t" }
FNR == 1 { file = (FILENAME == ARGV[1]) ? 1 : 2; header = 0 }
{ sub(/\r$/, "") }
/^#/ || /^[ \t]*$/ { next }
file == 1 && !header {
    header = 1; have_claims = 1
    if (NF != 4 || trim($1) != "group" || trim($2) != "quantities" || trim($3) != "statement" || trim($4) != "paper")
        err("claims.tsv line " FNR ": the header must be: group, quantities, statement, paper (tab-separated)")
    next
}
file == 1 {
    if (NF != 4 || trim($1) == "" || trim($2) == "" || trim($3) == "" || trim($4) == "") {
        err("claims.tsv line " FNR ": expected 4 non-empty tab-separated fields (group, quantities, statement, paper), got " NF); next
    }
    g = trim($1)
    if (g in gnum) { err("claims.tsv line " FNR ": group '" g "' is named twice"); next }
    ng++; gnum[g] = ng; gname[ng] = g; gre[ng] = trim($2); gline[ng] = FNR
    next
}
file == 2 && !header {
    header = 1
    for (i = 1; i <= NF; i++) C[trim($i)] = i
    if (!("quantity" in C) || !("kind" in C)) { err("bands.tsv: no quantity or kind column"); exit 1 }
    next
}
file == 2 {
    if (trim($(C["kind"])) != "claim") next
    q = trim($(C["quantity"]))
    if (q in seen) next
    seen[q] = 1; nq++; quant[nq] = q
}
END {
    if (nq > 0 && !have_claims) err("bands.tsv has " nq " claim quantities but there is no claims.tsv (experiments/" eid "/claims.tsv)")
    for (i = 1; i <= nq; i++) {
        q = quant[i]; hits = 0; names = ""
        for (j = 1; j <= ng; j++) if (q ~ gre[j]) { hits++; used[j]++; names = names (hits > 1 ? ", " : "") "'" gname[j] "'"; hit = j }
        if (hits == 0 && have_claims) err("claim " q " belongs to no group of claims.tsv")
        else if (hits > 1) err("claim " q " belongs to " hits " groups: " names)
        else if (hits == 1 && tsv) printf "%s\t%s\t%d\t%s\n", eid, q, hit, gname[hit]
    }
    for (j = 1; j <= ng; j++) if (!used[j]) err("claims.tsv line " gline[j] ": group '" gname[j] "' (" gre[j] ") matches no claim quantity")
    if (!tsv && nerr == 0) printf "%s: ok, %d claim quantities in %d groups\n", eid, nq, ng
    exit nerr > 0
}
