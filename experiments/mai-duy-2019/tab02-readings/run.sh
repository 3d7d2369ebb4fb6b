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
# fit NAME MODEL RHO BOX: dpd tcaf-fit of run NAME -> runs/NAME/tcaf_fit_MODEL.tsv (per shell) and .out
fit() {
    "$DPD" tcaf-fit "$OUT/runs/$1/tcaf.tsv" --rho "$3" --box "$4" --model "$2" --table "$OUT/runs/$1/tcaf_fit_$2.tsv" \
        > "$OUT/runs/$1/tcaf_fit_$2.out"
}
# fq NAME MODEL QUANTITY -> "value<TAB>stderr" of a fit
fq() {
    awk -F'\t' -v q="$3" '$1 == q { print $2 "\t" $3; f = 1; exit } END { exit !f }' "$OUT/runs/$1/tcaf_fit_$2.out" \
        || { echo "tab02-readings: no $3 in the $2 fit of $1" >&2; return 1; }
}
# put QUANTITY "value<TAB>stderr"
put() { printf '%s\t%s\n' "$1" "$2" >> "$OUT/summary.tsv"; }
val() { awk -F'\t' -v q="$1" '$1 == q { print $2 "\t" $3; f = 1; exit } END { exit !f }' "$OUT/summary.tsv"; }
# arithmetic on "value<TAB>stderr" pairs, first-order errors of independent operands:
# pm OP X Y (OP: minus, over) and scale X FACTOR
pm() {
    num_awk -v op="$1" -v x="$2" -v y="$3" 'BEGIN { split(x, a, "\t"); split(y, b, "\t")
        if (op == "minus") num_diff(a[1], a[2], b[1], b[2], o); else num_ratio(a[1], a[2], b[1], b[2], o)
        printf "%s\n", num_pair(o) }'
}
scale() { num_awk -v x="$1" -v f="$2" 'BEGIN { split(x, a, "\t"); num_scale(a[1], a[2], f, o); printf "%s\n", num_pair(o) }'; }
# curve FILE [FREEHK_FILE]: the eta(k) shells (k n2 vectors eta eta_se) of a tcaf_eta.tsv where eta is
# defined, continued by the shells of a high-k run above its last one
curve() {
    awk -F'\t' 'FNR == 1 { f++ } /^#/ || $1 == "k" { next }
        f == 1 && $4 != "nan" { print $1 "\t" $2 "\t" $3 "\t" $4 "\t" $5; if ($1 + 0 > kmax) kmax = $1 + 0; next }
        f == 2 && $4 != "nan" && $1 + 0 > kmax * (1 + 1e-9) { print $1 "\t" $2 "\t" $3 "\t" $4 "\t" $5 }' "$@"
}
# k_eff (keff.awk) of the value "v<TAB>se" on a curve file -> "k_eff<TAB>se"
keff() {
    case ${2%	*} in nan|-nan|inf|-inf) printf 'nan\tnan\n'; return ;; esac
    num_awk -F'\t' -v ec="${2%	*}" -v se="${2#*	}" -v tag=x -f "$T02/keff.awk" "$1" | awk -F'\t' '$1 == "k_eff_x" { print $2 "\t" $3 }'
}
# at CURVE "k<TAB>se": the curve's eta at k (linear between the bracketing shells), its error from the
# two shells' and, through the slope, from k's; nan outside the curve
at() {
    case ${2%	*} in nan|-nan|inf|-inf) printf 'nan\tnan\n'; return ;; esac
    num_awk -F'\t' -v x="$2" 'BEGIN { split(x, q, "\t") } { n++; k[n] = $1; v[n] = $4; s[n] = $5 }
        END { num_interp(k, v, s, n, q[1], q[2], o); print num_pair(o) }' "$1"
}

