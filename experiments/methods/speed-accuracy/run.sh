#!/usr/bin/env bash
# The speed-accuracy trade, measured (issue 7): ladders of cost settings with the
# error of a result against theory or the paper-tier value, and the CPU seconds.
#  1. Groot-Warren fluid (rho 3, a 25, sigma 3): kinetic temperature against dt for
#     the modified velocity Verlet at lambda = 0.5 and 0.65 (theory: kBT = 1).
#  2. mai-duy-2019 solvent (eq. 29): the same, near its stability edge.
#  3. pan-2008 rotating fluid: translational and rotational temperature against dt.
#  4. phan-thien-2016 Couette channel (Fig. 3 set-up, m = 0): the viscosity against
#     the eq. 27 tolerance of PCG and of the consistent Scheme 2 (error against the
#     fig03 paper-tier value).
. "$DPD_ROOT/tools/lib/exp.sh"
needs any phan-thien-2016/fig03-couette-profile@paper
case $TIER in
    quick) GW_DTS="0.005 0.01 0.02 0.03 0.04 0.05 0.06"; GW_T=20; GW_BOX=8
           MD_DTS="0.01 0.015 0.0175 0.02"; MD_T=8; MD_BOX=5
           PAN_DTS="0.005 0.01 0.015 0.02"; PAN_T=10; PAN_BOX=6
           OD_STEPS=500 OD_EQ=100
           declare -A OD_TOLS=([pcg]="1e-1 1e-3 1e-7" [scheme2_consistent]="1e-1 1e-2 1e-3") ;;
    paper) GW_DTS="0.01 0.02 0.03 0.04 0.05 0.06 0.07"; GW_T=100; GW_BOX=10
           MD_DTS="0.005 0.01 0.0125 0.015 0.0175 0.02"; MD_T=40; MD_BOX=8
           PAN_DTS="0.005 0.01 0.015 0.02"; PAN_T=40; PAN_BOX=8
           OD_STEPS=3000 OD_EQ=200
           declare -A OD_TOLS=([pcg]="1e-1 1e-2 1e-3 1e-4 1e-5 1e-7" [scheme2_consistent]="1e-1 1e-2 1e-3 1e-4 1e-5 1e-7") ;;
esac
# equilibration, time units: the heat of the random start (a = 25) is gone within about one
case $TIER in quick) T_EQ=2 ;; paper) T_EQ=5 ;; esac
nsteps() { "$ANALYSE" steps-for $1 $2; }

# ---- the simulations -----------------------------------------------------------
# 1-3: ladder_simulations FLUID SCENE BOX T_RUN "LAMBDAS" "DTS": a run per lambda and dt; one the
# simulator stops as unstable (dpd_run fails) is a gap in the ladder
declare -A unstable=()
ladder_simulations() {
    local fluid=$1 scene=$2 box=$3 trun=$4 lambdas=$5 dts=$6 k=0 name l dt
    for l in $lambdas; do for dt in $dts; do
        name=${fluid}_l${l}_dt$dt
        k=$((k + 1))
        dpd_run $name $scene --set "box=[$box.0,$box.0,$box.0]" --set lambda=$l --set dt=$dt \
            --set equilibration=$(nsteps $T_EQ $dt) --set steps=$(nsteps $trun $dt) \
            --set measure.every=$("$ANALYSE" sample-every 0.05 $dt) --set seed=$((7000 + k - 1)) ||
            unstable[$name]=1
    done; done
}
simulations() {
ladder_simulations gw gw-fluid.cfg $GW_BOX $GW_T "0.5 0.65" "$GW_DTS"
ladder_simulations maiduy maiduy-solvent.cfg $MD_BOX $MD_T "0.5 0.65" "$MD_DTS"
ladder_simulations pan pan-fluid.cfg $PAN_BOX $PAN_T "0.5" "$PAN_DTS"
# 4: the m = 0 Couette channel (fig03's scene) per solver and tolerance
couette=../../phan-thien-2016/fig03-couette-profile/couette.cfg
for solver in pcg scheme2_consistent; do
    for tol in ${OD_TOLS[$solver]}; do
        dpd_run ${solver}_$tol $couette --set equilibration=$OD_EQ --set steps=$OD_STEPS --set measure.blocks=10 \
            --set measure.profile.per_block=true --set "overdamped.solver=\"$solver\"" --set overdamped.tolerance=$tol --set overdamped.reference_tolerance=1e-10
    done
done
}

