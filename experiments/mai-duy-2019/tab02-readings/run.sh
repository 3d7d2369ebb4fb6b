#!/usr/bin/env bash
# Mai-Duy et al. 2019, Table 2 and the TCAF eta_r of Figs 4-5 under five readings of section 4.2.3
# (README.md: (a) literal, (b) bodies included, (c) mobile particles' slow mode, (d) solvent
# density, (e) two-step), and the constrained eta(k -> 0) by three estimators of eta(k)
# (`dpd tcaf-fit`) beside the suspension's shear viscosity. Paper tier: the committed simulations
# of tab01-wavelengths, fig01, fig02, fig04 and fig05 (reuse_run), analysed; quick tier: phi = 0.4940
# with systems of its own.
. "$DPD_ROOT/tools/lib/exp.sh"
needs paper mai-duy-2019/tab01-wavelengths
needs paper mai-duy-2019/fig01-viscosity-wavenumber
needs paper mai-duy-2019/fig02-length-scale
needs paper mai-duy-2019/fig04-relative-viscosity-a353
needs paper mai-duy-2019/fig05-relative-viscosity-a650
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
T02=$HERE/../tab02-effective-viscosity
F01=$HERE/../fig01-viscosity-wavenumber
F04=$HERE/../fig04-relative-viscosity-a353
PAPER2=$T02/paper-table2.tsv
MD=mai-duy-2019
READINGS="a b c d e"
case $TIER in
    # 13^3 colloids of the paper as 7^3 in 8.077^3 (the paper's lattice spacing); dt 0.005 (0.01 runs
    # this density 2 % hot); TCAF every 2 steps, window 1.0, origins every 0.05, n2 <= 9
    quick) PAIRS="13:7"; AS="3.53"
           tcaf=(--set dt=0.005 --set equilibration=400 --set steps=2400 --set measure.tcaf.every=2
                 --set measure.tcaf.window=200 --set measure.tcaf.origin_every=10 --set measure.tcaf.n2max=9)
           shear=(--set equilibration=400 --set steps=1600) ;;
    paper) PAIRS="3:3 4:4 5:5 6:6 7:7 8:8 9:9 10:10 11:11 12:12 13:13"; AS="3.53 6.50" ;;
    *) echo "tab02-readings: no tier '$TIER' (quick, paper)" >&2; exit 1 ;;
esac

# ---- simulations (paper: copies of committed ones) ----
# the runs of lattice pair "$pair" (after lattice_pair "$pair" 4) at repulsion $1, under the names
# free_a<A>_<tag>, constrained_..., susp_..., and freehk_... (paper) or bodies_... (quick)
pair_runs() {
    local A=$1 t2 src
    if [ "$TIER" = quick ]; then
        dpd_run free_a${A}_$tag "$T02/free.cfg" "${tcaf[@]}" "${geo[@]}" --set seed=61300
        dpd_run constrained_a${A}_$tag "$T02/constrained.cfg" "${tcaf[@]}" "${geo[@]}" --set "colloids.per_axis=$kq" --set seed=61301
        # the same trajectory (same seed), the bodies' momentum and mass in the current
        dpd_run bodies_a${A}_$tag "$T02/constrained.cfg" "${tcaf[@]}" "${geo[@]}" --set "colloids.per_axis=$kq" --set seed=61301 \
            --set measure.tcaf.include_bodies=true
        dpd_run susp_a${A}_$tag "$F04/suspension-shear.cfg" "${shear[@]}" "${geo[@]}" --set "colloids.per_axis=$kq" --set seed=61302
        return 0
    fi
    t2=$(lattice_pair "$pair" 2; echo "$tag")   # fig04/fig05 name their runs with 2 decimals
    if [ "$A" = 3.53 ]; then
        reuse_run free_a${A}_$tag $MD/tab01-wavelengths paper free_$tag
        reuse_run constrained_a${A}_$tag $MD/tab01-wavelengths paper constrained_$tag
        src=$MD/fig04-relative-viscosity-a353
    else
        src=$MD/fig05-relative-viscosity-a650
        reuse_run free_a${A}_$tag $src paper free_$t2
        reuse_run constrained_a${A}_$tag $src paper constrained_$t2
    fi
    reuse_run susp_a${A}_$tag $src paper susp_$t2
    reuse_run freehk_a${A}_$tag $src paper freehk_$t2
}
# the n = 4 solvent's eta(k) (reading e) and shear viscosity (eta_0)
simulations() {
if [ "$TIER" = quick ]; then
    lattice_pair "${PAIRS%% *}" 4
    dpd_run solvent_tcaf_a3.53 "$F01/solvent-tcaf.cfg" "${tcaf[@]}" --set "box=[$L,$L,$L]" --set seed=61303
else
    reuse_run solvent_tcaf_a3.53 $MD/fig01-viscosity-wavenumber paper solvent
    reuse_run solventhk_a3.53 $MD/fig04-relative-viscosity-a353 paper solventhk_phi0.49
    reuse_run solventhk_a6.50 $MD/fig05-relative-viscosity-a650 paper solventhk_phi0.49
    reuse_run solvent_shear_a3.53 $MD/fig04-relative-viscosity-a353 paper solvent
    # reading (b): fig02's free and constrained runs at phi = 0.0876 and the constrained one repeated
    # with the bodies in the current (same seed: same trajectory)
    reuse_run fig02_free_a3.53_phi0.0876 $MD/fig02-length-scale paper free
    reuse_run fig02_constrained_a3.53_phi0.0876 $MD/fig02-length-scale paper constrained
    reuse_run bodies_a3.53_phi0.0876 $MD/fig02-length-scale paper constrained_bodies
fi
for A in $AS; do for pair in $PAIRS; do lattice_pair "$pair" 4; pair_runs "$A"; done; done
}

