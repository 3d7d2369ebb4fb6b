#!/usr/bin/env bash
# Pan et al. 2008, eqs 16-17: colloid self-diffusion D from the MSD and the
# effective radius R = kBT / (c pi mu D), c = 6, with the paper's mu = 3.6388.
# Plus (issue 23 item 6) D in three periodic boxes, extrapolated in 1/L (Yeh & Hummer 2004):
# D(L) = D_inf - c / L, c = 2.837297 kBT / (6 pi eta) for a cubic box; R from D_inf.
. "$DPD_ROOT/tools/lib/exp.sh"
needs any pan-2008/fluid-viscosity@paper
MU=3.6388 L=10.0
# the three boxes: edge, production steps (dt = 0.01) and seed, per tier (README: sizes and lengths
# for a CPU budget; the paper tier's lengths give D_inf to about 0.5 %, not run)
BOX_L="6 8 12"
case $TIER in
    quick) tier=(--set steps=12000); BOX_STEPS="10000 10000 10000" ;;
    # reduced: 400 time units (the scene's steps), the committed result (README)
    reduced) tier=(); BOX_STEPS="1200000 300000 200000" ;;
    # paper (issue 38, README): the 10^3 box 2000 time units (D to 1 %: the FAIL of its band is decided);
    # the three boxes six times the reduced tier's time, as independent replicas (8, 4, 4 of 9000, 4500,
    # 3000 time units), so that each box's error comes from the replicas' scatter, not from a few
    # colloids' groups (the reduced fit's chi^2/dof 3.6)
    paper) tier=(--set steps=200000); BOX_STEPS="900000 450000 300000"; BOX_REPS="8 4 4" ;;
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
    nf=$((3 * Lb * Lb * Lb)) nc=$(awk -v l=$Lb 'BEGIN{printf "%d", 0.027 * l^3 + 0.5}') k=0
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
get diff D | num_awk -F'\t' -v m=$MU '{ num_rel1(1/(6*3.141592653589793*m*$1), $1, $2, o); print num_row("R", o) }' >> "$OUT/summary.tsv"
# the periodic box slows diffusion by 2.837 kBT / (6 pi mu L) (Yeh & Hummer 2004): D and R corrected
get diff D | num_awk -F'\t' -v m=$MU -v L=$L '{c = 2.837297/(6*3.141592653589793*m*L); D = $1 + c
    printf "D_colloid_box_corrected\t%.10g\t%.4g\n", D, $2
    num_rel1(1/(6*3.141592653589793*m*D), D, $2, o); print num_row("R_box_corrected", o) }' >> "$OUT/summary.tsv"
cp "$OUT/runs/diff/msd.tsv" "$OUT/msd.tsv"

