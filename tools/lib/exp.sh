# tools/lib/exp.sh - sourced by experiments/*/*/run.sh.
# Environment from tools/run-experiment: DPD (simulator), TIER, OUT (result dir).
set -euo pipefail
: "${DPD:?run through tools/run-experiment}" "${OUT:?}" "${TIER:?}"
mkdir -p "$OUT/runs"
[ -f "$OUT/summary.tsv" ] || printf 'quantity\tvalue\tstderr\n' > "$OUT/summary.tsv"

# dpd_run NAME SCENE [--set k=v ...]: one simulation into $OUT/runs/NAME.
# Resumable (tools/run-experiment keeps $OUT across attempts while nothing
# changed): a simulation already complete with the same arguments is not
# rerun; an interrupted one continues from its checkpoint, written every
# DPD_CHECKPOINT_EVERY steps (default 5000) but not sooner than
# DPD_CHECKPOINT_WALL seconds (default 60) after the last one: a checkpoint
# holds every sampled series and reaches hundreds of MB in long runs (the
# result is bit-identical either way).
dpd_run() {
    local name=$1 scene=$2; shift 2
    local dir=$OUT/runs/$name args
    args=$(printf '%s\n' "$scene" "$@")
    if [ "$(cat "$dir/.args" 2>/dev/null)" = "$args" ]; then
        if [ -s "$dir/summary.tsv" ] && [ ! -e "$dir/INCOMPLETE" ]; then
            echo "dpd_run: $name already complete, kept" >&2
            return 0
        fi
    else
        rm -rf "$dir"; mkdir -p "$dir"
        printf '%s\n' "$args" > "$dir/.args"
    fi
    "$DPD" run "$scene" --out "$dir" --quiet --checkpoint-every "${DPD_CHECKPOINT_EVERY:-5000}" \
        --checkpoint-wall "${DPD_CHECKPOINT_WALL:-60}" --resume "$@"
}

# get NAME QUANTITY -> "value<TAB>stderr" from a run's summary.
get() {
    awk -F'\t' -v q="$2" '$1==q{print $2 "\t" $3; f=1} END{exit !f}' "$OUT/runs/$1/summary.tsv" \
        || { echo "exp.sh: quantity '$2' missing in run '$1'" >&2; return 1; }
}

# emit QUANTITY VALUE STDERR: a row of the experiment summary.
emit() { printf '%s\t%s\t%s\n' "$1" "$2" "$3" >> "$OUT/summary.tsv"; }

# emit_from NAME QUANTITY [AS]: copy a run quantity into the summary.
emit_from() {
    local v; v=$(get "$1" "$2") || return 1
    printf '%s\t%s\n' "${3:-$2}" "$v" >> "$OUT/summary.tsv"
}


# emit_diff QUANTITY NAME1 Q1 NAME2 Q2: value1 - value2 with the errors in quadrature.
emit_diff() {
    local a b
    a=$(get "$2" "$3") b=$(get "$4" "$5")
    awk -F'\t' -v q="$1" -v a="$a" -v b="$b" 'BEGIN{split(a,x,"\t"); split(b,y,"\t");
        printf "%s\t%.10g\t%.4g\n", q, x[1]-y[1], sqrt(x[2]^2+y[2]^2)}' >> "$OUT/summary.tsv"
}

# emit_ratio QUANTITY NAME1 Q1 NAME2 Q2: value1 / value2 with first-order error propagation.
emit_ratio() {
    local a b
    a=$(get "$2" "$3") b=$(get "$4" "$5")
    awk -F'\t' -v q="$1" -v a="$a" -v b="$b" 'BEGIN{split(a,x,"\t"); split(b,y,"\t"); r=x[1]/y[1];
        printf "%s\t%.10g\t%.4g\n", q, r, (r<0?-r:r)*sqrt((x[2]/x[1])^2+(y[2]/y[1])^2)}' >> "$OUT/summary.tsv"
}

# emit_mean AS QUANTITY NAME...: mean over independent runs of a run quantity,
# standard error = sample standard deviation / sqrt(number of runs).
emit_mean() {
    local as=$1 q=$2; shift 2
    local vals="" n
    for n in "$@"; do vals="$vals $(get "$n" "$q" | cut -f1)" || return 1; done
    awk -v q="$as" -v v="$vals" 'BEGIN{k=split(v,x," "); s=0; for(i=1;i<=k;i++) s+=x[i]; m=s/k;
        ss=0; for(i=1;i<=k;i++) ss+=(x[i]-m)^2; se=(k>1)?sqrt(ss/(k-1)/k):0;
        printf "%s\t%.10g\t%.4g\n", q, m, se}' >> "$OUT/summary.tsv"
}

# lattice_pair KP:KQ DIGITS - the Mai-Duy et al. suspensions: the paper's KP^3
# colloids among 13500 solvent particles in 15^3 run as KQ^3 colloids in a box of
# side 15 KQ / KP (same lattice spacing, particles per colloid cell and phi).
# Sets kp, kq, tag ("phi" and phi to DIGITS decimals), L, count (constituent
# particles, 6 per colloid) and geo (the --set arguments of box and count).
lattice_pair() {
    kp=${1%:*} kq=${1#*:}
    tag=$(awk -v k="$kp" -v d="$2" 'BEGIN { printf ("phi%." d "f"), 6 * k^3 / (13500 + 6 * k^3) }')
    L=$(awk -v a="$kp" -v b="$kq" 'BEGIN { printf "%.10g", 15 * b / a }')
    count=$((6 * kq * kq * kq))
    geo=(--set "box=[$L,$L,$L]" --set "types.[1].count=$count")
}

# emit_drag_torque ROW "F se" "T se" F_THEORY T_THEORY "U se" - the Pan et al.
# table rows: drag_rowROW, torque_rowROW, their theories (no error) and the
# ratios simulated / theory, whose errors combine the simulated value's and that
# of the velocity U the theory is linear in, in quadrature.
emit_drag_torque() {
    local r=$1 F=$2 T=$3 Fth=$4 Tth=$5 u=$6 q v th
    emit "drag_row$r" $F
    emit "torque_row$r" $T
    emit "drag_theory_row$r" "$Fth" 0
    emit "torque_theory_row$r" "$Tth" 0
    for q in drag torque; do
        [ $q = drag ] && v=$F th=$Fth || v=$T th=$Tth
        printf '%s\t%s\n' "$v" "$u" | awk -F'\t' -v t=$th -v q=${q}_ratio_row$r '{ x = $1/t
            printf "%s\t%.10g\t%.4g\n", q, x, (x < 0 ? -x : x) * sqrt(($2/$1)^2 + ($4/$3)^2) }' >> "$OUT/summary.tsv"
    done
}
