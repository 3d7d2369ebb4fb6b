# analysis.sh - sourced by run.sh after its simulations (exp.sh's functions and run.sh's settings).
PI=3.141592653589793
FEXT=5.631                       # pan-2008/fig02's F_ext = N_f g = 3000 x 0.001877
up() { upstream "pan-2008/$1@$2"; }
FV=$(up fluid-viscosity paper) EQ16=$(up eq16-effective-radius reduced) F01=$(up fig01-torque-calibration reduced)
F02=$(up fig02-drag-calibration reduced) T01=$(up tab01-couette-torque reduced) T02=$(up tab02-poiseuille reduced)
T03=$(up tab03-two-spheres reduced) F03=$(up fig03-chain-rotation reduced)
# the best committed tier of each (paper where committed, else reduced): what ours-against-Pan's and
# Table 3's 30^3 rows read, as the precision tables do (claim-runs.tsv, entries.tsv); the estimator
# rows and ladders below keep the reduced runs they name
best() { local d; d=$(upstream_if "pan-2008/$1@paper") || return 1; [ -n "$d" ] && echo "$d" || up "$1" reduced; }
B_EQ16=$(best eq16-effective-radius) B_F01=$(best fig01-torque-calibration) B_F02=$(best fig02-drag-calibration)
B_T01=$(best tab01-couette-torque) B_T02=$(best tab02-poiseuille) B_T03=$(best tab03-two-spheres)
tier_of() { basename "$1"; }
# sget DIR QUANTITY -> "value<TAB>stderr" of a summary (an upstream result's or one of its runs')
sget() { tsv_lookup "$1/summary.tsv" "$2" pan-estimators; }
# speed factor of the committed pan-2008 runs (made by binaries of b789431's speed; tools/cost's class
# factor for these scenes) and of this experiment's own runs (the current binary: 1)
OLD=$(tsv_lookup "$DPD_ROOT/bench/speedup.tsv" rotation-generic pan-estimators | cut -f1)
# prod_time NAME -> production time units of one of this experiment's runs (dt = 0.01): the summary's
# steps less the equilibration of its arguments, else of its scene (no simulator call: verification)
prod_time() {
    local a=$OUT/runs/$1/.args sc
    sc=$(head -1 "$a" | sed -E "s#^/([^/]+/)*experiments/#$DPD_ROOT/experiments/#"); case $sc in /*) ;; *) sc=$HERE/$sc ;; esac
    "$ANALYSE" prod-time "$(getv "$1" steps)" "$a" "$sc"
}
# column_mean_se FILE COLUMN -> "mean<TAB>stderr" over the rows after the header (blocks)
column_mean_se() { "$ANALYSE" column-mean "$1" $2; }
# cpu_h NAME -> the run's CPU hours (this binary)
cpu_h() { "$ANALYSE" quotient6 "$(getv "$1" cpu_seconds)" 3600; }

# ------------------------------------------------------------------ 1. the precision each claim needs
DPD_ROOT=$DPD_ROOT "$HERE/precision.sh" "$HERE/claim-runs.tsv" > "$OUT/precision.tsv"
"$ANALYSE" precision-totals "$OUT/precision.tsv" >> "$OUT/summary.tsv"
# Pan's 0.5 % (item 5): the plain average's CPU-hours for a stderr of 0.5 % of every number the paper
# prints from a simulation (entries.tsv), in the paper's box at the paper's drive; totals per source
PRECISION_REL=0.005 DPD_ROOT=$DPD_ROOT "$HERE/precision.sh" "$HERE/entries.tsv" > "$OUT/half_percent.tsv"
"$ANALYSE" half-percent-totals "$OUT/half_percent.tsv" >> "$OUT/summary.tsv"
# the entries that dominate it (paper.md names them): Table 3's torques and Table 2's row-1 torque, the
# CPU-hours at the paper's values (a projection: no stderr)
for q in tab03-two-spheres:torque_row1 tab03-two-spheres:torque_row2 tab03-two-spheres:torque_row3 tab02-poiseuille:torque_row1; do
    e=pan-2008/${q%%:*} n=${q#*:}
    t=$(awk -F'\t' -v e=$e '$1 == e { print $2; exit }' "$HERE/entries.tsv")   # (its committed tier)
    emit "half_percent_cpu_hours_${q%%-*}_$n" "$("$ANALYSE" cols-where "$OUT/half_percent.tsv" 1=$e@$t,2=$n 13)" 0
done

# ------------------------------------------------------------------ 2a. the rotation ladder (stronger drive)
# torque over eq. 18 at each Omega, the noise (variance of the mean x production time), the relative
# variance x CPU-hour (the figure of merit: lower is better), and the ratios between drives
printf 'omega\ttorque\ttorque_se\tratio_eq18\tratio_se\tnoise\tcpu_h\trel_var_cpu_h\n' > "$OUT/ladder.tsv"
for w in $LADDER; do
    W=${w%%:*} n=rot_W${w%%:*}
    "$ANALYSE" ladder-row $W "$(get $n torque_on_colloid_z)" "$(prod_time $n)" "$(cpu_h $n)" $MU $R >> "$OUT/ladder.tsv"
    "$ANALYSE" ladder-rows "$OUT/ladder.tsv" $W >> "$OUT/summary.tsv"
done
# the plain average at the paper's Omega = -0.4 (fig01's committed 1500 time units) for comparison
emit plain_torque_ratio_W-0.4 $(sget "$F01" torque_ratio_gS5.5)
# linearity: the torque per unit Omega of each drive over that of the next weaker one
ws=($(for w in $LADDER; do echo ${w%%:*}; done | sort -g -r))   # -1.0 -2.0 -4.0 (weakest first)
prev=-0.4 prevv=$(sget "$F01" torque_ratio_gS5.5)
for W in "${ws[@]}"; do
    cur=$(get . ladder_torque_ratio_W$W)
    emit "ladder_linearity_W${W}_vs_W$prev" "$("$ANALYSE" ratio "$cur" "$prevv")"
    prev=$W prevv=$cur
done

# ------------------------------------------------------------------ 2b. the held mean velocity (Figs 1-2's sphere)
# drag coefficient zeta = drag / u, over Stokes 6 pi mu R (paper's mu, R) and over Hasimoto's simple
# cubic array (Sangani & Acrivos 1982's coefficients, fig02 README): K(phi) = 1 / (1 - 1.7601 phi^(1/3)
# + phi - 1.5593 phi^2), phi = (4/3) pi R^3 / L^3; u at fig02's F_ext from zeta, and Hasimoto's u there;
# the Einstein (Green-Kubo) form of the total force's fluctuations, var x T / (2 kBT), against zeta
printf 'L\tu\tzeta\tzeta_se\tK_measured\tK_se\tK_hasimoto\tK_over_hasimoto\tK_over_hasimoto_se\tu_at_Fext\tu_at_Fext_se\tu_hasimoto_at_Fext\tnoise_drag\tnoise_total\tzeta_einstein\tcpu_h\n' > "$OUT/hold.tsv"
for h in $HOLD; do
    IFS=: read -r Lb u n <<< "$h"; nm=hold_L${Lb}_u$u
    "$ANALYSE" hold-row $Lb $u "$(get $nm drag_on_colloid_x)" "$(get $nm force_on_colloid_x)" "$(prod_time $nm)" "$(cpu_h $nm)" \
        $MU $R $FEXT >> "$OUT/hold.tsv"
    "$ANALYSE" hold-rows "$OUT/hold.tsv" $Lb $u >> "$OUT/summary.tsv"
done
# the box test: zeta(6) / zeta(10) against Hasimoto's K(6) / K(10); linearity: zeta at u = 0.15 / at 0.3 (L = 6)
zrow() { "$ANALYSE" hold-cols "$OUT/hold.tsv" $1 $2 3 4 7; }
if [ -n "$(zrow 10 0.3)" ] && [ -n "$(zrow 6 0.3)" ]; then
"$ANALYSE" hold-ratio "$OUT/hold.tsv" 6 0.3 10 0.3 zeta_L6_over_L10 hasimoto_L6_over_L10 >> "$OUT/summary.tsv"
    # the body-force plain average (fig02, 3000 time units) against the held-u estimate in the same box
    emit u_bodyforce_minus_held_L10 "$("$ANALYSE" diff "$(sget "$F02" u_gC3.5)" "$(get . u_at_fext_L10_u0.3)")"
fi
if [ -n "$(zrow 6 0.15)" ] && [ -n "$(zrow 6 0.3)" ]; then
"$ANALYSE" hold-ratio "$OUT/hold.tsv" 6 0.15 6 0.3 zeta_L6_u0.15_over_u0.3 >> "$OUT/summary.tsv"
fi

# ------------------------------------------------------------------ 2c. the twins (correlated sampling)
# per window of 5 steps (0.05 time units) after the branch, over the seeds: the response (driven minus
# undriven; its stderr from the seeds' scatter), the rms of the tiny twin's difference and of the full
# twin's difference about the response, both over sqrt(2) x the rms of one run's window means (1:
# independent, 0: identical); the Lyapunov rate from the tiny twin's growth; the twin estimator (the
# difference averaged over [t1, t2] after the branch) against the plain average per unit of simulated
# time (each branch costs 2 t2: a driven and an undriven run, equilibration not counted)
# twins KIND SERIES BASE DRIVE TINY STEADY PLAIN_NOISE: twin_KIND.tsv and the summary rows twin_KIND_*
twins() {
    local kind=$1 ser=$2 b=$3 d=$4 t=$5 steady=$6 plain=$7 s files=""
    for s in $SEEDS; do
        files="$files $OUT/runs/twin_${kind}_s${s}_$b/$ser.windows $OUT/runs/twin_${kind}_s${s}_$d/$ser.windows $OUT/runs/twin_${kind}_s${s}_$t/$ser.windows"
    done
    # shellcheck disable=SC2086
    "$ANALYSE" twins "$kind" "$steady" "$plain" "$OUT/twin_$kind.tsv" $files >> "$OUT/summary.tsv"
}
# the steady responses and the plain averages' noise (variance x time) they are compared with: drag at
# V = 0.3 from the held u = 0.3 in the same 10^3 box (opposite sign: the sphere moves through the fluid),
# torque at Omega = -0.4 from the ladder's weakest drive (scaled by Omega; gamma^C_cf does not enter, Fig. 1)
sd=""; pd=""
if [ -n "$(zrow 10 0.3)" ]; then
    sd=$("$ANALYSE" scale "$(get hold_L10_u0.3 drag_on_colloid_x)" -1 | cut -f1)
    pd=$("$ANALYSE" hold-cols "$OUT/hold.tsv" 10 0.3 13)
fi
twins drag drag_on_colloid_x V0.0 V0.3 V0.003 "$sd" "$pd"
wk=${ws[0]}
sr=$("$ANALYSE" ladder-steady "$OUT/ladder.tsv" $wk)
pr=$("$ANALYSE" ladder-cols "$OUT/ladder.tsv" $wk 6)
twins rot torque_on_colloid_z W0.0 W-0.4 W-0.004 "$sr" "$pr"

# ------------------------------------------------------------------ 2d. Green-Kubo for the rotational friction
# tab01's control-variate diagnostic (seven frozen spheres at rest, 504 run means of 10 time units): the
# total torque's variance x time over 2 kBT is the rotational friction (Einstein form of Green-Kubo);
# against fig01's driven friction (torque / Omega at -0.4) and the ladder's
"$ANALYSE" gk-rotational-friction "$(sget "$T01" cv_noise_total)" $MU $R >> "$OUT/summary.tsv"

# ------------------------------------------------------------------ 3. Table 3's pair in two boxes
# drag per sphere over eq. 23 at the same u, against the leading periodic-array correction for two
# spheres per cell, 1 / (1 - 2 x 2.837297 R / L) (the partner's images and the sphere's own, each
# -2.837297 F / (6 pi mu L) at the sphere: the Yeh-Hummer / Hasimoto constant), in 12^3 (this
# experiment, l = 1, u = 0.3) and 30^3 (tab03's committed rows, its best tier)
eq23F() { "$ANALYSE" two-sphere-theory $1 $2 $MU $R | cut -d' ' -f1; }
lattice2() { "$ANALYSE" pair-periodic-factor $1 $R; }
printf 'L\tl\tu\tdrag\tdrag_se\tdrag_over_eq23\tse\tperiodic_prediction\tover_prediction\tse\tpan_over_eq23\n' > "$OUT/pair_boxes.tsv"
pan_F() { case $1 in 2.0) echo 4.861;; 1.5) echo 4.857;; 1.0) echo 4.863;; esac; }
for r in 1 2 3; do
    l=$(case $r in 1) echo 2.0;; 2) echo 1.5;; 3) echo 1.0;; esac)
    "$ANALYSE" pair-box-row 30 $l 0.3 "$(sget "$B_T03" drag_row$r)" $(eq23F $l 0.3) $(lattice2 30) $(pan_F $l) >> "$OUT/pair_boxes.tsv"
done
for p in $PAIR12; do
    u=${p%%:*}
    F=$(column_mean_se "$OUT/runs/pair12_u$u/sphere_blocks.tsv" 2)
    "$ANALYSE" pair-box-row 12 1.0 $u "$F" $(eq23F 1.0 $u) $(lattice2 12) $(pan_F 1.0) >> "$OUT/pair_boxes.tsv"
    emit "pair12_drag_over_eq23_u$u" $("$ANALYSE" cols-where "$OUT/pair_boxes.tsv" 1=12,3=$u 6 7)
    emit "pair12_drag_over_periodic_u$u" $("$ANALYSE" cols-where "$OUT/pair_boxes.tsv" 1=12,3=$u 9 10)
    emit "pair12_torque_u$u" $(column_mean_se "$OUT/runs/pair12_u$u/sphere_blocks.tsv" 3)
    # the box ratio: l = 1's drag per sphere in 12^3 over 30^3, both at u = 0.3, against the prediction
    emit pair_drag_L12_over_L30 "$("$ANALYSE" ratio "$("$ANALYSE" cols-where "$OUT/pair_boxes.tsv" 1=12,3=$u 4 5)" "$(sget "$B_T03" drag_row3)")"
    "$ANALYSE" periodic-ratio-row $(lattice2 12) $(lattice2 30) >> "$OUT/summary.tsv"
done
"$ANALYSE" pair30-rows "$OUT/pair_boxes.tsv" >> "$OUT/summary.tsv"

# ------------------------------------------------------------------ 3b. torque over drag, box by box
# The periodic images change the flow a sphere of the pair sees by a uniform backflow at leading
# order (the regular part of the periodic Stokeslet at the pair, -2.837297 F / (6 pi mu L) per force
# in the cell), which raises drag and torque in the same proportion; the torque's own image terms
# come from the images' velocity gradients, of relative order (l / L)^3. So T / F would not depend
# on the box, and Table 3's torque in 30^3 would be (T / F) from a small box times the 30^3 drag,
# at a fraction of the cost. Tested: l = 1, u = 0.6 in 8^3 and 12^3 (12^3: this experiment's run and
# the committed ladder's u = 0.6 run, weighted by their errors); 30^3 at u = 0.3 (tab03 row 3, its best
# tier's runs).
tf() {   # FILE(S) of sphere_blocks -> "T/F<TAB>se<TAB>F<TAB>F_se<TAB>T<TAB>T_se" (runs weighted by their errors)
    "$ANALYSE" torque-over-drag "$@"
}
if [ -n "$PAIRBOX" ]; then
    printf 'L\tu\tT_over_F\tse\tdrag\tdrag_se\ttorque\ttorque_se\tperiodic_prediction_drag\n' > "$OUT/torque_over_drag.tsv"
    tf8=$(tf "$OUT/runs/pairbox_L8_u0.6/sphere_blocks.tsv")
    tf12=$(tf "$OUT/runs/pairbox_L12_u0.6/sphere_blocks.tsv" "$T03"/runs/lr_u0.6*/sphere_blocks.tsv)   # (the ladder's replicas too)
    tf30=$(tf "$B_T03"/runs/row3*/sphere_blocks.tsv)   # (the paper tier: row 3's three replicas)
    printf '8\t0.6\t%s\t%s\n12\t0.6\t%s\t%s\n30\t0.3\t%s\t%s\n' "$tf8" $(lattice2 8) "$tf12" $(lattice2 12) "$tf30" $(lattice2 30) >> "$OUT/torque_over_drag.tsv"
    emit tf_L8_u0.6 $(echo "$tf8" | cut -f1,2)
    emit tf_L12_u0.6 $(echo "$tf12" | cut -f1,2)
    emit tf_L30_u0.3 $(echo "$tf30" | cut -f1,2)