analysis() {
# ---- per repulsion and pair ----
printf '# a\tphi\tD\tE\tK\tF\tk_eff\tse\teta_eff\tse (grid.awk)\n' > "$OUT/grid_rows.tsv"
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
        [ "$A" = 3.53 ] && awk -v c="$count" -v n="$(get $fr particles | cut -f1)" -v t="$tag" \
            'BEGIN { printf "phi_%s\t%.10g\t0\n", t, c / n }' >> "$OUT/summary.tsv"
        rho=$(get $cr tcaf_mass_density | cut -f1)
        # total density: the particles' and the bodies' (each of mass 6 m, the p = 6 constituents',
        # src/bodies/colloid.c default)
        rho_tot=$(awk -v r="$rho" -v nc="$(get $cr colloids | cut -f1)" -v L="$L" 'BEGIN { printf "%.10g", r + 6 * nc / L^3 }')
        for m in two-mode integral; do fit $fr $m "$rho" "$L"; fit $cr $m "$rho" "$L"; done
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
            "$(pm minus "$(scale "$c2" "$(awk -v a="$rho_tot" -v b="$rho" 'BEGIN { printf "%.12g", a / b }')")" "$ci")"
        put rho_particles_a${A}_$tag "$rho	0"
        put rho_total_a${A}_$tag "$rho_tot	0"
        # the free curve: today's fit, continued by the high-k run (paper)
        fc=$OUT/runs/$fr/curve.tsv
        if [ "$TIER" = paper ]; then curve "$OUT/runs/$fr/tcaf_eta.tsv" "$OUT/runs/freehk_a${A}_$tag/tcaf_eta.tsv" > "$fc"
        else curve "$OUT/runs/$fr/tcaf_eta.tsv" > "$fc"; fi
        # the readings' eta_eff
        put reading_a_eta_eff_a${A}_$tag "$ci"
        put reading_c_eta_eff_a${A}_$tag "$c2"
        put reading_d_eta_eff_a${A}_$tag "$(scale "$ci" "$(awk -v r="$rho" 'BEGIN { printf "%.12g", 4 / r }')")"
        # (e): r = eta_c / eta_f (integral), k_eff where eta_free(k) / eta_free(k -> 0) = r, the solvent there
        ratio=$(pm over "$ci" "$fi_")
        put reading_e_ratio_a${A}_$tag "$ratio"
        c0=$(get $fr tcaf_eta_k0 | cut -f1)
        awk -F'\t' -v c0="$c0" '{ printf "%s\t%s\t%s\t%.10g\t%.4g\n", $1, $2, $3, $4 / c0, $5 / c0 }' "$fc" > "$OUT/runs/$fr/curve_normalised.tsv"
        ke=$(keff "$OUT/runs/$fr/curve_normalised.tsv" "$ratio")
        put reading_e_k_eff_a${A}_$tag "$ke"
        put reading_e_eta_eff_a${A}_$tag "$(at "$sc" "$ke")"
        # (b): the bodies' run where it exists (quick: this pair; paper: fig02 at phi = 0.0876, a = 3.53)
        br=bodies_a${A}_$tag bfc=$fc
        if [ -d "$OUT/runs/$br" ]; then
            if [ "$TIER" = paper ]; then
                bfc=$OUT/runs/fig02_free_a${A}_$tag/curve.tsv
                curve "$OUT/runs/fig02_free_a${A}_$tag/tcaf_eta.tsv" "$OUT/runs/freehk_a${A}_$tag/tcaf_eta.tsv" > "$bfc"
                fit fig02_constrained_a${A}_$tag integral "$(get fig02_constrained_a${A}_$tag tcaf_mass_density | cut -f1)" "$L"
            fi
            fit $br integral "$(get $br tcaf_mass_density | cut -f1)" "$L"
            fit $br two-mode "$(get $br tcaf_mass_density | cut -f1)" "$L"
            put reading_b_eta_eff_a${A}_$tag "$(fq $br integral eta_k0)"
            put eta_k0_bodies_two_mode_a${A}_$tag "$(fq $br two-mode eta_k0)"
            # the same trajectory's particle current (quick: this pair's; paper: fig02's)
            same=$cr; [ "$TIER" = paper ] && same=fig02_constrained_a${A}_$tag
            put constrained_integral_particles_minus_bodies_a${A}_$tag "$(pm minus "$(fq $same integral eta_k0)" "$(fq $br integral eta_k0)")"
            if [ "$TIER" = paper ]; then
                # fig02's three runs by each estimator, and its free minus constrained by them
                f2=fig02_free_a${A}_$tag c2r=fig02_constrained_a${A}_$tag
                fit $f2 integral "$(get $f2 tcaf_mass_density | cut -f1)" "$L"
                fit $c2r two-mode "$(get $c2r tcaf_mass_density | cut -f1)" "$L"
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
        # the grid of the open choices (grid.awk): k_eff and eta_eff of every combination, and eta_susp
        num_awk -F'\t' -v a="$A" -v phi="$tag" -v f_p=1 -v f_s="$(awk -v r="$rho" 'BEGIN { printf "%.12g", 4 / r }')" \
            -v f_t="$(awk -v a="$rho_tot" -v b="$rho" 'BEGIN { printf "%.12g", a / b }')" \
            -v c_exp="$(get $cr tcaf_eta_k0)" -v c_two_mode="$c2" -v c_integral="$ci" \
            -v f0_exp="$(get $fr tcaf_eta_k0)" -v f0_two_mode="$(fq $fr two-mode eta_k0)" -v f0_integral="$fi_" \
            -f "$HERE/grid.awk" "$fc" "$sc" >> "$OUT/grid_rows.tsv"
        i=$((i + 1))
    done
done
# Table 2 rows (a = 3.53) under their own names (the bands' quantities)
awk -F'\t' '$1 ~ /^reading_[a-e]_(k_eff|eta_eff)_a3\.53_phi/ { q = $1; sub(/_a3\.53_/, "_", q); print q "\t" $2 "\t" $3 }' \
    "$OUT/summary.tsv" > "$OUT/.rows"
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
    awk -F'\t' -v q="$q" 'index($1, q "_a") == 1 && $3 > 0 { x = $2 / $3; x = x < 0 ? -x : x; if (x > m) m = x; n++ }
        END { printf "largest_sigmas_%s\t%.3g\t0\nlargest_sigmas_%s_cases\t%d\t0\n", q, m, q, n }' "$OUT/summary.tsv" > "$OUT/.rows"
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
            fit $r exp "$(get $r tcaf_mass_density | cut -f1)" "$L"
            awk -F'\t' -v c=$col 'NR == FNR { if ($1 !~ /^#/ && $1 != "k" && $5 != "nan" && $5 > 0) b[$2] = $5; next }
                $1 !~ /^#/ && $1 != "k" && ($2 in b) && $c != "nan" && $c > 0 { print log($c / b[$2]) }' \
                "$OUT/runs/$r/tcaf_eta.tsv" "$OUT/runs/$r/tcaf_fit_exp.tsv"
        done
    done | num_awk -v q="exp_se_${kind}_over_blocks_a3.53" -v kind=$kind '{ x[++n] = $1 }
        END { m = num_mean_se(x, n, o); e = o["se"]; printf "%s\t%.6g\t%.3g\n", q, exp(m), exp(m) * e
              if (kind == "propagated") printf "exp_se_ratio_shells_a3.53\t%d\t0\n", n }' >> "$OUT/summary.tsv"
done
# paper: the eta_0 (1 - phi) test of Table 2 and the CPU that reading (b) at every phi would take
if [ "$TIER" = paper ]; then
    e0=$(get solvent_shear_a3.53 viscosity)
    put eta0_solvent_a3.53 "$e0"
    num_awk -F'\t' -v e0="$e0" 'NR == FNR { if ($1 ~ /^phi_phi/) phi[substr($1, 5)] = $2; next }
        /^#/ || $1 == "k" { next }
        { split(e0, z, "\t"); t = sprintf("phi%.4f", $2); den = z[1] * (1 - phi[t])
          num_rel1($5 / den, z[1], z[2], o); print num_row("table2_eta_eff_over_eta0_one_minus_phi_" t, o) }' "$OUT/summary.tsv" "$PAPER2" > "$OUT/.rows"
    cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
    for A in $AS; do
        awk -F'\t' '$1 == "cpu_seconds" { s += $2 } END { printf "%.1f\t0\n", s }' "$OUT"/runs/constrained_a${A}_phi*/provenance.tsv > "$OUT/.rows"
        put reading_b_include_bodies_cpu_seconds_a$A "$(cat "$OUT/.rows")"; rm "$OUT/.rows"
    done
fi

# ---- tables ----
pmstr='function pm(q,   v, s) { if (!(q in V)) return "-"; if (V[q] == "nan") return "none"; v = V[q]; s = S[q]
           return sprintf("%.*f +- %.*f", d(v), v, d(v), s) }
       function d(v) { v = v < 0 ? -v : v; return v >= 100 ? 1 : v >= 10 ? 2 : v >= 1 ? 3 : 4 }'