# ---- analysis helpers ----
# fq NAME MODEL QUANTITY -> "value<TAB>stderr" of a fit
fq() { tsv_lookup "$OUT/runs/$1/tcaf_fit_$2.out" "$3" tab02-readings; }
# put QUANTITY "value<TAB>stderr"
put() { printf '%s\t%s\n' "$1" "$2" >> "$OUT/summary.tsv"; }
val() { tsv_lookup "$OUT/summary.tsv" "$1"; }
# arithmetic on "value<TAB>stderr" pairs, first-order errors of independent operands:
# pm OP X Y (OP: minus, over) and scale X FACTOR
pm() { if [ "$1" = minus ]; then "$ANALYSE" diff "$2" "$3"; else "$ANALYSE" ratio "$2" "$3"; fi; }
scale() { "$ANALYSE" scale "$1" "$2"; }
# curve FILE [FREEHK_FILE]: the eta(k) shells (k n2 vectors eta eta_se) of a tcaf_eta.tsv where eta is
# defined, continued by the shells of a high-k run above its last one
curve() { "$ANALYSE" curve "$@"; }
# k_eff of the value "v<TAB>se" on a curve file -> "k_eff<TAB>se" (nan for a nan value)
keff() { "$ANALYSE" k-eff "$1" "$2"; }
# at CURVE "k<TAB>se": the curve's eta at k (linear between the bracketing shells), its error from the
# two shells' and, through the slope, from k's; nan outside the curve
at() { "$ANALYSE" interp "$1" "$2"; }

