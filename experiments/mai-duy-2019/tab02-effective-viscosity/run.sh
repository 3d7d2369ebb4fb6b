#!/usr/bin/env bash
# Table 2 of Mai-Duy et al. 2019: at each phi, eta(k) of the free and of the spring-constrained
# system by TCAF (as fig02-length-scale), the constrained eta(k -> 0) = eta_eff and the free
# system's k at which eta_free(k) equals it = k_eff (tools/analysis.py keff). The constrained eta(k -> 0) by the
# time integral of C(k,t) (tcaf_k0, tools/lib/exp.sh; issue 37), the two-mode slow mode beside it
# (second estimator) and eq. 28's amplitude-1 fit (the paper's literal method, *_exp_*) as well; the
# free system's eta(k) and eta(k -> 0) by the run's own eq. 28 fit (a simple fluid: the estimators
# agree there, tab02-readings' consistency rows).
. "$DPD_ROOT/tools/lib/exp.sh"
needs paper mai-duy-2019/tab01-wavelengths
needs any mai-duy-2019/fig01-viscosity-wavenumber@paper
# PAIRS: "kp:kq" = the paper's k^3 colloids in 15^3 (names the phi) run as kq^3 colloids in a box
# 15 kq / kp: the same lattice spacing, particles per colloid cell and phi as the paper's.
case $TIER in
    quick) PAIRS="8:4"
           tier=(--set dt=0.01 --set equilibration=300 --set steps=3000 --set measure.tcaf.every=1
                 --set measure.tcaf.window=60 --set measure.tcaf.origin_every=10 --set measure.tcaf.n2max=9) ;;
    paper) PAIRS="3:3 4:4 5:5 6:6 7:7 8:8 9:9 10:10 11:11 12:12 13:13"; tier=() ;;
esac
printf 'k\tphi\tk_eff\tk_eff_se\tlambda_eff\tlambda_eff_se\teta_eff\teta_eff_se\teta_k0_free\teta_k0_free_se\tk_eff_exp\tk_eff_exp_se\teta_eff_exp\teta_eff_exp_se\tk_eff_two_mode\tk_eff_two_mode_se\teta_eff_two_mode\teta_eff_two_mode_se\n' > "$OUT/table2_data.tsv"
# the simulations: free and constrained at each phi
simulations() {
i=0
for pair in $PAIRS; do
    lattice_pair "$pair" 4
    if [ "$TIER" = paper ]; then
        # the paper's Tables 1 and 2 come from one set of TCAF runs: so do ours (tab01-wavelengths
        # runs these scenes with the same settings; its paper tier must exist: needs, above)
        reuse_run free_$tag mai-duy-2019/tab01-wavelengths paper
        reuse_run constrained_$tag mai-duy-2019/tab01-wavelengths paper
    else
        dpd_run free_$tag free.cfg "${tier[@]}" "${geo[@]}" --set "seed=$((50300 + 2 * i))"
        dpd_run constrained_$tag constrained.cfg "${tier[@]}" "${geo[@]}" --set "colloids.per_axis=$kq" --set "seed=$((50301 + 2 * i))"
    fi
    i=$((i + 1))
done
}
analysis() {
# the analysis
for pair in $PAIRS; do
    lattice_pair "$pair" 4
    np=$(getv free_$tag particles)
    "$ANALYSE" phi-row "$tag" "$count" "$np" >> "$OUT/summary.tsv"
    emit_from free_$tag tcaf_eta_k0 eta_k0_free_$tag
    emit eta_k0_constrained_$tag "$(tcaf_k0 constrained_$tag integral,two-mode "$L")"
    emit eta_k0_constrained_two_mode_$tag "$(tcaf_k0_of constrained_$tag two-mode)"
    emit_from constrained_$tag tcaf_eta_k0 eta_k0_constrained_exp_$tag
    emit_diff eta_k0_free_minus_constrained_$tag free_$tag tcaf_eta_k0 . eta_k0_constrained_$tag
    emit_diff eta_k0_free_minus_constrained_exp_$tag free_$tag tcaf_eta_k0 constrained_$tag tcaf_eta_k0
    emit_from constrained_$tag temperature temperature_constrained_$tag
    ec=$(get . eta_k0_constrained_$tag)
    "$ANALYSE" keff "$OUT/runs/free_$tag/tcaf_eta.tsv" "${ec%	*}" "${ec#*	}" "$tag" >> "$OUT/summary.tsv"
    ec=$(get . eta_k0_constrained_two_mode_$tag)
    "$ANALYSE" keff "$OUT/runs/free_$tag/tcaf_eta.tsv" "${ec%	*}" "${ec#*	}" "two_mode_$tag" >> "$OUT/summary.tsv"
    ec=$(get constrained_$tag tcaf_eta_k0)
    "$ANALYSE" keff "$OUT/runs/free_$tag/tcaf_eta.tsv" "${ec%	*}" "${ec#*	}" "exp_$tag" >> "$OUT/summary.tsv"
    cp "$OUT/runs/free_$tag/tcaf_eta.tsv" "$OUT/tcaf_eta_free_$tag.tsv"
    cp "$OUT/runs/constrained_$tag/tcaf_eta.tsv" "$OUT/tcaf_eta_constrained_$tag.tsv"
    "$ANALYSE" tab02-data-row "$OUT/summary.tsv" "$tag" "$kp" >> "$OUT/table2_data.tsv"
done
# Table 2 beside the paper's values (rows of the phi run; value +- stderr)
"$ANALYSE" tab02-table paper-table2.tsv "$OUT/table2_data.tsv" > "$OUT/table2.tsv"
# Side check (not a reproduction): the paper's (k_eff, eta_eff) pairs against the eta(k) of the
# pure solvent (n = 4) of fig01-viscosity-wavenumber's committed paper tier, read-only.
F01=$(upstream_if mai-duy-2019/fig01-viscosity-wavenumber@paper)/tcaf_eta.tsv
if [ -f "$F01" ]; then
    printf 'phi\tk_eff, paper\teta_eff, paper\tsolvent eta(k_eff, paper) (fig01)\tse\n' > "$OUT/solvent_at_paper_keff.tsv"
    "$ANALYSE" solvent-at-paper-keff paper-table2.tsv "$F01" >> "$OUT/solvent_at_paper_keff.tsv"
fi
}
experiment
