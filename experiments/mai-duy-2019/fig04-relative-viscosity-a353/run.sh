#!/usr/bin/env bash
# Figs 4-5 of Mai-Duy et al. 2019: relative viscosity eta_r(phi) of the spring-model suspension
# under simple shear, eta_susp / eta_solvent with four choices of the solvent viscosity:
#   original: the solvent's shear viscosity (same box, rate, run length);
#   TCAF:     eta_eff = the constrained system's eta(k -> 0) by the time integral of C(k,t) (Table 2,
#             tab02-effective-viscosity; the two-mode slow mode and eq. 28's amplitude-1 fit beside it);
#   cube, sphere: the free system's eta(k) at k = 2 pi / lambda, lambda of eq. 31 / eq. 32, from
#             a short run at dt = 0.001 sampling the axis wave vectors up to past the sphere's k
#             (the main TCAF runs reach |k| ~ 2 and cannot resolve decays of a few steps);
#             the same for the solvent alone (n = 4) in the same box (columns *_solvent).
# fig05-relative-viscosity-a650 runs this script with A=6.50.
. "$DPD_ROOT/tools/lib/exp.sh"
needs paper mai-duy-2019/tab01-wavelengths
A=${A:-3.53}
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
T02=$HERE/../tab02-effective-viscosity
# "kp:kq": the paper's k^3 colloids in 15^3 (names the phi) run as kq^3 colloids in a box
# 15 kq / kp (same lattice spacing, particles per colloid cell and phi as the paper's)
# hik: the high-k runs (every step at dt = 0.001: the decay time at the sphere's k is ~0.01)
hik=(--set dt=0.001 --set measure.tcaf.every=1 --set measure.tcaf.window=60 --set measure.tcaf.origin_every=10
     --set measure.tcaf.n2max=1 --set measure.blocks=20)
case $TIER in
    quick) PAIRS="8:4 13:7"; TCAF_PAIRS="8:4"; LSOLV=8; hik+=(--set equilibration=300 --set steps=1000)
           # shear runs at the scene's (the paper's) dt = 0.005, 2 + 8 time units: at 0.01 the
           # phi = 0.49 suspension (total density 7.9) runs 2 % hot and its springs stretch past
           # equipartition (issue 23); the TCAF pair at phi = 0.19 keeps 0.01 (right there)
           shear=(--set equilibration=400 --set steps=1600)
           tcaf=(--set dt=0.01 --set equilibration=200 --set steps=1200 --set measure.tcaf.every=1
                 --set measure.tcaf.window=60 --set measure.tcaf.origin_every=10 --set measure.tcaf.n2max=9) ;;
    # reduced: the paper's box, dt and TCAF settings at two phi, shorter runs (not the paper tier)
    reduced) PAIRS="8:8 13:13"; TCAF_PAIRS="13:13"; LSOLV=15; hik+=(--set equilibration=1000 --set steps=2000)
           shear=(--set equilibration=1000 --set steps=3000); tcaf=(--set equilibration=500 --set steps=3000) ;;
    paper) PAIRS="3:3 4:4 5:5 6:6 7:7 8:8 9:9 10:10 11:11 12:12 13:13"; TCAF_PAIRS=$PAIRS; LSOLV=15
           hik+=(--set equilibration=1000 --set steps=4000)
           shear=(); tcaf=() ;;