# ---- D(L) in three boxes, extrapolated in 1/L -------------------------------------------------
printf 'L\tinv_L\tcolloids\tD\tD_se\tD_t_ratio_late_half\tD_t_ratio_late_half_se\n' > "$OUT/d-of-L.tsv"
for Lb in $BOX_L; do
    nc=$(awk -v l=$Lb 'BEGIN{printf "%d", 0.027 * l^3 + 0.5}') runs=$(box_runs $Lb)
    if [ "$runs" = box_L$Lb ]; then
        d=$(get box_L$Lb D) r=$(get box_L$Lb D_t_ratio_late_half)
    else
        # replicas of equal length: D their mean, its error from their scatter (the replicas are
        # independent); the pooled error of the colloid groups beside it, and the ratio of the two
        # (does the groups' error hold? README)
        d=$(for n in $runs; do get $n D; done | num_awk -F'\t' '{ k++; x[k] = $1 } END { num_mean_se(x, k, o); printf "%s", num_pair(o) }')
        g=$(for n in $runs; do get $n D; done | num_awk -F'\t' '{ k++; e[k] = $2 } END { printf "%.4g", num_quad(e, k) / k }')
        emit D_se_groups_L$Lb "$g" 0
        echo "$d" | awk -F'\t' -v g=$g -v n=$(echo $runs | wc -w) -v q=D_se_replicas_over_groups_L$Lb '{
            printf "%s\t%.4g\t%.2g\n", q, $2 / g, $2 / g / sqrt(2 * (n - 1)) }' >> "$OUT/summary.tsv"
        r=$(for n in $runs; do get $n D_t_ratio_late_half; done | num_awk -F'\t' '{ k++; x[k] = $1; e[k] = $2 }
            END { num_set(o, num_mean(x, k), num_quad(e, k) / k); printf "%s", num_pair(o) }')
    fi
    printf '%s\t%.10g\t%s\t%s\t%s\n' $Lb $(awk -v l=$Lb 'BEGIN{printf "%.10g", 1/l}') $nc "$d" "$r" >> "$OUT/d-of-L.tsv"
    emit D_colloid_L$Lb $d
    emit D_t_ratio_late_half_L$Lb $r
done
# weighted straight line D = D_inf + slope / L (num_wline; its value at 1/L = 0 is the intercept;
# the errors scaled by chi^2/dof when that exceeds 1, the scatter then exceeding the errors; r2 the
# unweighted coefficient of determination), in the table the former `dpd fit-line` wrote
num_awk -F'\t' 'NR>1 && num_usable($4, $5) { n++; x[n]=$2; y[n]=$4; s[n]=$5 }
    END { if (n < 3) { print "eq16: " n " usable rows in d-of-L.tsv; need at least 3" > "/dev/stderr"; exit 1 }
        num_wline(x, y, s, n, o); b=o["slope"]; a=o["icpt"]
        for (i = 1; i <= n; i++) { r=y[i]-(a+b*x[i]); chi2+=num_sq(r/s[i]); ssr+=num_sq(r); ym+=y[i]/n }
        for (i = 1; i <= n; i++) sst+=num_sq(y[i]-ym)
        c=chi2/(n-2); f=sqrt(c > 1 ? c : 1)
        printf "quantity\tvalue\tstderr\n"
        printf "slope\t%.10g\t%.4g\n", b, f*o["slope_se"]
        printf "value_at_centre\t%.10g\t%.4g\n", a, f*o["icpt_se"]
        printf "r2\t%.10g\t0\nchi2_dof\t%.10g\t0\npoints\t%d\t0\n", (sst > 0 ? 1-ssr/sst : 1), c, n }' "$OUT/d-of-L.tsv" > "$OUT/fit-d-of-L.tsv"
fit() { awk -F'\t' -v q="$1" '$1==q{print $2 "\t" $3; f=1} END{exit !f}' "$OUT/fit-d-of-L.tsv"; }
dinf=$(fit value_at_centre) slope=$(fit slope)
printf 'D_colloid_extrapolated\t%s\n' "$dinf" >> "$OUT/summary.tsv"
num_awk -F'\t' -v s="$slope" 'BEGIN{split(s,a,"\t"); num_scale(a[1], a[2], -1, o); print num_row("finite_size_slope", o)}' >> "$OUT/summary.tsv"
printf 'fit_chi2_dof\t%s\n' "$(fit chi2_dof)" >> "$OUT/summary.tsv"
# Yeh-Hummer's coefficient from the measured fluid viscosity at this dt (pan-2008/fluid-viscosity,
# paper tier, mu_dt0.01), and the fitted slope against it (a consistency check of the fit)
visc=$(upstream pan-2008/fluid-viscosity@paper)
eta=$(awk -F'\t' '$1=="mu_dt0.01"{print $2 "\t" $3}' "$visc/summary.tsv")
num_awk -F'\t' -v e="$eta" -v s="$slope" -v di="$dinf" -v m=$MU 'BEGIN{split(e,E,"\t"); split(s,S,"\t"); split(di,DI,"\t"); pi=3.141592653589793
    num_rel1(2.837297/(6*pi*E[1]), E[1], E[2], cy); print num_row("yeh_hummer_coefficient", cy)
    num_ratio(-S[1], S[2], cy["v"], cy["se"], o); print num_row("finite_size_slope_over_yeh_hummer", o)
    D=DI[1]; Dse=DI[2]
    # eq. 16 (c = 6) from the extrapolated D: with the paper mu, as the paper computes R; and with
    # the measured eta (errors of D and eta in quadrature)
    num_rel1(1/(6*pi*m*D), D, Dse, o); print num_row("R_extrapolated", o)
    num_rel2(1/(6*pi*E[1]*D), D, Dse, E[1], E[2], o); print num_row("R_extrapolated_measured_eta", o)
    num_set(o, E[1], E[2]); print num_row("measured_eta", o)}' >> "$OUT/summary.tsv"
# Yeh-Hummer read the other way (post hoc, no band; paper.md): the difference D(8) - D(6) it expects,
# c (1/6 - 1/8), and each box's D corrected by c / L with the measured eta (errors of D and c in
# quadrature: c comes from the fluid's viscosity, independent of the boxes' runs)
cyh=$(get . yeh_hummer_coefficient)
num_awk -F'\t' -v c="$cyh" 'BEGIN{split(c, C, "\t"); num_scale(C[1], C[2], 1/6 - 1/8, o); print num_row("yeh_hummer_D_L8_minus_L6", o)}' >> "$OUT/summary.tsv"
for Lb in $BOX_L; do
    paste <(get . D_colloid_L$Lb) <(echo "$cyh") | num_awk -F'\t' -v L=$Lb '{ num_lin2(1, $1, $2, 1 / L, $3, $4, o)
        print num_row("D_colloid_L" L "_yeh_hummer_corrected", o) }' >> "$OUT/summary.tsv"
done
# what paper.md says in words (issue 40 item 7): each D and R against the paper's (bands.tsv), and
# D(8) - D(6)
for q in D_colloid D_colloid_box_corrected D_colloid_extrapolated; do emit_pct ${q}_pct_from_paper "$(get . $q)" "$(paper_number D_colloid)"; done
for q in R R_box_corrected R_extrapolated; do emit_pct ${q}_pct_from_paper "$(get . $q)" "$(paper_number R)"; done
emit_minus D_colloid_L8_minus_L6 "$(get . D_colloid_L8)" "$(get . D_colloid_L6)"
}
experiment
