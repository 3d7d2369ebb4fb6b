# common.sh -- shared helpers of the tools (sourced, bash): tools/check, tools/verify-results,
# tools/lib/paper-filter.lua (the ids of the summary table), ...
# DPD_ROOT: root of the tree to work on (default: the repository top, found
# from this file's location).

_dpd_lib_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)
DPD_TOOLS=$(dirname "$_dpd_lib_dir")
DPD_ROOT=${DPD_ROOT:-$(dirname "$DPD_TOOLS")}
DPD_ROOT=$(cd "$DPD_ROOT" && pwd -P) || { echo "DPD_ROOT not a directory" >&2; exit 2; }
BANDS_AWK="$_dpd_lib_dir/bands.awk"

# partial_stamp TIER BINARY: the stamp of an interrupted run (results/P/E/.TIER.partial/.stamp):
# the tier and the simulator binary's sha256; tools/run-experiment resumes only with the same one
partial_stamp() { { echo "tier $1"; sha256sum "$2" | cut -c1-64; } | sha256sum | cut -c1-64; }
die() { echo "$(basename "$0"): $*" >&2; exit 2; }
# recorded_size DIR DPD: `DPD run --dry-run` of the simulation recorded in run directory DIR (its scene
# and arguments, one per line in DIR/.args, relative to the directory in DIR/.cwd): the particles,
# equilibration and steps rows on stdout, and its status (tools/plan, tools/cost, tools/in-flight)
recorded_size() {
    local a cwd
    mapfile -t a < "$1/.args"
    IFS= read -r cwd < "$1/.cwd"
    (cd "$cwd" && exec "$2" run "${a[0]}" --dry-run "${a[@]:1}")
}

# normalise an experiment id: strip experiments/ or results/ prefix, trailing /
norm_id() {
    local id=$1
    id=${id#./}; id=${id#experiments/}; id=${id#results/}; id=${id%/}
    printf '%s\n' "$id"
}

# all experiment ids that have a directory experiments/<paper>/<exp>/ (sorted)
list_exp_dirs() {
    local d
    for d in "$DPD_ROOT"/experiments/*/*/; do
        [ -d "$d" ] || continue
        d=${d%/}; printf '%s\n' "${d#"$DPD_ROOT"/experiments/}"
    done | LC_ALL=C sort
}

# valid_result ID TIER: true if results/ID/TIER/summary.tsv exists and the dir
# has no INCOMPLETE marker
valid_result() {
    local r="$DPD_ROOT/results/$1/$2"
    [ -f "$r/summary.tsv" ] && [ ! -e "$r/INCOMPLETE" ]
}

# evaluate ID TIER -> TSV rows (see lib/bands.awk); nothing if no bands rows
evaluate() {
    local id=$1 tier=$2 b="$DPD_ROOT/experiments/$1/bands.tsv" s="" why="no summary.tsv" notrun=0
    [ -f "$b" ] || return 0
    if valid_result "$id" "$tier"; then s="$DPD_ROOT/results/$id/$tier/summary.tsv"
    elif [ -e "$DPD_ROOT/results/$id/$tier/INCOMPLETE" ]; then why="result dir marked INCOMPLETE"
    elif [ "$tier" = paper ] && [ ! -e "$DPD_ROOT/results/$id/paper" ] && valid_result "$id" reduced; then
        # a paper tier never run (too long for the machine that made the package's results): its
        # reduced tier is committed and checked with TIER=reduced; paper.md gives the paper tier's cost
        notrun=1; why="paper tier not run: the reduced tier is committed (make check TIER=reduced)"
    elif [ "$tier" = reduced ] && [ ! -e "$DPD_ROOT/results/$id/reduced" ]; then
        # a reduced tier is optional: most experiments have none
        notrun=1; why="this experiment has no reduced tier"
    fi
    awk -v eid="$id" -v tier="$tier" -v sfile="$s" -v why="$why" -v notrun="$notrun" -f "$BANDS_AWK" "$b"
}

# provenance ID TIER KEY -> value or empty
provenance() {
    local p="$DPD_ROOT/results/$1/$2/provenance.tsv"
    [ -f "$p" ] || return 0
    awk -F '\t' -v k="$3" '{ sub(/\r$/, "") } $1 == k { print $2; exit }' "$p"
}

# the EXPERIMENTS.md to read ids from (empty if none found)
find_experiments_md() {
    local f
    for f in "${DPD_EXPERIMENTS_MD:-}" "$DPD_ROOT/EXPERIMENTS.md" "$DPD_ROOT/docs/EXPERIMENTS.md" \
             "$DPD_ROOT/../shared/EXPERIMENTS.md"; do
        [ -n "$f" ] && [ -f "$f" ] && { printf '%s\n' "$f"; return 0; }
    done
    return 0
}

# ids listed in EXPERIMENTS.md tables (backticked paper/exp in the first column)
list_md_ids() {
    local f; f=$(find_experiments_md)
    [ -n "$f" ] || return 0
    awk '/^[ \t]*\|[ \t]*`[^`]+\/[^`]+`[ \t]*\|/ {
            s = $0; sub(/^[ \t]*\|[ \t]*`/, "", s); sub(/`.*/, "", s); print s }' "$f"
}