analysis() {
# ---- per repulsion and pair ----
"$ANALYSE" grid --header > "$OUT/grid_rows.tsv"
i=0
for A in $AS; do
    # the solvent's eta(k) for reading (e)
    if [ "$TIER" = quick ]; then curve "$OUT/runs/solvent_tcaf_a$A/tcaf_eta.tsv" > "$OUT/runs/solvent_tcaf_a$A/curve.tsv"; sc=$OUT/runs/solvent_tcaf_a$A/curve.tsv
    elif [ "$A" = 3.53 ]; then
        curve "$OUT/runs/solvent_tcaf_a$A/tcaf_eta.tsv" "$OUT/runs/solventhk_a$A/tcaf_eta.tsv" > "$OUT/runs/solventhk_a$A/curve.tsv"; sc=$OUT/runs/solventhk_a$A/curve.tsv
    else curve "$OUT/runs/solventhk_a$A/tcaf_eta.tsv" > "$OUT/runs/solventhk_a$A/curve.tsv"; sc=$OUT/runs/solventhk_a$A/curve.tsv; fi
    for pair in $PAIRS; do
        lattice_pair "$pair" 4
        fr=free_a${A}_$tag cr=constrained_a${A}_$tag
        [ "$A" = 3.53 ] && "$ANALYSE" phi-row "$tag" "$count" "$(getv $fr particles)" >> "$OUT/summary.tsv"
        rho=$(getv $cr tcaf_mass_density)
        # total density: the particles' and the bodies' (each of mass 6 m, the p = 6 constituents',
        # src/bodies/colloid.c default)
        rho_tot=$("$ANALYSE" rho-total "$rho" "$(getv $cr colloids)" "$L")
        # the density factors of readings (d) and (c)'s total density: 4 / rho and rho_tot / rho
        f_s=$("$ANALYSE" quotient 4 "$rho") f_t=$("$ANALYSE" quotient "$rho_tot" "$rho")
        tcaf_fit $fr two-mode,integral "$rho" "$L"; tcaf_fit $cr two-mode,integral "$rho" "$L"
        # the estimators' eta(k -> 0) (exp: the run's own fit, errors from blocks) and the suspension's
        for sys in free constrained; do
            r=${sys}_a${A}_$tag
            put eta_k0_${sys}_exp_a${A}_$tag "$(get $r tcaf_eta_k0)"
            put eta_k0_${sys}_two_mode_a${A}_$tag "$(fq $r two-mode eta_k0)"
            put eta_k0_${sys}_integral_a${A}_$tag "$(fq $r integral eta_k0)"
        done
        put eta_susp_a${A}_$tag "$(get susp_a${A}_$tag viscosity)"
        ci=$(fq $cr integral eta_k0) c2=$(fq $cr two-mode eta_k0) fi_=$(fq $fr integral eta_k0)
        put free_integral_minus_exp_a${A}_$tag "$(pm minus "$fi_" "$(get $fr tcaf_eta_k0)")"
        put free_two_mode_minus_exp_a${A}_$tag "$(pm minus "$(fq $fr two-mode eta_k0)" "$(get $fr tcaf_eta_k0)")"
        put constrained_integral_over_susp_a${A}_$tag "$(pm over "$ci" "$(get susp_a${A}_$tag viscosity)")"
        put constrained_slow_mode_total_density_minus_integral_a${A}_$tag \
            "$(pm minus "$(scale "$c2" "$f_t")" "$ci")"
        put rho_particles_a${A}_$tag "$rho	0"
        put rho_total_a${A}_$tag "$rho_tot	0"
        # the free curve: today's fit, continued by the high-k run (paper)
        fc=$OUT/runs/$fr/curve.tsv
        if [ "$TIER" = paper ]; then curve "$OUT/runs/$fr/tcaf_eta.tsv" "$OUT/runs/freehk_a${A}_$tag/tcaf_eta.tsv" > "$fc"
        else curve "$OUT/runs/$fr/tcaf_eta.tsv" > "$fc"; fi
        # the readings' eta_eff
        put reading_a_eta_eff_a${A}_$tag "$ci"
        put reading_c_eta_eff_a${A}_$tag "$c2"
        put reading_d_eta_eff_a${A}_$tag "$(scale "$ci" "$f_s")"
        # (e): r = eta_c / eta_f (integral), k_eff where eta_free(k) / eta_free(k -> 0) = r, the solvent there
        ratio=$(pm over "$ci" "$fi_")
        put reading_e_ratio_a${A}_$tag "$ratio"
        c0=$(getv $fr tcaf_eta_k0)
        "$ANALYSE" normalise "$fc" "$c0" > "$OUT/runs/$fr/curve_normalised.tsv"
        ke=$(keff "$OUT/runs/$fr/curve_normalised.tsv" "$ratio")
        put reading_e_k_eff_a${A}_$tag "$ke"
        put reading_e_eta_eff_a${A}_$tag "$(at "$sc" "$ke")"
        # (b): the bodies' run where it exists (quick: this pair; paper: fig02 at phi = 0.0876, a = 3.53)
        br=bodies_a${A}_$tag bfc=$fc
        if [ -d "$OUT/runs/$br" ]; then
            if [ "$TIER" = paper ]; then
                bfc=$OUT/runs/fig02_free_a${A}_$tag/curve.tsv
                curve "$OUT/runs/fig02_free_a${A}_$tag/tcaf_eta.tsv" "$OUT/runs/freehk_a${A}_$tag/tcaf_eta.tsv" > "$bfc"
                tcaf_fit fig02_constrained_a${A}_$tag integral,two-mode "$(getv fig02_constrained_a${A}_$tag tcaf_mass_density)" "$L"
            fi
            tcaf_fit $br integral,two-mode "$(getv $br tcaf_mass_density)" "$L"
            put reading_b_eta_eff_a${A}_$tag "$(fq $br integral eta_k0)"
            put eta_k0_bodies_two_mode_a${A}_$tag "$(fq $br two-mode eta_k0)"
            # the same trajectory's particle current (quick: this pair's; paper: fig02's)
            same=$cr; [ "$TIER" = paper ] && same=fig02_constrained_a${A}_$tag
            put constrained_integral_particles_minus_bodies_a${A}_$tag "$(pm minus "$(fq $same integral eta_k0)" "$(fq $br integral eta_k0)")"
            if [ "$TIER" = paper ]; then
                # fig02's three runs by each estimator, and its free minus constrained by them
                f2=fig02_free_a${A}_$tag c2r=fig02_constrained_a${A}_$tag
                tcaf_fit $f2 integral "$(getv $f2 tcaf_mass_density)" "$L"   # (c2r's fits: above)
                put fig02_eta_k0_free_exp_a${A}_$tag "$(get $f2 tcaf_eta_k0)"
                put fig02_eta_k0_free_integral_a${A}_$tag "$(fq $f2 integral eta_k0)"
                put fig02_eta_k0_constrained_exp_a${A}_$tag "$(get $c2r tcaf_eta_k0)"
                put fig02_eta_k0_constrained_integral_a${A}_$tag "$(fq $c2r integral eta_k0)"
                put fig02_eta_k0_constrained_two_mode_a${A}_$tag "$(fq $c2r two-mode eta_k0)"
                put fig02_eta_k0_bodies_exp_a${A}_$tag "$(get $br tcaf_eta_k0)"
                put fig02_free_minus_constrained_integral_a${A}_$tag "$(pm minus "$(fq $f2 integral eta_k0)" "$(fq $c2r integral eta_k0)")"
                put fig02_free_minus_constrained_two_mode_a${A}_$tag "$(pm minus "$(get $f2 tcaf_eta_k0)" "$(fq $c2r two-mode eta_k0)")"
            fi
        fi
        for rd in a b c d; do
            v=$(val reading_${rd}_eta_eff_a${A}_$tag) || continue
            curvefile=$fc; [ $rd = b ] && curvefile=$bfc
            put reading_${rd}_k_eff_a${A}_$tag "$(keff "$curvefile" "$v")"
        done
        for rd in $READINGS; do
            v=$(val reading_${rd}_eta_eff_a${A}_$tag) || continue
            put reading_${rd}_eta_r_a${A}_$tag "$(pm over "$(get susp_a${A}_$tag viscosity)" "$v")"
        done
        # the grid of the open choices (analysis.py tcaf_grid): k_eff and eta_eff of every combination
        "$ANALYSE" grid "$A" "$tag" 1 "$f_s" "$f_t" \
            "$(get $cr tcaf_eta_k0)" "$c2" "$ci" "$(get $fr tcaf_eta_k0)" "$(fq $fr two-mode eta_k0)" "$fi_" \
            "$fc" "$sc" >> "$OUT/grid_rows.tsv"
        i=$((i + 1))
    done
done
# Table 2 rows (a = 3.53) under their own names (the bands' quantities)
"$ANALYSE" readings-table2-rows "$OUT/summary.tsv" > "$OUT/.rows"
cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
# the set-up of the quick tier's runs
if [ "$TIER" = quick ]; then
    t=phi0.4940
    for q in free_integral_minus_exp free_two_mode_minus_exp constrained_slow_mode_total_density_minus_integral \
             constrained_integral_particles_minus_bodies; do put ${q}_$t "$(val ${q}_a3.53_$t)"; done
    put temperature_free_$t "$(get free_a3.53_$t temperature)"
    put temperature_constrained_$t "$(get constrained_a3.53_$t temperature)"
    put spring_extension_rms_$t "$(get constrained_a3.53_$t colloid_spring_extension_rms)"
fi
# the largest |difference| / stderr over every phi and repulsion: the new estimators against today's
# fit on the free systems, and the total-density slow mode against the integral on the constrained ones
for q in free_integral_minus_exp free_two_mode_minus_exp constrained_slow_mode_total_density_minus_integral; do
    "$ANALYSE" largest-sigmas "$OUT/summary.tsv" "$q" > "$OUT/.rows"
    cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
done
# the propagated errors against the blocks': eq. 28's fit of every shell of the free and constrained
# runs at a = 3.53 by `dpd tcaf-fit --model exp` (the simulator's own fit of the mean curve, errors
# propagated from the per-lag errors) against the run's tcaf_eta.tsv (the same fit block by block);
# the geometric mean of the ratios over the shells, its error from their scatter (shells independent)
for kind in propagated bound; do
    col=4; [ $kind = bound ] && col=5
    for pair in $PAIRS; do
        lattice_pair "$pair" 4
        for sys in free constrained; do
            r=${sys}_a3.53_$tag
            tcaf_fit $r exp "$(getv $r tcaf_mass_density)" "$L"
            "$ANALYSE" log-ratios $col "$OUT/runs/$r/tcaf_eta.tsv" "$OUT/runs/$r/tcaf_fit_exp.tsv"
        done
    done | "$ANALYSE" geometric-mean "exp_se_${kind}_over_blocks_a3.53" $kind >> "$OUT/summary.tsv"
done
# paper: the eta_0 (1 - phi) test of Table 2 and the CPU that reading (b) at every phi would take
if [ "$TIER" = paper ]; then
    e0=$(get solvent_shear_a3.53 viscosity)
    put eta0_solvent_a3.53 "$e0"
    "$ANALYSE" eta0-ratios "$OUT/summary.tsv" "$PAPER2" "$e0" > "$OUT/.rows"
    cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
    for A in $AS; do
        "$ANALYSE" sum-column cpu_seconds $'%.1f\t0' "$OUT"/runs/constrained_a${A}_phi*/provenance.tsv > "$OUT/.rows"
        put reading_b_include_bodies_cpu_seconds_a$A "$(cat "$OUT/.rows")"; rm "$OUT/.rows"
    done
fi

# ---- tables ----
# estimators_aA, table2_reading_R, eta_r_reading_R, readings_data, estimators_data, readings_summary
# (paper: eta0_one_minus_phi) from the summary (analysis.py readings_tables)
# and the readings side by side: how many of Table 2's values each gives within 10 %, and eta_r(0.49)
"$ANALYSE" readings-tables "$OUT" "$PAPER2" "$TIER" "$AS" "$READINGS"
# the constrained C(k,t) of the smallest k at phi = 0.4940, a = 3.53, with its two-mode fit
lattice_pair "${PAIRS##* }" 4
cr=constrained_a3.53_$tag
"$DPD" tcaf-fit "$OUT/runs/$cr/tcaf.tsv" --rho "$(getv $cr tcaf_mass_density)" --box "$L" --model two-mode \
    --curves "$OUT/runs/$cr/tcaf_fit_two-mode_curves.tsv" > /dev/null
paste <(grep -v '^#' "$OUT/runs/$cr/tcaf.tsv" | cut -f1-3) <(grep -v '^#' "$OUT/runs/$cr/tcaf_fit_two-mode_curves.tsv" | cut -f2) \
    <(grep -v '^#' "$OUT/runs/free_a3.53_$tag/tcaf.tsv" | cut -f2-3) |
    { read -r _; printf 't\tconstrained\tse\ttwo_mode_fit\tfree\tfree_se\n'; cat; } > "$OUT/curve_phi0.4940.tsv"

# ---- the grid of the open choices (README, "The grid"): per combination, Table 2's rows (a = 3.53)
# under the decision rule (value +- 2 se inside the paper's value +- 10 %: pass; wholly outside: fail;
# else unresolved; none where the curve is not reached: fail), and the TCAF eta_r(0.49) at both a
"$ANALYSE" readings-grid "$PAPER2" "$OUT/summary.tsv" "$OUT/grid_rows.tsv" "$OUT/grid.tsv" > "$OUT/.rows"
cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
# what paper.md says in words (issue 40 item 7): reading (d)'s eta_eff at phi = 0.4940 over the
# paper's (Table 2, bands.tsv), where it is computed
if d=$(get . reading_d_eta_eff_phi0.4940 2> /dev/null); then
    "$ANALYSE" div "$d" "$(paper_number reading_d_eta_eff_phi0.4940)" reading_d_eta_eff_phi0.4940_over_paper >> "$OUT/summary.tsv"
fi
}
experiment
