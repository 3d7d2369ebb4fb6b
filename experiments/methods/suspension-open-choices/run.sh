#!/usr/bin/env bash
# The a-dependence of Mai-Duy et al.'s Fig. 5 against what the paper leaves open (issue 23 item 3).
# Our eta_r(phi = 0.49) is 4.83 at a = 3.53 and 4.80 at a = 6.50 (fig04, fig05 paper tier); the
# paper's 5.17 and 6.69. At phi = 0.4940 (the paper's 13^3 colloids' lattice spacing: 7^3 colloids
# in a box of 8.077), rate 0.1, dt 0.005, 10 + 50 time units unless varied, both repulsions:
#   mass:  the rigid bodies' mass M = 1, 6 (ours), 24, their inertia scaled with it (M d^2 2/3);
#   dt:    0.01 against 0.005;
#   rate:  0.003 (300 time units of production: strain 0.9) against 0.1;
# each with the solvent sheared alike (eta_r = eta_susp / eta_solvent, eq. 11 for both); and the
# constrained system's TCAF eta(k -> 0) (time integral of C(k,t), `dpd tcaf-fit --model integral`,
# tab02-readings' estimator) at each M, with and without the bodies' momentum in the current
# (measure.tcaf.include_bodies), against the suspension's shear viscosity at that M.
. "$DPD_ROOT/tools/lib/exp.sh"
# the finite-size effect of this 8.077^3 box: our eta_r(0.49) against fig04's and fig05's in 15^3
needs paper mai-duy-2019/fig04-relative-viscosity-a353
needs paper mai-duy-2019/fig05-relative-viscosity-a650
MD=$DPD_ROOT/experiments/mai-duy-2019
FIG04=$MD/fig04-relative-viscosity-a353 T02=$MD/tab02-effective-viscosity
lattice_pair 13:7 2                          # tag phi0.49, L = 8.077, count = 2058, geo
case $TIER in
    quick) MASSES="6"; AS="3.53 6.50"; CHOICES=""; SIZES=""; TCAF_MASSES="6"
           run=(--set equilibration=200 --set steps=600); slow=(); tcafrun=(--set equilibration=200 --set steps=1200) ;;
    paper) MASSES="1 6 24"; AS="3.53 6.50"; CHOICES="dt0.01 rate0.003"; SIZES="H100 H1600 d0.35 d0.25"; TCAF_MASSES="1 6 24"
           run=(--set equilibration=2000 --set steps=10000); tcafrun=(--set equilibration=1000 --set steps=8000) ;;
