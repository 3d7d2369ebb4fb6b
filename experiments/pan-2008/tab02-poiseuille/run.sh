#!/usr/bin/env bash
# Pan et al. 2008, Table 2: drag and torque on a colloid held fixed at h = 2
# from the lower wall of a body-force-driven Poiseuille channel, against eq. 22
# with u_h measured in the same channel without the colloid.
. "$DPD_ROOT/tools/lib/exp.sh"
MU=3.6388 R=0.2737 H=2.0 ZH=3.0 GREF=0.20   # paper mu and R; sphere at z = 1 + h
case $TIER in
    quick) ROWS="3"; sph=(--set equilibration=2000 --set steps=10000); emp=(--set equilibration=2000 --set steps=4000) ;;
    reduced|paper) ROWS="1 2 3"; sph=(--set measure.blocks=50); emp=() ;;
esac
# Reduced tier (the committed result, README): rows 1, 2, 3 run 21000, 5300 and 1100 time units, the
# lengths at which the torque's stderr is about 10 % of eq. 22 (torque noise variance x run length
# about 1.4 in torque^2 x time, measured at 500 time units). Paper tier (issue 38, README): each row's
# torque to a stderr a third of the paper value's distance to its band's edge (issue 37's rule; the
# reduced rows' noise): 530000, 63000 and 9000 time units, as 20, 3 and 1 independent runs of 26500,
# 21000 and 9000 (no run above about an hour); the drags are then decided too (the empty channel's
# 400 already gives u_h to 0.4 %).
row_steps() { case $TIER in
    reduced) case $1 in 1) echo 2100000;; 2) echo 530000;; 3) echo 110000;; esac;;
    paper) case $1 in 1) echo 2650000;; 2) echo 2100000;; 3) echo 900000;; esac;; esac; }
