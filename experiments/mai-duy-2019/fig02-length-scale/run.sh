#!/usr/bin/env bash
# Fig. 2 of Mai-Duy et al. 2019: eta(k) of the free and of the spring-constrained system at one
# phi, and the free system's k at which eta_free(k) equals the constrained eta(k -> 0).
. "$DPD_ROOT/tools/lib/exp.sh"
case $TIER in
    # 8^3, k = 3 colloids per axis: phi = 162 / (2048 + 162) = 0.0733
    quick) K=3; tier=(--set 'box=[8.0,8.0,8.0]' --set dt=0.01 --set equilibration=500 --set steps=5000
                      --set measure.tcaf.every=1 --set measure.tcaf.window=150 --set measure.tcaf.origin_every=10
                      --set measure.tcaf.n2max=9) ;;
    paper) K=6; tier=() ;;
esac
count=$((6 * K * K * K))
simulations() {
dpd_run free free.cfg "${tier[@]}" --set "types.[1].count=$count"
dpd_run constrained constrained.cfg "${tier[@]}" --set "types.[1].count=$count" --set "colloids.per_axis=$K"
# the same trajectory (same seed), the TCAF of all momentum: particles plus the rigid bodies
dpd_run constrained_bodies constrained.cfg "${tier[@]}" --set "types.[1].count=$count" --set "colloids.per_axis=$K" \
        --set measure.tcaf.include_bodies=true
}
analysis() {
np=$(getv free particles)
emit phi "$("$ANALYSE" fraction "$count" "$np")" 0
L=15; [ "$TIER" = quick ] && L=8          # the box's side (the scenes' 15, the quick tier's 8)
# the constrained eta(k -> 0) by the time integral of C(k,t) (tcaf_k0, tools/lib/exp.sh; issue 37), the
# two-mode slow mode (second estimator) and eq. 28's amplitude-1 fit (the paper's literal, *_exp)
emit_from free tcaf_eta_k0 eta_k0_free
for r in constrained constrained_bodies; do
    w=; [ $r = constrained_bodies ] && w=_with_bodies
    emit eta_k0_constrained$w "$(tcaf_k0 $r integral,two-mode "$L")"
    emit eta_k0_constrained_two_mode$w "$(tcaf_k0_of $r two-mode)"
    emit_from $r tcaf_eta_k0 eta_k0_constrained_exp$w
    emit_diff eta_k0_free_minus_constrained$w free tcaf_eta_k0 . eta_k0_constrained$w
    emit_diff eta_k0_free_minus_constrained_two_mode$w free tcaf_eta_k0 . eta_k0_constrained_two_mode$w
    emit_diff eta_k0_free_minus_constrained_exp$w free tcaf_eta_k0 $r tcaf_eta_k0
done
emit_from constrained colloid_spring_extension_rms spring_extension_rms
emit_from constrained temperature temperature_constrained
# k_eff: linear interpolation of the free eta(k) between the two shells that bracket the
# constrained eta(k -> 0); errors of the three values (independent) propagated to first order
for est in "" _exp; do
    ec=$(get . eta_k0_constrained$est)
    "$ANALYSE" keff-rows "$OUT/runs/free/tcaf_eta.tsv" "${ec%	*}" "${ec#*	}" "$est" >> "$OUT/summary.tsv"
done
for r in free constrained constrained_bodies; do cp "$OUT/runs/$r/tcaf_eta.tsv" "$OUT/tcaf_eta_$r.tsv"; done
# what paper.md says in words (issue 40 item 7): the free minus constrained eta(k -> 0) (two-mode) in
# standard errors
"$ANALYSE" sigmas eta_k0_free_minus_constrained_two_mode_sigmas "$(get . eta_k0_free_minus_constrained_two_mode)" 0 >> "$OUT/summary.tsv"
}
experiment
