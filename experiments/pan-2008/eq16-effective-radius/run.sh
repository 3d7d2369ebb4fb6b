#!/usr/bin/env bash
# Pan et al. 2008, eqs 16-17: colloid self-diffusion D from the MSD and the
# effective radius R = kBT / (c pi mu D), c = 6, with the paper's mu = 3.6388.
# Plus (issue 23 item 6) D in three periodic boxes, extrapolated in 1/L (Yeh & Hummer 2004):
# D(L) = D_inf - c / L, c = 2.837297 kBT / (6 pi eta) for a cubic box; R from D_inf.
. "$DPD_ROOT/tools/lib/exp.sh"
needs any pan-2008/fluid-viscosity@paper
MU=3.6388 L=10.0
# the three boxes: edge, production steps (dt = 0.01) and seed, per tier (README: sizes and lengths
# per tier; the paper tier was run 2026-12-06)
BOX_L="6 8 12"
case $TIER in
    quick) tier=(--set steps=12000); BOX_STEPS="10000 10000 10000" ;;
    # reduced: 400 time units (the scene's steps), the committed result (README)
    reduced) tier=(); BOX_STEPS="1200000 300000 200000" ;;
    # paper (issue 38, README): the 10^3 box 2000 time units (D to 1 %: the FAIL of its band is decided);
    # the three boxes six times the reduced tier's time, as independent replicas (8, 4, 4 of 9000, 4500,
    # 3000 time units), so that each box's error comes from the replicas' scatter, not from a few
    # colloids' groups (the reduced fit's chi^2/dof 3.6)
    # The slope extension (2026-12-06, README, fixed before any of it ran): the slope over Yeh-Hummer
    # came out 0.83 +- 0.10, UNRESOLVED; replicas of the same lengths at L = 6 and 12 (the line's ends,
    # in the ratio of their variance per CPU second) bring it to about 0.032: 64 and 68 replicas
    paper) tier=(--set steps=200000); BOX_STEPS="900000 450000 300000"; BOX_REPS="64 4 68" ;;
esac
BOX_REPS=${BOX_REPS:-"1 1 1"}
# box_runs L: the runs of box L (one, or the replicas box_L<L>_r<k>)
box_runs() { local i=0 n; for n in $BOX_REPS; do i=$((i + 1)); [ "$(echo $BOX_L | cut -d' ' -f$i)" = "$1" ] && break; done
    if [ "$n" = 1 ]; then echo box_L$1; else seq -f "box_L$1_r%g" 1 $n; fi; }