# the runs of a row: one, or at the paper tier replicas row<r>, row<r>r2, ... (seeds 2200 + r, then
# 2200 + 10 k + r for replica k)
row_reps() { case $TIER:$1 in paper:1) echo 20;; paper:2) echo 3;; *) echo 1;; esac; }
row_runs() { local k; echo row$1; for k in $(seq 2 $(row_reps $1)); do echo row$1r$k; done; }
run_seed() { case $1 in row?r*) echo $((2200 + 10 * ${1##*r} + ${1:3:1}));; *) echo $((2200 + ${1#row}));; esac; }
# mean_runs: the equal-weight mean of "value<TAB>stderr" lines (replicas of equal length), stderr
# sqrt(sum se^2) / n
mean_runs() { "$ANALYSE" mean-runs; }
row_g()     { case $1 in 1) echo 0.05;; 2) echo 0.10;; 3) echo 0.20;; esac; }
paper_F()   { case $1 in 1) echo 4.4881;; 2) echo 9.689;; 3) echo 18.881;; esac; }
paper_T()   { case $1 in 1) echo 0.0838;; 2) echo 0.163;; 3) echo 0.313;; esac; }
# the simulations: the channel without the colloid at g = GREF, then one with it per row
simulations() {
dpd_run empty poiseuille-empty.cfg "${emp[@]}" --set "types.[0].body_force=[$GREF,0.0,0.0]" --set seed=2200 \
    --set measure.profile.per_block=true
for r in $ROWS; do
    len=(); [ -n "$(row_steps $r)" ] && len=(--set "steps=$(row_steps $r)")
    for n in $(row_runs $r); do
        dpd_run $n poiseuille-sphere.cfg "${sph[@]}" "${len[@]}" --set "types.[0].body_force=[$(row_g $r),0.0,0.0]" --set "seed=$(run_seed $n)"
    done
done
}
analysis() {
# the analysis
# undisturbed channel at g = GREF: u at z = 3 (mean of the two 0.25-wide bins either side, per
# block; error from the blocks: the two bins' errors are not independent), scaled linearly to
# each row's g (Stokes flow; the largest g gives the smallest relative error)
cp "$OUT/runs/empty/profile.tsv" "$OUT/profile_empty.tsv"
UREF=$(block_mean empty $("$ANALYSE" bin-window $ZH 0.25))
emit u_h_gref $UREF
printf 'row\tg\tu_h\tu_h_se\tdrag\tdrag_se\tdrag_theory\tdrag_paper\ttorque\ttorque_se\ttorque_theory\ttorque_paper\n' > "$OUT/table2.data.tsv"
printf 'row\tRe (paper)\tu_h\tF paper\tF ours\tF eq. 22\tF verdict@\tT paper\tT ours\tT eq. 22\tT verdict@\n' > "$OUT/table2.tsv"
for r in $ROWS; do
    g=$(row_g $r)
    # (linear response: u_h scales with the force)
    uh=$("$ANALYSE" linear-scale "$UREF" $g $GREF)
    emit "u_h_row$r" $uh
    # eq. 22 (paper mu and R, h = 2 from the reflection plane z = 1)
    read -r Fth Tth < <("$ANALYSE" wall-sphere-theory "$(cut -f1 <<< "$uh")" $MU $R $H)
    # both without the zero-mean random part; replicas: their equal-weight mean
    F=$(for n in $(row_runs $r); do get $n drag_on_colloid_x; done | mean_runs)
    T=$(for n in $(row_runs $r); do get $n torque_on_colloid_y; done | mean_runs)
    emit_drag_torque $r "$F" "$T" "$Fth" "$Tth" "$uh"
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' $r $g "$uh" "$F" $Fth $(paper_F $r) "$T" $Tth $(paper_T $r) >> "$OUT/table2.data.tsv"
    "$ANALYSE" tab02-row $r "$uh" "$F" "$T" $Fth $Tth $(paper_F $r) $(paper_T $r) >> "$OUT/table2.tsv"
done
# linear response (issue 23 item 5; reported, no band: computed after the rows were seen): the torque
# and drag per unit g between successive rows (g doubles), relative errors in quadrature; and the
# torque's noise, variance of the mean x production time (torque^2 x time), its stderr that of a
# variance from 50 blocks per run (49 degrees of freedom per run: the paper tier's replicas pooled)
if [ "$TIER" != quick ]; then
    for p in 1:2 2:3; do
        a=${p%:*} b=${p#*:}
        for q in torque drag; do
            "$ANALYSE" per-unit-ratio "$(get . ${q}_row$a)" $(row_g $a) "$(get . ${q}_row$b)" $(row_g $b) \
                ${q}_per_g_row${b}_vs_row$a >> "$OUT/summary.tsv"
        done
    done
    for r in $ROWS; do
        "$ANALYSE" noise-row torque_noise_row$r "$(get . torque_row$r | cut -f2)" $(( $(row_steps $r) * $(row_reps $r) / 100 )) $(( $(row_reps $r) * 49 )) >> "$OUT/summary.tsv"
    done
    # a second estimator of the stderr of a row with replicas (reported, no band): the mean of its
    # runs' values with the stderr of their scatter, against drag_row* and torque_row*, whose stderr
    # comes from each run's blocks (the same mean)
    for r in $ROWS; do
        [ "$(row_reps $r)" -ge 2 ] || continue
        for q in drag:drag_on_colloid_x torque:torque_on_colloid_y; do
            emit ${q%%:*}_row${r}_by_runs "$(for n in $(row_runs $r); do getv $n ${q#*:}; done | "$ANALYSE" mean-se)"
        done
    done
fi
# how many times its run each row's torque would need for a stderr of 0.5 % of eq. 22 (the paper
# tier's aim, README), (se / 0.005)^2 of torque_ratio_row (the error falling as 1 / sqrt(length)); its
# stderr that of a variance from the row's blocks, sqrt(2 / (runs x 49))
if [ "$TIER" != quick ]; then
    for r in $ROWS; do
        emit torque_ratio_time_factor_half_percent_row$r "$("$ANALYSE" half-percent-time "$(get . torque_ratio_row$r | cut -f2)" - $(( $(row_reps $r) * 49 )))"
    done
fi
# what paper.md says in words (issue 40 item 7): each drag's deviation from eq. 22, and the empty
# channel's u_h against the no-slip parabola g n (z - 1)(9 - z) / (2 mu) at z = 3 (walls at z = 1
# and 9, n = 3, the paper's mu)
for r in $ROWS; do emit_pct drag_ratio_row${r}_pct_from_eq22 "$(get . drag_ratio_row$r)" 1; done
emit_pct u_h_gref_pct_from_no_slip "$(get . u_h_gref)" "$("$ANALYSE" no-slip-poiseuille $GREF $ZH $MU)"
}
experiment