analysis() {
# ---- the analysis. 1-3: temperature against dt --------------------------------
printf 'fluid\tlambda\tdt\tT\tT_se\tT_rot\tT_rot_se\tcpu_seconds\tcost\n' > "$OUT/ladder-dt.tsv"
# ladder_analysis FLUID T_RUN "LAMBDAS" "DTS": cost = CPU seconds per 1000 particles per time unit
ladder_analysis() {
    local fluid=$1 trun=$2 lambdas=$3 dts=$4 name l dt T Tr cpu np
    for l in $lambdas; do for dt in $dts; do
        name=${fluid}_l${l}_dt$dt
        if [ -n "${unstable[$name]:-}" ]; then
            echo "$name: unstable (dpd exited non-zero); a gap in the ladder" >&2
            printf '%s\t%s\t%s\tnan\tnan\tnan\tnan\tnan\tnan\n' $fluid $l $dt >> "$OUT/ladder-dt.tsv"
            continue
        fi
        T=$(get $name temperature) cpu=$(getv $name cpu_seconds) np=$(getv $name particles)
        Tr=$(get $name rotational_temperature 2>/dev/null || printf 'nan\tnan')
        emit_from $name temperature T_${name}
        [ "${Tr%%	*}" = nan ] || emit_from $name rotational_temperature T_rot_${name}
        printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' $fluid $l $dt "$T" "$Tr" $cpu \
            $("$ANALYSE" cost-per-kilo $cpu $np $((trun + T_EQ))) >> "$OUT/ladder-dt.tsv"
    done; done
}
ladder_analysis gw $GW_T "0.5 0.65" "$GW_DTS"
ladder_analysis maiduy $MD_T "0.5 0.65" "$MD_DTS"
ladder_analysis pan $PAN_T "0.5" "$PAN_DTS"
# cost_per_dt: the CPU cost per particle-step of each fluid averaged over its ladder (one run's
# CPU time is noisy on a shared machine), times the steps per time unit 1/dt: CPU seconds per
# 1000 particles per time unit
"$ANALYSE" ladder-cost-per-dt "$OUT/ladder-dt.tsv" > "$OUT/ladder-dt.tmp"
mv "$OUT/ladder-dt.tmp" "$OUT/ladder-dt.tsv"

# Groot-Warren fluid, lambda = 0.5: (a) weighted fit T = T0 + c1 dt + c2 dt^2 (FDT: T0 = kBT);
# (b) the order p of the error, weighted straight line through log |T - 1| against log dt
# (points whose error exceeds 2 stderr); (c) |T - 1| at lambda 0.65 over that at 0.5, largest dt.
"$ANALYSE" gw-temperature-ladder "$OUT/ladder-dt.tsv" 0.06 >> "$OUT/summary.tsv"
# largest dt of each temperature ladder with |T - 1| <= 1 % (2 stderr allowed), and the next rung up
"$ANALYSE" dt-within-1pct "$OUT/ladder-dt.tsv" | sort >> "$OUT/summary.tsv"

# ---- 4: the m = 0 Couette viscosity against the solver tolerance -------------
ref=$(upstream phan-thien-2016/fig03-couette-profile@paper)/summary.tsv
read -r eta_ref eta_ref_se < <("$ANALYSE" lookup "$ref" eta)
printf 'solver\ttolerance\teta\teta_se\terror\terror_se\titerations\tcpu_per_step\ttrue_rel_error\n' > "$OUT/ladder-tolerance.tsv"
for solver in pcg scheme2_consistent; do
    for tol in ${OD_TOLS[$solver]}; do
        name=${solver}_$tol
        # viscosity from the wall shear stress over the bulk shear rate (as fig03)
        read -r _ _ _ _ eta etase < <(couette_viscosity $name 10 2:10)
        emit eta_${name} $eta $etase
        printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' $solver $tol $eta $etase \
            "$("$ANALYSE" rel-error $eta $etase $eta_ref $eta_ref_se)" \
            "$(getv $name solver_iterations)" "$(getv $name solver_cpu_seconds_per_step)" \
            "$(getv $name solver_true_rel_error)" >> "$OUT/ladder-tolerance.tsv"
    done
done
emit eta_fig03_paper_tier $eta_ref $eta_ref_se
# the paper's tolerance (1e-7, PCG) against the fig03 paper tier: the same setting, shorter
# and what the paper's tolerance costs against a loose one (paper.md): PCG's CPU per step at 1e-7 over
# 1e-3 (one run each; no error)
"$ANALYSE" tolerance-summary "$OUT/ladder-tolerance.tsv" >> "$OUT/summary.tsv"
# slope of log(true error) against log(tolerance), per solver (weighted equally)
"$ANALYSE" true-error-slopes "$OUT/ladder-tolerance.tsv" | sort >> "$OUT/summary.tsv"
# what paper.md says in words (issue 40 item 7): Mai-Duy's fluid's step within 1 % over the step 0.01
"$ANALYSE" div "$(get . dt_T1pct_maiduy_l0.5)" 0.01 dt_T1pct_maiduy_l0.5_over_0.01 >> "$OUT/summary.tsv"
# (CPU of every run, the unstable ones included: tools/run-experiment sums runs/*/.cpu_seconds)
}
experiment