esac
# body M with its inertia: the octahedron's sites at d = 0.5 from the centre, I = (2/3) M d^2
body() { echo --set "colloids.mass=$1" --set "colloids.inertia=$("$ANALYSE" octahedron-inertia "$1" 0.5)"; }
rep() { echo --set "pairs.[0].a=$1" --set "pairs.[1].a=$1" --set "pairs.[2].a=$1"; }
# choice settings: the default (M as given, dt 0.005, rate 0.1, H = 400, d = 0.5) or one varied (issue 37
# item 5: the spring stiffness H and the octahedron's size d, the two choices that set the colloid's size;
# d above 0.5 is not possible here, the lattice spacing 1.154 leaving the facing sites of neighbours
# 1.154 - 2 d apart; the inertia (2/3) M d^2 follows d)
choice_args() { case $1 in dt0.01) echo --set dt=0.01 --set equilibration=1000 --set steps=5000 ;;
                          rate0.003) echo --set shear_rate=0.003 --set equilibration=2000 --set steps=60000 ;;
                          H*) echo "${run[@]}" --set "colloids.H=${1#H}" ;;
                          d*) echo "${run[@]}" --set "colloids.site_distance=${1#d}" \
                                   --set "colloids.inertia=$("$ANALYSE" octahedron-inertia 6 "${1#d}")" ;; esac; }

# ---- the simulations
simulations() {
n=0
for a in $AS; do
    for M in $MASSES; do
        # shellcheck disable=SC2046
        dpd_run susp_M${M}_a$a "$FIG04/suspension-shear.cfg" "${run[@]}" "${geo[@]}" $(rep $a) $(body $M) \
            --set "colloids.per_axis=$kq" --set "seed=$((47000 + n))"; n=$((n + 1))
    done
    dpd_run solvent_a$a "$FIG04/solvent-shear.cfg" "${run[@]}" --set "box=[$L,$L,$L]" --set "pairs.[0].a=$a" \
        --set "seed=$((47000 + n))"; n=$((n + 1))
    for c in $CHOICES; do
        # shellcheck disable=SC2046
        dpd_run susp_M6_a${a}_$c "$FIG04/suspension-shear.cfg" "${geo[@]}" $(rep $a) $(choice_args $c) \
            --set "colloids.per_axis=$kq" --set "seed=$((47000 + n))"; n=$((n + 1))
        # shellcheck disable=SC2046
        dpd_run solvent_a${a}_$c "$FIG04/solvent-shear.cfg" --set "box=[$L,$L,$L]" --set "pairs.[0].a=$a" $(choice_args $c) \
            --set "seed=$((47000 + n))"; n=$((n + 1))
    done
done
# the colloid's size: H and d varied one at a time (their solvent is the default one: it has no colloids)
n=200
for a in $AS; do
    for c in $SIZES; do
        # shellcheck disable=SC2046
        dpd_run susp_M6_a${a}_$c "$FIG04/suspension-shear.cfg" "${geo[@]}" $(rep $a) $(body 6) $(choice_args $c) \
            --set "colloids.per_axis=$kq" --set "seed=$((47000 + n))"; n=$((n + 1))
    done
done
for M in $TCAF_MASSES; do
    for b in false true; do
        # shellcheck disable=SC2046
        dpd_run tcaf_M${M}_bodies$b "$T02/constrained.cfg" "${tcafrun[@]}" "${geo[@]}" $(body $M) \
            --set "colloids.per_axis=$kq" --set "measure.tcaf.include_bodies=$b" --set "seed=$((47100 + M))"
    done
done
}

analysis() {
# ---- the analysis
printf 'choice\ta\tM\teta_r\tse\teta_susp\tse\teta_solvent\tse\ttemperature_susp\tse\n' > "$OUT/eta_r.tsv"
row() {  # NAME(case) SUSP SOLVENT a M
    emit_ratio eta_r_$1 "$2" viscosity "$3" viscosity
    emit_from "$2" temperature temperature_$2
    emit_from "$3" temperature temperature_$3
    emit_from "$2" colloid_spring_extension_rms spring_extension_rms_$2
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "${1%_a*}" "$4" "$5" "$(get . eta_r_$1)" "$(get "$2" viscosity)" \
        "$(get "$3" viscosity)" "$(get "$2" temperature)" >> "$OUT/eta_r.tsv"
}
for M in $MASSES; do for a in $AS; do row M${M}_a$a susp_M${M}_a$a solvent_a$a $a $M; done; done
for c in $CHOICES; do for a in $AS; do row ${c}_a$a susp_M6_a${a}_$c solvent_a${a}_$c $a 6; done; done
for c in $SIZES; do for a in $AS; do row ${c}_a$a susp_M6_a${a}_$c solvent_a$a $a 6; done; done
# the question: does a choice make eta_r rise with a as the paper's does (6.69 - 5.17 = 1.52)?
for M in $MASSES; do emit_diff eta_r_a6.50_minus_a3.53_M$M . eta_r_M${M}_a6.50 . eta_r_M${M}_a3.53; done
for c in $CHOICES $SIZES; do emit_diff eta_r_a6.50_minus_a3.53_$c . eta_r_${c}_a6.50 . eta_r_${c}_a3.53; done
# and how far each moves eta_r from ours (M = 6, dt 0.005, rate 0.1)
for M in $MASSES; do [ "$M" = 6 ] || for a in $AS; do emit_diff eta_r_change_M${M}_a$a . eta_r_M${M}_a$a . eta_r_M6_a$a; done; done
for c in $CHOICES $SIZES; do for a in $AS; do emit_diff eta_r_change_${c}_a$a . eta_r_${c}_a$a . eta_r_M6_a$a; done; done
# the box: ours (M = 6, 7^3 colloids in 8.077^3) against the paper tier's 13^3 in 15^3 (fig04, fig05)
if [ "$TIER" = paper ]; then
    for a in $AS; do
        up=$(upstream mai-duy-2019/fig04-relative-viscosity-a353); [ "$a" = 6.50 ] && up=$(upstream mai-duy-2019/fig05-relative-viscosity-a650)
        "$ANALYSE" rename "$up/summary.tsv" eta_r_original_phi0.49 eta_r_box15_a$a >> "$OUT/summary.tsv"
        emit_diff eta_r_box8.08_minus_box15_a$a . eta_r_M6_a$a . eta_r_box15_a$a
    done
fi
# constrained TCAF eta(k -> 0) (time integral) with and without the bodies, at each M (a = 3.53),
# and the TCAF eta_r = eta_susp(M) / eta_c(k -> 0)
printf 'M\tbodies\teta_k0\tse\teta_susp\tse\n' > "$OUT/tcaf.tsv"
for M in $TCAF_MASSES; do
    for b in false true; do
        r=tcaf_M${M}_bodies$b
        ek=$(tcaf_k0 $r integral "$L")
        emit "eta_k0_constrained_M${M}_bodies$b" "${ek%	*}" "${ek#*	}"
        emit_from $r temperature temperature_$r
        printf '%s\t%s\t%s\t%s\n' "$M" "$b" "$ek" "$(get susp_M${M}_a3.53 viscosity)" >> "$OUT/tcaf.tsv"
    done
    emit_ratio tcaf_eta_r_M${M}_a3.53 susp_M${M}_a3.53 viscosity . eta_k0_constrained_M${M}_bodiesfalse
done
}
experiment