simulations() {
dpd_run diff colloid-diffusion.cfg "${tier[@]}"
# Each box: fluid density 3 (3 L^3 particles) and the colloid number density of the 10^3 box, 0.027
# (rounded: 6, 14, 47 colloids), so crowding is alike in every box and only the periodic images
# differ. MSD window W = L^2 / 10 time units (10 L^2 steps; 10 time units at L = 10), D from the
# slope over its second half: the finite-size part of D(t) relaxes with the box's slowest shear
# mode, tau = L^2 / (4 pi^2 nu) (nu = eta / rho = 1.23: tau = 0.021 L^2), so the slope starts at
# 2.4 tau in every box; with W ~ L^2 the remaining part is itself ~ 1/L (hydrodynamic terms go as
# F(nu t / L^2) / L), so D_inf is not biased by it and the slope by about +2.5 % (README).
set -- $BOX_STEPS
for Lb in $BOX_L; do
    nf=$((3 * Lb * Lb * Lb)) nc=$("$ANALYSE" colloid-count $Lb) k=0
    for n in $(box_runs $Lb); do   # seeds 1606, 1608, 1612 (one run), 1600 + 100 k + L (replica k)
        sd=$((1600 + Lb)); [ $n = box_L$Lb ] || { k=$((k + 1)); sd=$((1600 + 100 * k + Lb)); }
        dpd_run $n colloid-diffusion.cfg --set "box=[$Lb.0,$Lb.0,$Lb.0]" --set "types.[0].count=$nf" \
            --set "types.[1].count=$nc" --set "measure.msd.window=$((10 * Lb * Lb))" --set steps=$1 --set seed=$sd
    done
    shift
done
}
analysis() {
emit_from diff D D_colloid
emit_from diff D_t_ratio_late_half D_t_ratio_late_half
# eq. 16 with c = 6: R = kBT / (6 pi mu D); error from D alone
"$ANALYSE" stokes-radius R "$(get diff D)" $MU >> "$OUT/summary.tsv"
# the periodic box slows diffusion by 2.837 kBT / (6 pi mu L) (Yeh & Hummer 2004): D and R corrected
"$ANALYSE" box-corrected "$(get diff D)" $MU $L >> "$OUT/summary.tsv"
cp "$OUT/runs/diff/msd.tsv" "$OUT/msd.tsv"

# ---- D(L) in three boxes, extrapolated in 1/L -------------------------------------------------
printf 'L\tinv_L\tcolloids\tD\tD_se\tD_t_ratio_late_half\tD_t_ratio_late_half_se\n' > "$OUT/d-of-L.tsv"
for Lb in $BOX_L; do
    nc=$("$ANALYSE" colloid-count $Lb) runs=$(box_runs $Lb)
    if [ "$runs" = box_L$Lb ]; then
        d=$(get box_L$Lb D) r=$(get box_L$Lb D_t_ratio_late_half)
    else
        # replicas of equal length: D their mean, its error from their scatter (the replicas are
        # independent); the pooled error of the colloid groups beside it, and the ratio of the two
        # (does the groups' error hold? README)
        d=$(for n in $runs; do get $n D; done | "$ANALYSE" mean-se)
        g=$(for n in $runs; do get $n D; done | "$ANALYSE" mean-runs | cut -f2)
        emit D_se_groups_L$Lb "$g" 0
        "$ANALYSE" se-ratio-row D_se_replicas_over_groups_L$Lb "$d" $g $(echo $runs | wc -w) >> "$OUT/summary.tsv"
        r=$(for n in $runs; do get $n D_t_ratio_late_half; done | "$ANALYSE" mean-runs)
    fi
    printf '%s\t%.10g\t%s\t%s\t%s\n' $Lb $("$ANALYSE" inverse $Lb) $nc "$d" "$r" >> "$OUT/d-of-L.tsv"
    emit D_colloid_L$Lb $d
    emit D_t_ratio_late_half_L$Lb $r
done
# weighted straight line D = D_inf + slope / L (tools/analysis.py wline; its value at 1/L = 0 is the intercept;
# the errors scaled by chi^2/dof when that exceeds 1, the scatter then exceeding the errors; r2 the
# unweighted coefficient of determination), in the table the former `dpd fit-line` wrote
"$ANALYSE" finite-size-fit "$OUT/d-of-L.tsv" > "$OUT/fit-d-of-L.tsv"
fit() { tsv_lookup "$OUT/fit-d-of-L.tsv" "$1" eq16; }
dinf=$(fit value_at_centre) slope=$(fit slope)
printf 'D_colloid_extrapolated\t%s\n' "$dinf" >> "$OUT/summary.tsv"
emit finite_size_slope "$("$ANALYSE" scale "$slope" -1)"
printf 'fit_chi2_dof\t%s\n' "$(fit chi2_dof)" >> "$OUT/summary.tsv"
# Yeh-Hummer's coefficient from the measured fluid viscosity at this dt (pan-2008/fluid-viscosity,
# paper tier, mu_dt0.01), and the fitted slope against it (a consistency check of the fit)
visc=$(upstream pan-2008/fluid-viscosity@paper)
eta=$(tsv_lookup "$visc/summary.tsv" mu_dt0.01 eq16)
"$ANALYSE" yeh-hummer-rows "$eta" "$slope" "$dinf" $MU >> "$OUT/summary.tsv"
# Yeh-Hummer read the other way (post hoc, no band; paper.md): the difference D(8) - D(6) it expects,
# c (1/6 - 1/8), and each box's D corrected by c / L with the measured eta (errors of D and c in
# quadrature: c comes from the fluid's viscosity, independent of the boxes' runs)
cyh=$(get . yeh_hummer_coefficient)
"$ANALYSE" yeh-hummer-corrections "$OUT/summary.tsv" "$cyh" "$BOX_L" >> "$OUT/summary.tsv"
# what paper.md says in words (issue 40 item 7): each D and R against the paper's (bands.tsv), and
# D(8) - D(6)
for q in D_colloid D_colloid_box_corrected D_colloid_extrapolated; do emit_pct ${q}_pct_from_paper "$(get . $q)" "$(paper_number D_colloid)"; done
for q in R R_box_corrected R_extrapolated; do emit_pct ${q}_pct_from_paper "$(get . $q)" "$(paper_number R)"; done
emit_minus D_colloid_L8_minus_L6 "$(get . D_colloid_L8)" "$(get . D_colloid_L6)"
}
experiment
