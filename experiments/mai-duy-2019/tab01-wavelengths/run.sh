#!/usr/bin/env bash
# Table 1 of Mai-Duy et al. 2019: the cube (eq. 31) and sphere (eq. 32) length
# scales for the 11 volume fractions (k^3 octahedra of 6 particles among 13500
# solvent particles in 15^3), computed by `dpd wavelengths` (every tier), and the
# TCAF length scale (section 4.2.3): the free system's lambda = 2 pi / k at which
# its eta(k) equals the constrained system's eta(k -> 0) (keff of
# tools/analysis.py, error propagated), at the phi of the tier.
. "$DPD_ROOT/tools/lib/exp.sh"
needs reduced mai-duy-2019/fig04-relative-viscosity-a353@reduced
T02=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../tab02-effective-viscosity
# TCAF pairs "kp:kq": the paper's k^3 colloids in 15^3 (names the phi) run as kq^3 colloids in a
# box 15 kq / kp (same lattice spacing, particles per colloid cell and phi)
case $TIER in
    quick) PAIRS="8:4"
           tcaf=(--set dt=0.01 --set equilibration=200 --set steps=1200 --set measure.tcaf.every=1
                 --set measure.tcaf.window=60 --set measure.tcaf.origin_every=10 --set measure.tcaf.n2max=9) ;;
    # reduced: the paper's box, dt and TCAF settings at phi = 0.0119, 0.0526, 0.1854 and 0.3077, runs
    # 2.7 times shorter (as fig04-relative-viscosity-a353 reduced, whose committed phi = 0.4940 pair is
    # read too); the order keeps the seeds of the first two pairs run
    reduced) PAIRS="3:3 8:8 5:5 10:10"; tcaf=(--set equilibration=500 --set steps=3000) ;;
    paper) PAIRS="3:3 4:4 5:5 6:6 7:7 8:8 9:9 10:10 11:11 12:12 13:13"; tcaf=() ;;
esac
# the free and constrained TCAF runs of lattice pair number $1 ($2 = "kp:kq", after lattice_pair)
pair_simulations() {
    dpd_run free_$tag "$T02/free.cfg" "${tcaf[@]}" "${geo[@]}" --set "seed=$((60300 + 2 * $1))"
    dpd_run constrained_$tag "$T02/constrained.cfg" "${tcaf[@]}" "${geo[@]}" --set "colloids.per_axis=$kq" \
        --set "seed=$((60301 + 2 * $1))"
}
# the simulations
simulations() {
i=0
for pair in $PAIRS; do lattice_pair "$pair" 4; pair_simulations $i; i=$((i + 1)); done
}
# the analysis
analysis() {
"$DPD" wavelengths --box 15 --n 4 --p 6 --kmin 3 --kmax 13 | tail -n +2 >> "$OUT/summary.tsv"
for pair in $PAIRS; do
    lattice_pair "$pair" 4
    # the constrained eta(k -> 0) by the time integral of C(k,t) (tcaf_k0, tools/lib/exp.sh; issue 37),
    # eq. 28's amplitude-1 fit (the paper's literal method and its artefact) beside it as *_exp_*
    emit_from free_$tag tcaf_eta_k0 eta_k0_free_$tag
    emit eta_k0_constrained_$tag "$(tcaf_k0 constrained_$tag integral "$L")"
    emit_from constrained_$tag tcaf_eta_k0 eta_k0_constrained_exp_$tag
    emit_diff eta_k0_free_minus_constrained_$tag free_$tag tcaf_eta_k0 . eta_k0_constrained_$tag
    for est in "" exp_; do
        ec=$(get . eta_k0_constrained_$est$tag)
        "$ANALYSE" keff-lambda "$OUT/runs/free_$tag/tcaf_eta.tsv" "${ec%	*}" "${ec#*	}" "$est$tag" >> "$OUT/summary.tsv"
    done
    cp "$OUT/runs/free_$tag/tcaf_eta.tsv" "$OUT/tcaf_eta_free_$tag.tsv"
    cp "$OUT/runs/constrained_$tag/tcaf_eta.tsv" "$OUT/tcaf_eta_constrained_$tag.tsv"
done
# reduced: phi = 0.4940 from the same construction in fig04-relative-viscosity-a353's committed
# reduced tier (15^3, dt 0.005, equilibration 500 + 3000 steps; read-only)
F04=; [ "$TIER" = reduced ] && F04=$(upstream_if mai-duy-2019/fig04-relative-viscosity-a353@reduced)
if [ -n "$F04" ] && [ -f "$F04/tcaf_eta_free_phi0.49.tsv" ]; then
    tag=phi0.4940
    "$ANALYSE" rename "$F04/summary.tsv" eta_k0_free_phi0.49 eta_k0_free_$tag eta_eff_phi0.49 eta_k0_constrained_$tag \
        eta_eff_exp_phi0.49 eta_k0_constrained_exp_$tag >> "$OUT/summary.tsv"
    "$ANALYSE" summary-diff "$OUT/summary.tsv" eta_k0_free_$tag eta_k0_constrained_$tag eta_k0_free_minus_constrained_$tag > "$OUT/.rows"
    cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
    for est in "" exp_; do
        ec=$(get . eta_k0_constrained_$est$tag)
        "$ANALYSE" keff-lambda "$F04/tcaf_eta_free_phi0.49.tsv" "${ec%	*}" "${ec#*	}" "$est$tag" >> "$OUT/summary.tsv"
    done
    cp "$F04/tcaf_eta_free_phi0.49.tsv" "$OUT/tcaf_eta_free_$tag.tsv"
    cp "$F04/tcaf_eta_constrained_phi0.49.tsv" "$OUT/tcaf_eta_constrained_$tag.tsv"
fi
# reduced: the paper tier's CPU-hours as projected before it ran (paper.md), from this tier's cost per
# particle-step (its free run at phi = 0.1854): 22 runs (free and constrained) of 13500 + 6 k^3
# particles for k = 3 ... 13, 8000 production steps each (the scenes' 40 time units at dt = 0.005)
if [ "$TIER" = reduced ]; then
    c=$(getv free_phi0.1854 cpu_seconds) np=$(getv free_phi0.1854 particles) ns=$(getv free_phi0.1854 steps)
    emit paper_tier_projected_cpu_hours "$("$ANALYSE" tab01-projected-cpu-hours "$c" "$np" "$ns")" 0
fi
# table beside the paper's columns; TCAF: value +- se, "no crossing" when the free eta(k) never
# reaches the constrained eta(k -> 0), "-" when the phi was not run at this tier
"$ANALYSE" tab01-tables "$OUT/summary.tsv" paper-table1.tsv "$OUT/table1.tsv" "$OUT/lambda_tcaf.tsv"
# what paper.md says in words (issue 40 item 7): the free minus constrained eta(k -> 0) at the
# smallest phi in standard errors (where that phi is run)
if d=$(get . eta_k0_free_minus_constrained_phi0.0119 2> /dev/null); then
    "$ANALYSE" sigmas eta_k0_free_minus_constrained_phi0.0119_sigmas "$d" 0 >> "$OUT/summary.tsv"
fi
}
experiment