tags=$(awk -F'\t' '$1 ~ /^phi_phi/ { print substr($1, 5) }' "$OUT/summary.tsv")
# estimators beside the suspension's viscosity, per repulsion
for A in $AS; do
    awk -F'\t' -v A="$A" -v tags="$tags" "$pmstr"'
        { V[$1] = $2; S[$1] = $3 }
        END { printf "phi\teta_susp (shear, rate 0.1)\tconstrained: exp (eq. 28, C/C0 >= 0.3)\tconstrained: two-mode slow mode (rho particles)\tconstrained: integral\tintegral / eta_susp\tfree: exp\tfree: two-mode\tfree: integral\n"
              n = split(tags, t, "\n"); for (i = 1; i <= n; i++) { g = "_a" A "_" t[i]
                  printf "%.4f\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", V["phi_" t[i]], pm("eta_susp" g), pm("eta_k0_constrained_exp" g),
                         pm("eta_k0_constrained_two_mode" g), pm("eta_k0_constrained_integral" g), pm("constrained_integral_over_susp" g),
                         pm("eta_k0_free_exp" g), pm("eta_k0_free_two_mode" g), pm("eta_k0_free_integral" g) } }' \
        "$OUT/summary.tsv" > "$OUT/estimators_a$A.tsv"
done
# per reading: Table 2 (a = 3.53) beside the paper, and eta_r (a = 3.53, 6.50)
for rd in $READINGS; do
    awk -F'\t' -v rd="$rd" -v tags="$tags" "$pmstr"'
        NR == FNR { if ($1 !~ /^#/ && $1 != "k") { pk[sprintf("phi%.4f", $2)] = $3; pe[sprintf("phi%.4f", $2)] = $5 }; next }
        { V[$1] = $2; S[$1] = $3 }
        END { printf "k\tphi\tk_eff (%s)\tk_eff, paper\teta_eff (%s)\teta_eff, paper\n", rd, rd
              n = split(tags, t, "\n"); for (i = 1; i <= n; i++) { g = "_a3.53_" t[i]
                  p = V["phi_" t[i]]; printf "%d\t%.4f\t%s\t%s\t%s\t%s\n", int((13500 * p / (6 * (1 - p)))^(1 / 3) + 0.5), p, pm("reading_" rd "_k_eff" g), pk[t[i]],
                         pm("reading_" rd "_eta_eff" g), pe[t[i]] } }' "$PAPER2" "$OUT/summary.tsv" > "$OUT/table2_reading_$rd.tsv"
    awk -F'\t' -v rd="$rd" -v tags="$tags" "$pmstr"'
        { V[$1] = $2; S[$1] = $3 }
        END { printf "phi\teta_r TCAF (%s), a = 3.53\teta_r TCAF (%s), a = 6.50\teta_eff (%s), a = 6.50\tk_eff (%s), a = 6.50\n", rd, rd, rd, rd
              n = split(tags, t, "\n"); for (i = 1; i <= n; i++)
                  printf "%.4f\t%s\t%s\t%s\t%s\n", V["phi_" t[i]], pm("reading_" rd "_eta_r_a3.53_" t[i]), pm("reading_" rd "_eta_r_a6.50_" t[i]),
                         pm("reading_" rd "_eta_eff_a6.50_" t[i]), pm("reading_" rd "_k_eff_a6.50_" t[i]) }' \
        "$OUT/summary.tsv" > "$OUT/eta_r_reading_$rd.tsv"
done
# numbers for the plot (nan where absent)
awk -F'\t' -v tags="$tags" -v rds="$READINGS" -v as="$AS" '{ V[$1] = $2; S[$1] = $3 }
    function g(q) { return (q in V) ? V[q] "\t" S[q] : "nan\tnan" }
    END { printf "# reading\tphi\tk_eff\tse\teta_eff\tse\teta_r_a3.53\tse\teta_r_a6.50\tse (blocks: the readings in order)\n"
          nr = split(rds, r, " "); n = split(tags, t, "\n")
          for (j = 1; j <= nr; j++) { for (i = 1; i <= n; i++)
              printf "%s\t%.6f\t%s\t%s\t%s\t%s\n", r[j], V["phi_" t[i]], g("reading_" r[j] "_k_eff_a3.53_" t[i]), g("reading_" r[j] "_eta_eff_a3.53_" t[i]),
                     g("reading_" r[j] "_eta_r_a3.53_" t[i]), g("reading_" r[j] "_eta_r_a6.50_" t[i])
              printf "\n\n" } }' "$OUT/summary.tsv" > "$OUT/readings_data.tsv"
awk -F'\t' -v tags="$tags" -v as="$AS" '{ V[$1] = $2; S[$1] = $3 }
    function g(q) { return (q in V) ? V[q] "\t" S[q] : "nan\tnan" }
    END { printf "# a\tphi\teta_susp\tse\texp\tse\ttwo_mode\tse\tintegral\tse\tfree_exp\tse\tfree_integral\tse (blocks: the repulsions in order)\n"
          na = split(as, a, " "); n = split(tags, t, "\n")
          for (j = 1; j <= na; j++) { for (i = 1; i <= n; i++) { s = "_a" a[j] "_" t[i]
              printf "%s\t%.6f\t%s\t%s\t%s\t%s\t%s\t%s\n", a[j], V["phi_" t[i]], g("eta_susp" s), g("eta_k0_constrained_exp" s),
                     g("eta_k0_constrained_two_mode" s), g("eta_k0_constrained_integral" s), g("eta_k0_free_exp" s), g("eta_k0_free_integral" s) }
              printf "\n\n" } }' "$OUT/summary.tsv" > "$OUT/estimators_data.tsv"
# the constrained C(k,t) of the smallest k at phi = 0.4940, a = 3.53, with its two-mode fit
lattice_pair "${PAIRS##* }" 4
cr=constrained_a3.53_$tag
"$DPD" tcaf-fit "$OUT/runs/$cr/tcaf.tsv" --rho "$(get $cr tcaf_mass_density | cut -f1)" --box "$L" --model two-mode \
    --curves "$OUT/runs/$cr/tcaf_fit_two-mode_curves.tsv" > /dev/null
paste <(grep -v '^#' "$OUT/runs/$cr/tcaf.tsv" | cut -f1-3) <(grep -v '^#' "$OUT/runs/$cr/tcaf_fit_two-mode_curves.tsv" | cut -f2) \
    <(grep -v '^#' "$OUT/runs/free_a3.53_$tag/tcaf.tsv" | cut -f2-3) |
    awk -F'\t' 'NR == 1 { print "t\tconstrained\tse\ttwo_mode_fit\tfree\tfree_se"; next } { print }' > "$OUT/curve_phi0.4940.tsv"
# the readings side by side: how many of Table 2's values each gives within 10 %, and eta_r(0.49)
awk -F'\t' -v tags="$tags" -v rds="$READINGS" "$pmstr"'
    NR == FNR { if ($1 !~ /^#/ && $1 != "k") { key = sprintf("phi%.4f", $2); pk[key] = $3; pe[key] = $5 }; next }
    { V[$1] = $2; S[$1] = $3 }
    function off(q, p) { return V[q] / p - 1 < 0 ? 1 - V[q] / p : V[q] / p - 1 }
    END {
        def["a"] = "J over the particles, rho of the particles, integral"
        def["b"] = "J and rho with the rigid bodies, integral"
        def["c"] = "J over the particles, rho of the particles, slow mode of the two-mode fit"
        def["d"] = "as (a) with rho = 4 (the solvent) for the constrained system"
        def["e"] = "ratio of (a)s constrained to free eta(k -> 0) on the free curve, the solvent eta(k) there"
        printf "reading\tdefinition\teta_eff within 10 %% of Table 2\tk_eff within 10 %% of Table 2\teta_eff at phi = 0.4940 (paper 15.5091)\teta_r at 0.49, a = 3.53 (paper 9.69)\teta_r at 0.49, a = 6.50 (paper 12.46)\n"
        nr = split(rds, r, " "); n = split(tags, t, "\n")
        for (j = 1; j <= nr; j++) {
            ne = nk = me = mk = 0
            for (i = 1; i <= n; i++) {
                q = "reading_" r[j] "_eta_eff_a3.53_" t[i]
                if (q in V) { me++; if (V[q] != "nan" && off(q, pe[t[i]]) <= 0.1) ne++ }
                q = "reading_" r[j] "_k_eff_a3.53_" t[i]
                if (q in V) { mk++; if (V[q] != "nan" && off(q, pk[t[i]]) <= 0.1) nk++ }
            }
            printf "(%s)\t%s\t%d of %d\t%d of %d\t%s\t%s\t%s\n", r[j], def[r[j]], ne, me, nk, mk, pm("reading_" r[j] "_eta_eff_a3.53_phi0.4940"),
                   pm("reading_" r[j] "_eta_r_a3.53_phi0.4940"), pm("reading_" r[j] "_eta_r_a6.50_phi0.4940")
        } }' "$PAPER2" "$OUT/summary.tsv" > "$OUT/readings_summary.tsv"
if [ "$TIER" = paper ]; then
    awk -F'\t' -v tags="$tags" "$pmstr"'
        NR == FNR { if ($1 !~ /^#/ && $1 != "k") pe[sprintf("phi%.4f", $2)] = $5; next }
        { V[$1] = $2; S[$1] = $3 }
        END { split(V["eta0_solvent_a3.53"] "", z, "\t")
              printf "phi\teta_eff, paper Table 2\teta_0 (1 - phi)\tratio\n"
              n = split(tags, t, "\n"); for (i = 1; i <= n; i++) {
                  e0 = V["eta0_solvent_a3.53"]; s0 = S["eta0_solvent_a3.53"]; p = V["phi_" t[i]]
                  printf "%.4f\t%s\t%.3f +- %.3f\t%s\n", p, pe[t[i]], e0 * (1 - p), s0 * (1 - p), pm("table2_eta_eff_over_eta0_one_minus_phi_" t[i]) } }' \
        "$PAPER2" "$OUT/summary.tsv" > "$OUT/eta0_one_minus_phi.tsv"
fi

# ---- the grid of the open choices (README, "The grid"): per combination, Table 2's rows (a = 3.53)
# under the decision rule (value +- 2 se inside the paper's value +- 10 %: pass; wholly outside: fail;
# else unresolved; none where the curve is not reached: fail), and the TCAF eta_r(0.49) at both a
num_awk -F'\t' -v GRID="$OUT/grid.tsv" 'FNR == 1 { file++ }
    file == 1 { if ($1 !~ /^#/ && $1 != "k") { key = sprintf("phi%.4f", $2); pk[key] = $3; pe[key] = $5 }; next }
    file == 2 { if ($1 ~ /^eta_susp_a/) { es[$1] = $2; ess[$1] = $3 }; next }
    /^#/ { next }
    function decide(v, se, p,    lo, hi) { lo = 0.9 * p; hi = 1.1 * p
        if (num_isnan(v)) return "fail"
        if (v - 2 * se >= lo && v + 2 * se <= hi) return "pass"
        if (v + 2 * se < lo || v - 2 * se > hi) return "fail"
        return "unresolved" }
    { c = $3 "_" $4 "_" $5 "_" $6
      if (!(c in seen)) { seen[c] = 1; order[++nc] = c; dd[c] = $3; ee[c] = $4; kk[c] = $5; ff[c] = $6 }
      if ($1 == "3.53" && ($2 in pe)) { ne[c, decide($9, $10, pe[$2])]++; nk[c, decide($7, $8, pk[$2])]++ }
      if ($2 == "phi0.4940") {
          q = "eta_susp_a" $1 "_phi0.4940"
          if ((q in es) && !num_isnan($9)) num_ratio(es[q], ess[q], $9, $10, o); else { o["v"] = "nan"; o["se"] = "nan" }
          er[c, $1] = num_pair(o); erf[c, $1] = num_fmt("%.2f", o["v"]) " +- " num_fmt("%.2f", o["se"]); ev[c, $1] = $9; evs[c, $1] = $10 } }
    END {
        printf "D\tE\tK\tF\teta_eff rows pass / fail / unresolved (of 11)\tk_eff rows pass / fail / unresolved (of 11)\teta_eff at 0.4940 (paper 15.5091)\teta_r(0.49), a = 3.53 (paper 9.69)\teta_r(0.49), a = 6.50 (paper 12.46)\n" > GRID
        for (i = 1; i <= nc; i++) { c = order[i]
            printf "%s\t%s\t%s\t%s\t%d / %d / %d\t%d / %d / %d\t%s\t%s\t%s\n", dd[c], ee[c], kk[c], ff[c],
                ne[c, "pass"], ne[c, "fail"], ne[c, "unresolved"], nk[c, "pass"], nk[c, "fail"], nk[c, "unresolved"],
                num_fmt("%.2f", ev[c, "3.53"]) " +- " num_fmt("%.2f", evs[c, "3.53"]), ((c, "3.53") in erf) ? erf[c, "3.53"] : "-", ((c, "6.50") in erf) ? erf[c, "6.50"] : "-" > GRID
            for (j = 1; j <= 2; j++) { A = j == 1 ? "3.53" : "6.50"
                if ((c, A) in er) { split(er[c, A], x, "\t"); printf "grid_%s_eta_r_a%s_phi0.4940\t%s\t%s\n", c, A, x[1], x[2] } }
            printf "grid_%s_table2_eta_eff_rows_pass\t%d\t0\ngrid_%s_table2_k_eff_rows_pass\t%d\t0\n", c, ne[c, "pass"], c, nk[c, "pass"] } }' \
    "$PAPER2" "$OUT/summary.tsv" "$OUT/grid_rows.tsv" > "$OUT/.rows"
cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
}
experiment
