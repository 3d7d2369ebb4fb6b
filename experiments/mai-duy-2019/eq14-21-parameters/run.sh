#!/usr/bin/env bash
# s and gamma from (eta, Sc) by eqs 14-21 of Mai-Duy et al. 2019, 3D and 2D,
# for the solvent of section 4 (eta = 30, Sc = 500, n = 4, rc = 1.5, m = kBT = 1),
# plus the curves s(eta), gamma(eta) at Sc = 500 for the figure. Same for both tiers.
. "$DPD_ROOT/tools/lib/exp.sh"
# no simulations: the tables are the formulas of `dpd params`
simulations() { :; }
analysis() {
for dim in 3 2; do
    "$DPD" params --dim $dim --eta 30 --Sc 500 --n 4 --rc 1.5 --m 1 --kBT 1 | tail -n +2 >> "$OUT/summary.tsv"
done
printf 'eta\ts_3d\tgamma_3d\ts_2d\tgamma_2d\n' > "$OUT/curves.tsv"
for eta in $(seq 10 0.5 33.5); do
    row=$eta
    for dim in 3 2; do
        # s <= 0 (beyond the bound of eq. 16 / 20): dpd params exits 2, plotted as a gap
        if out=$("$DPD" params --dim $dim --eta $eta --Sc 500 --n 4 --rc 1.5 2>/dev/null); then
            vals=$(printf '%s\n' "$out" | "$ANALYSE" values s_${dim}d gamma_${dim}d)
        else
            vals=$'nan\tnan'
        fi
        row="$row"$'\t'"$vals"
    done
    printf '%s\n' "$row" >> "$OUT/curves.tsv"
done
}
experiment