"$ANALYSE" tf-ratios "$tf8" "$tf12" $(lattice2 8) $(lattice2 12) >> "$OUT/summary.tsv"
    # Table 3's row 3 torque in 30^3 from (T / F) of 12^3 times the 30^3 drag (u = 0.3; the ratio is
    # linear in u within the ladder's 6 %), over eq. 23, beside the plain 30^3 average
    T23=$("$ANALYSE" two-sphere-theory 1.0 0.3 $MU $R | cut -d' ' -f2)
    "$ANALYSE" tf-torque "$tf12" "$(sget "$B_T03" drag_row3)" $T23 >> "$OUT/summary.tsv"
fi

# ------------------------------------------------------------------ 4. ours against Pan's simulated values
# every number the paper prints from its simulations, ours beside it (each experiment's best committed
# tier, named in the first column), the ratio
# and the difference in our stderrs; and each against its theory, ours and Pan's
pan_compare() {
    printf 'experiment\trow\tquantity\tpan_sim\tours\tours_se\tours_over_pan\tse\tsigmas\tpan_over_theory\tours_over_theory\tse\n'
    # row DIR QUANTITY PAN PAN_THEORY OURS_RATIO_QUANTITY (the ratio of ours to our own theory value)
    # (PAN_THEORY and OURS_RATIO_QUANTITY "-": no theory value); the experiment is labelled with its tier
    row() { local d=$1 q=$2 p=$3 pt=$4 rq=$5 lab=$6 rr="-	-"
        [ "$rq" = - ] || rr=$(sget "$d" "$rq")
        "$ANALYSE" pan-compare-row "${lab/	/ ($(tier_of "$d"))	}" $q $p $pt "$(sget "$d" "$q")" "$rr"; }
    # fig01 at Pan's Omega = -0.4: the paper tier's own run there (its banded ratio is at Omega = -2)
    local w=torque_ratio_gS5.5; [ "$(tier_of "$B_F01")" = paper ] && w=torque_ratio_gS5.5_W-0.4
    row "$B_F01" $w 1.013 1 $w "fig01	Omega -0.4"
    row "$B_F02" u_gC3.5 0.2986 - u_ratio_eq19_gC3.5 "fig02	gC 3.5"
    row "$B_EQ16" D_colloid 0.0533 - - "eq16	10^3"
    row "$B_EQ16" D_colloid_extrapolated 0.0533 - - "eq16	1/L -> 0"
    local i
    for i in 1 2 3 4; do
        row "$B_T01" torque_row$i $(echo "0.3675 0.7540 0.7289 1.0659" | cut -d' ' -f$i) $(echo "0.3750 0.7500 0.7500 1.1251" | cut -d' ' -f$i) torque_ratio_row$i "tab01	$i"
    done
    for i in 1 2 3; do
        row "$B_T02" drag_row$i $(echo "4.4881 9.689 18.881" | cut -d' ' -f$i) $(echo "5.114 10.230 20.463" | cut -d' ' -f$i) drag_ratio_row$i "tab02	$i"
        row "$B_T02" torque_row$i $(echo "0.0838 0.163 0.313" | cut -d' ' -f$i) $(echo "0.0786 0.157 0.315" | cut -d' ' -f$i) torque_ratio_row$i "tab02	$i"
    done
    for i in 1 2 3; do
        row "$B_T03" drag_row$i $(echo "4.861 4.857 4.863" | cut -d' ' -f$i) $(echo "5.100 5.089 5.185" | cut -d' ' -f$i) drag_ratio_row$i "tab03	$i"
        row "$B_T03" torque_row$i $(echo "0.0253 0.0451 0.113" | cut -d' ' -f$i) $(echo "0.0261 0.0463 0.106" | cut -d' ' -f$i) torque_ratio_row$i "tab03	$i"
    done
}
pan_compare > "$OUT/pan_compare.tsv"