esac
rep=(--set "pairs.[0].a=$A")
rep3=(--set "pairs.[0].a=$A" --set "pairs.[1].a=$A" --set "pairs.[2].a=$A")
# the simulations of lattice pair number $1 ($2 = "kp:kq", after lattice_pair): the shear run and,
# at a TCAF pair, the free and constrained TCAF runs and the high-k runs (nax: the axis shells
# n = 1 .. 1 + the sphere's n, k = 2 pi n / L; the cube's k is the shell n = kq)
pair_simulations() {
    local i=$1 pair=$2 nax
    dpd_run susp_$tag "$HERE/suspension-shear.cfg" "${shear[@]}" "${rep3[@]}" "${geo[@]}" \
        --set "colloids.per_axis=$kq" --set "seed=$((40200 + i))"
    [[ " $TCAF_PAIRS " == *" $pair "* ]] || return 0
    if [ "$TIER" = paper ] && [ "$A" = 3.53 ]; then
        # the same scenes and settings as tab01-wavelengths' paper tier (the scenes' a = 3.53):
        # its simulations, not new ones (tools/lib/exp.sh reuse_run; `needs` above orders them)
        t01=$(lattice_pair "$pair" 4; echo "$tag")   # tab01's tag (4 decimals)
        reuse_run free_$tag mai-duy-2019/tab01-wavelengths paper free_$t01
        reuse_run constrained_$tag mai-duy-2019/tab01-wavelengths paper constrained_$t01
    else
        dpd_run free_$tag "$T02/free.cfg" "${tcaf[@]}" "${rep3[@]}" "${geo[@]}" --set "seed=$((40300 + 2 * i))"
        dpd_run constrained_$tag "$T02/constrained.cfg" "${tcaf[@]}" "${rep3[@]}" "${geo[@]}" \
            --set "colloids.per_axis=$kq" --set "seed=$((40301 + 2 * i))"
    fi
    nax=$("$ANALYSE" tcaf-axis-nmax "$kq")
    dpd_run freehk_$tag "$T02/free.cfg" "${hik[@]}" "${rep3[@]}" "${geo[@]}" --set "measure.tcaf.axis_nmax=$nax" \
        --set "seed=$((40500 + 2 * i))"
    dpd_run solventhk_$tag "$HERE/../fig01-viscosity-wavenumber/solvent-tcaf.cfg" "${hik[@]}" "${rep[@]}" \
        --set "box=[$L,$L,$L]" --set "measure.tcaf.axis_nmax=$nax" --set "seed=$((40501 + 2 * i))"
}
# the simulations: each lattice pair's, the solvent alone, and five colloid RDF runs
simulations() {
i=0
for pair in $PAIRS; do lattice_pair "$pair" 2; pair_simulations $i "$pair"; i=$((i + 1)); done
dpd_run solvent "$HERE/solvent-shear.cfg" "${shear[@]}" "${rep[@]}" --set "box=[$LSOLV,$LSOLV,$LSOLV]"
rdf_name() { [ "$1" -gt 0 ] && echo rdf_r$1 || echo rdf; }
for r in 0 1 2 3 4; do
    seed=(); [ $r -gt 0 ] && seed=(--set "seed=$((40170 + r))")
    dpd_run "$(rdf_name $r)" "$HERE/colloid-rdf.cfg" "${rep3[@]}" "${seed[@]}"
done
}
analysis() {
# the analysis
emit_from solvent viscosity eta_solvent
emit_from solvent temperature temperature_solvent
# colloid size: one colloid at rest in a 5^3 box; r_half where the solvent-constituent RDF
# reaches 1/2, from a straight line through g(r) over 0.1 <= r <= 0.6 (where it rises from ~0.2
# to ~0.65; `dpd fit-line`): r_half = 0.35 + (1/2 - g(0.35)) / slope; the colloid radius
# d + r_half (d = 0.5, the site distance). Five independent runs (seeds 40170 ... 40174), r_half
# their mean, its error from their scatter (the bins of one g(r) are not independent, so the
# fit's own error would understate it).
rdfs=""
for r in 0 1 2 3 4; do
    name=$(rdf_name $r)
    "$DPD" fit-line "$OUT/runs/$name/rdf.tsv" --x r --y g --se g_se --range 0.1:0.6 |
        "$ANALYSE" r-half > "$OUT/runs/$name/r_half"
    rdfs="$rdfs $(cat "$OUT/runs/$name/r_half")"
done
cp "$OUT/runs/rdf/rdf.tsv" "$OUT/colloid_rdf.tsv"
"$ANALYSE" colloid-radius "$rdfs" 0.5 >> "$OUT/summary.tsv"
# the shear rate of the paper's Pe = 0.18 (paper.md): Pe = rate a^2 / D0, D0 = kBT / (6 pi eta_solvent a)
"$ANALYSE" shear-rate-at-pe "$OUT/summary.tsv" 0.18 > "$OUT/.rows"; cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
printf 'phi\teta_r_original\tse\teta_r_tcaf\tse\teta_r_cube\tse\teta_r_sphere\tse\teta_r_cube_solvent\tse\teta_r_sphere_solvent\tse\n' > "$OUT/eta_r.tsv"
for pair in $PAIRS; do
    lattice_pair "$pair" 2
    np=$(getv susp_$tag particles)
    "$ANALYSE" phi-row "$tag" "$count" "$np" >> "$OUT/summary.tsv"
    emit_from susp_$tag viscosity eta_susp_$tag
    emit_from susp_$tag temperature temperature_$tag
    emit_from susp_$tag colloid_spring_extension_rms spring_extension_rms_$tag
    emit_ratio eta_r_original_$tag susp_$tag viscosity solvent viscosity
    if [[ " $TCAF_PAIRS " == *" $pair "* ]]; then
        # the TCAF construction of tab02-effective-viscosity at this phi and repulsion: the constrained
        # eta(k -> 0) by the time integral of C(k,t) (tcaf_k0, tools/lib/exp.sh; issue 37), the
        # two-mode slow mode (second estimator) and eq. 28's amplitude-1 fit (the paper's literal, *_exp_*)
        emit_from free_$tag tcaf_eta_k0 eta_k0_free_$tag
        emit eta_eff_$tag "$(tcaf_k0 constrained_$tag integral,two-mode "$L")"
        emit eta_eff_two_mode_$tag "$(tcaf_k0_of constrained_$tag two-mode)"
        emit_from constrained_$tag tcaf_eta_k0 eta_eff_exp_$tag
        emit_ratio eta_r_tcaf_$tag susp_$tag viscosity . eta_eff_$tag
        emit_ratio eta_r_tcaf_two_mode_$tag susp_$tag viscosity . eta_eff_two_mode_$tag
        emit_ratio eta_r_tcaf_exp_$tag susp_$tag viscosity constrained_$tag tcaf_eta_k0
        lc=$("$ANALYSE" lambda-cube "$L" "$kq")      # eq. 31
        ls=$("$ANALYSE" lambda-sphere "$L" "$kq")    # eq. 32
        # eta(k) at the cube and sphere k (the high-k runs), free system and solvent alone in the same box
        emit_from freehk_$tag temperature temperature_freehk_$tag
        for sys in free solvent; do
            "$ANALYSE" etak "$OUT/runs/${sys}hk_$tag/tcaf_eta.tsv" "$lc" "eta_${sys}_cube_$tag" >> "$OUT/summary.tsv"
            "$ANALYSE" etak "$OUT/runs/${sys}hk_$tag/tcaf_eta.tsv" "$ls" "eta_${sys}_sphere_$tag" >> "$OUT/summary.tsv"
            cp "$OUT/runs/${sys}hk_$tag/tcaf_eta.tsv" "$OUT/tcaf_eta_${sys}hk_$tag.tsv"
        done
        printf 'lambda_cube_%s\t%s\t0\nlambda_sphere_%s\t%s\t0\n' "$tag" "$lc" "$tag" "$ls" >> "$OUT/summary.tsv"
        # ratios and the TCAF - original difference (errors of the shared eta_susp counted once)
        "$ANALYSE" fig04-ratios "$OUT/summary.tsv" "$tag" > "$OUT/.rows"
        cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
        cp "$OUT/runs/free_$tag/tcaf_eta.tsv" "$OUT/tcaf_eta_free_$tag.tsv"
        cp "$OUT/runs/constrained_$tag/tcaf_eta.tsv" "$OUT/tcaf_eta_constrained_$tag.tsv"
    fi
    "$ANALYSE" fig04-eta-r-row "$OUT/summary.tsv" "$tag" >> "$OUT/eta_r.tsv"
done
# what paper.md says in words (issue 40 item 7): the free system's eta(k -> 0) against eta_eff at
# phi = 0.19 (where that phi is run)
if f=$(get . eta_k0_free_phi0.19 2> /dev/null) && e=$(get . eta_eff_phi0.19 2> /dev/null); then
    emit_minus eta_k0_free_minus_eta_eff_phi0.19 "$f" "$e"
fi
}
experiment