# ------------------------------------------------------------------ 5. variance per CPU-hour, by estimator
# The figure of merit of an estimator: relative variance x CPU-hours, r = (se / value)^2 x CPU_h; it
# needs r / 1e-4 CPU-hours for a relative stderr of 1 %; gain = r of the plain average over its r.
# CPU of the committed pan-2008 runs is scaled to this binary (class rotation-generic of
# bench/speedup.tsv, $OLD, as tools/cost does); this experiment's runs are this binary's.
# est_row QUANTITY ESTIMATOR SETUP VALUE SE CPU_H CHECK KEPT
est_row() {
    "$ANALYSE" est-row "$@"
}
rcpu() { "$ANALYSE" rcpu "$1" ${2:-1}; }
pair() { printf '%s %s' "$(echo "$1" | cut -f1)" "$(echo "$1" | cut -f2)"; }
{
printf 'quantity\testimator\tsetup\tvalue\tse\tcpu_h\trel_var_cpu_h\tcpu_h_for_1pct\tcheck\tkept\n'
# A. the rotational friction of Figs 1 and 3 (torque at a prescribed spin)
est_row "fig01 torque" "plain average, Omega = -0.4" "10^3, one sphere, 1500 t.u. (fig01 reduced)" \
    $(pair "$(sget "$F01/runs/gC0.0_gS5.5" torque_on_colloid_z)") $(rcpu "$F01/runs/gC0.0_gS5.5/summary.tsv" $OLD) "the paper's drive" reference
prev=-0.4
for W in "${ws[@]}"; do
    est_row "fig01 torque" "stronger drive, Omega = $W" "10^3, one sphere (this experiment)" \
        $("$ANALYSE" ladder-cols "$OUT/ladder.tsv" $W 2 3 7) \
        "torque per Omega over Omega = $prev: $("$ANALYSE" fmt "%.4f +- %.4f" "$(get . ladder_linearity_W${W}_vs_W$prev)")" \
        "kept where linear"
    prev=$W
done
read -r v se < <("$ANALYSE" half-pair "$(sget "$T01" cv_noise_total)")
est_row "fig01 torque" "Green-Kubo (Einstein form): total torque's variance x time / 2 kBT" "10^3, seven spheres at rest, 3 components, $(ls -d "$T01"/runs/cv* | wc -l) x 10 t.u. (tab01 cv runs)" \
    $v $se $(cat "$T01"/runs/cv*/summary.tsv | rcpu /dev/stdin $OLD) \
    "friction over eq. 18: $("$ANALYSE" fmt "%.3f +- %.3f" "$(get . gk_rotational_friction_over_eq18)") (driven, Omega = -0.4: $("$ANALYSE" fmt "%.3f +- %.3f" "$(sget "$F01" torque_ratio_gS5.5)"))" no
vr=$(getv . twin_rot_variance_ratio_0.25_0.5)
plain_r=$("$ANALYSE" ladder-cols "$OUT/ladder.tsv" ${ws[0]} 6)   # noise x time, Omega-independent
echo "fig01 torque	twins: driven minus undriven over [0.25, 0.5] t.u. after the branch	10^3, $(echo $SEEDS | wc -w) pairs (this experiment)	-	-	-	-	-	variance x simulated time $(printf '%.3g' $vr) of the plain average's (2 branches of 0.5 t.u., no equilibration counted); response over steady $("$ANALYSE" fmt "%+.3f +- %.3f" "$(get . twin_rot_bias_0.25_0.5)"): bias unresolved at 8 %	no"
# B. the drag of a fixed sphere (Figs 1-2's colloid, gamma^C_cf = 3.5) in the 10^3 box
if [ -n "$(zrow 10 0.3)" ]; then
    est_row "fig02 drag (u at F_ext)" "plain average, body force (u from the fluid's mean velocity)" "10^3, 3000 t.u. (fig02 reduced, Ornstein-Uhlenbeck error)" \
        $(pair "$(sget "$F02" u_gC3.5)") $(rcpu "$F02/runs/gC3.5/summary.tsv" $OLD) "the paper's drive" reference
    est_row "fig02 drag (u at F_ext)" "held mean velocity u = 0.3, u = F_ext / zeta" "10^3, 12000 t.u. (this experiment)" \
        $(pair "$(get . u_at_fext_L10_u0.3)") $(rcpu "$OUT/runs/hold_L10_u0.3/summary.tsv") \
        "body force minus held: $("$ANALYSE" fmt "%.4f +- %.4f" "$(get . u_bodyforce_minus_held_L10)")" "kept (no start-up, no slow mode)"
    est_row "fig02 drag (u at F_ext)" "Green-Kubo (Einstein form): total force's variance x time / 2 kBT" "10^3, u = 0.3 held (this experiment)" \
        $("$ANALYSE" with-variance-se "$("$ANALYSE" hold-cols "$OUT/hold.tsv" 10 0.3 15)" 49) $(rcpu "$OUT/runs/hold_L10_u0.3/summary.tsv") \
        "zeta from it $("$ANALYSE" fmt %.1f "$("$ANALYSE" hold-cols "$OUT/hold.tsv" 10 0.3 15)") against the driven $("$ANALYSE" fmt %.2f "$("$ANALYSE" hold-cols "$OUT/hold.tsv" 10 0.3 3)"): the held momentum changes the ensemble" no
    vr=$(getv . twin_drag_variance_ratio_0.25_0.5)
    echo "fig02 drag (u at F_ext)	twins: sphere moving at 0.3 minus at rest over [0.25, 0.5] t.u. after the branch	10^3, $(echo $SEEDS | wc -w) pairs (this experiment)	-	-	-	-	-	variance x simulated time $(printf '%.3g' $vr) of the plain average's; response over steady $("$ANALYSE" fmt "%+.3f +- %.3f" "$(get . twin_drag_bias_0.25_0.5)") (Basset's transient R / sqrt(pi nu t) is +23 % at 0.375 t.u. in a continuum)	no"
fi
# C. Table 3's torque, l = 1, 30^3: the plain average at u = 0.3 and the same noise at a stronger drive
# (projected: the 30^3 row's noise x time, its torque scaled linearly in u, its cost per time unit)
read -r T Tse < <(sget "$T03" torque_row3 | tr '\t' ' ')
c3=$(rcpu "$T03/runs/row3/summary.tsv" $OLD)
est_row "tab03 torque l = 1" "plain average, u = 0.3" "30^3, 600 t.u. (tab03 reduced row 3)" $T $Tse $c3 "the paper's drive" reference
for u in 0.6 1.2; do
    "$ANALYSE" drive-projection $T $Tse $u $c3 | {
        read -r Tu seu cu
        est_row "tab03 torque l = 1" "stronger drive, u = $u (projected)" "30^3, the row's noise and cost per t.u." $Tu $seu $cu \
            "12^3 ladder: torque per u at 1.2 over 0.6 $("$ANALYSE" fmt "%.3f +- %.3f" "$(sget "$T03" lr_torque_per_u_1.2_vs_0.6)"), at 2.4 over 1.2 $("$ANALYSE" fmt "%.3f +- %.3f" "$(sget "$T03" lr_torque_per_u_2.4_vs_1.2)"); drag per u 1.2 over 0.6 $("$ANALYSE" fmt "%.4f +- %.4f" "$(sget "$T03" lr_drag_per_u_1.2_vs_0.6)")" \
            "$( [ $u = 0.6 ] && echo 'no: linearity not shown at the precision of Table 3 (its paper tier runs at u = 0.3); used by the reduced tier projection only' || echo 'no: linearity not shown at 2 %')"; }
done
# D. D of eq. 16: one 10^3 box with 27 colloids against the 1/L extrapolation of three boxes
est_row "eq16 D" "plain MSD, one box" "10^3, 27 colloids, 400 t.u. (eq16 reduced)" $(pair "$(sget "$EQ16" D_colloid)") \
    $(rcpu "$EQ16/runs/diff/summary.tsv" $OLD) "finite-size biased (Yeh-Hummer -8 %)" reference
est_row "eq16 D" "1/L extrapolation of three boxes" "6, 8, 12, 12000 / 3000 / 2000 t.u. (eq16 reduced)" $(pair "$(sget "$EQ16" D_colloid_extrapolated)") \
    $(cat "$EQ16"/runs/box_L*/summary.tsv | rcpu /dev/stdin $OLD) "chi^2/dof $(sget "$EQ16" fit_chi2_dof | cut -f1 | xargs printf '%.1f') (errors scaled by its root)" "kept, with replicas per box"
# E. the random part as a control variate (tab01's diagnostic, seven spheres at rest, every step sampled)
echo "fig01 torque	control variate: D + c R (R the torque's zero-mean random part)	10^3, seven spheres at rest (tab01 cv runs)	-	-	-	-	-	variance factor at the best c $("$ANALYSE" fmt "%.3f +- %.3f" "$(sget "$T01" cv_variance_factor_best)"), only with every step sampled (fig01 README: every 2 steps gives a smaller error per CPU second), and R is not in run.h5	no"
# F. replicas: the same variance per CPU-hour (plus one equilibration each), the wall time divided
echo "every quantity	independent replicas, each with its own equilibration	any	-	-	-	-	-	same variance per CPU-hour (each adds its equilibration: 1-2 % at the paper tier's lengths); wall time / number of replicas	kept (wall time)"
} > "$OUT/estimators.tsv"
