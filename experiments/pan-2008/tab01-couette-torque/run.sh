#!/usr/bin/env bash
# Pan et al. 2008, Table 1: torque on a fixed colloid spinning at Omega about y
# in Couette flow between walls moving at -v and +v (curl/2 = v / H, H = 8).
. "$DPD_ROOT/tools/lib/exp.sh"
MU=3.6388 R=0.2737     # the paper's mu and R in eq. 21
# Reduced tier (the committed result, README): the torque noise is the same in every row (measured:
# its variance times the run length is about 1.3 in torque^2 x time, correlation time 0.04), so each
# row runs long enough for a stderr of about 6 % of its eq. 21 torque: 2500, 800, 800, 400 time units.
# 50 blocks (25 to 8 time units each, all far longer than the correlation time) estimate the
# stderr to about 10 %, against 16 % with 20.
# Paper tier (issue 38, README): each row long enough to decide its band under issue 37's rule (a
# stderr a third of the paper value's distance to the band's edge, with variance x run length 2.0):
# 34000 (two replicas of 17000), 6000, 9000, 16000 time units.
case $TIER in
    quick) tier=(--set steps=6000); ROWS="1 4" ;;
    reduced|paper) tier=(--set measure.blocks=50); ROWS="1 2 3 4" ;;
esac
tier+=(--set measure.profile.per_block=true)   # the vorticity's error from the blocks (block_slope)
row_steps() { case $TIER in quick) ;;
    reduced) case $1 in 1) echo 250000;; 2|3) echo 80000;; 4) echo 40000;; esac;;
    paper) case $1 in 1) echo 1700000;; 2) echo 600000;; 3) echo 900000;; 4) echo 1600000;; esac;; esac; }
row_omega() { case $1 in 1|2) echo 0.0;; 3|4) echo -0.2;; esac; }
row_curl()  { case $1 in 1|3) echo 0.2;; 2|4) echo 0.4;; esac; }
paper_T()   { case $1 in 1) echo 0.3675;; 2) echo 0.7540;; 3) echo 0.7289;; 4) echo 1.0659;; esac; }
# Replicas (issue 23 item 5): the reduced tier's row 1 (stderr 0.0802 of eq. 21 in 2500 time units,
# UNRESOLVED: 2 stderr just above the band width 0.16) gets one independent replica of the same length
# (seed 9011), decided before it ran: row 1 is the equal-weight mean of the two runs, its expected
# stderr 0.080 / sqrt 2 = 0.057. The torque's noise is thermal and the same in every row (README), so
# a harder drive is the paper's row 2 (curl/2 = 0.4), the linear-response check beside it.
# The paper tier's row 1 (issue 38): its two runs of 17000 time units gave 1.051 +- 0.018 of eq. 21,
# UNRESOLVED (value + 2 stderr past the band's 1.08; make check: 1.52 times the length decides it at
# that value). Two more independent runs of the same length (seeds 9021, 9031), decided on 2026-12-06
# after that result and before these ran (a second look, disclosed in the README and paper.md): four
# runs, twice the length, expected stderr 0.018 / sqrt 2 = 0.0125.
row_runs() { case $TIER:$1 in reduced:1) echo "row1 row1r2";; paper:1) echo "row1 row1r2 row1r3 row1r4";; *) echo "row$1";; esac; }
run_seed() { case $1 in row1r2) echo 9011;; row1r3) echo 9021;; row1r4) echo 9031;; *) echo $((9000 + ${1#row}));; esac; }
# the simulations: one per row (row 1 of the reduced tier: two)
simulations() {
for r in $ROWS; do
    W=$(row_omega $r) C=$(row_curl $r)
    V=$("$ANALYSE" times6 $C 8.0)    # v = (curl/2) H: shear rate 2v/H = 2 curl/2
    len=(); [ -n "$(row_steps $r)" ] && len=(--set "steps=$(row_steps $r)")
    for n in $(row_runs $r); do
        dpd_run $n couette-sphere.cfg "${tier[@]}" "${len[@]}" --set "types.[1].velocity=[-$V,0.0,0.0]" \
            --set "types.[2].velocity=[$V,0.0,0.0]" --set "types.[3].spin=[0.0,$W,0.0]" --set "seed=$(run_seed $n)"
    done
done
# Control-variate diagnostic (reduced tier; issue 23 item 5, README "Where the torque's variance comes
# from"): the torque is reported without its random part R, which has zero mean exactly; the rest, D,
# fluctuates because the neighbours' thermal velocities do. R is a control variate for D only if
# their run means are correlated (D + c R keeps D's mean for any c; variance factor 1 - rho^2 at the
# best c). Measured on seven frozen spheres at rest (random-part-cv.cfg, sampled every step), 24
# independent runs of 3 + 10 time units: the per-run means of D and R of every sphere and component.
# 24 runs until 2026-12-06; then 60 (seeds 9125-9160 added), decided after the rule of 2026-12-05 left
# the gate cv_torque_mean unresolved at 24 (stderr 0.0154 above its resolution 0.0098: 2.5 times the
# runs expected to bring it below) and before the new runs ran: a gate must pass or its tier be fixed.
# The 60 gave a stderr of 0.0100, still above; then 100 (seeds 9161-9200), on the stderr alone (the
# resolution test does not look at the mean)
CV_RUNS=100
if [ "$TIER" = reduced ]; then
    for i in $(seq 1 $CV_RUNS); do dpd_run "cv$(printf %02d $i)" random-part-cv.cfg --set "seed=$((9100 + i))"; done
fi
}
# mean_runs: the equal-weight mean of "value<TAB>stderr" lines (replicas of equal length), stderr
# sqrt(sum se^2) / n
mean_runs() { "$ANALYSE" mean-runs; }
analysis() {
# the analysis
printf 'row\tOmega\tcurl2_nominal\tcurl2_measured\tcurl2_se\ttorque\ttorque_se\ttheory\tpaper\tverdict@\n' > "$OUT/table1.tsv"
for r in $ROWS; do
    W=$(row_omega $r) C=$(row_curl $r)
    # undisturbed vorticity: slope of the plane-averaged v_x(z) over the central 4 rc, fitted per
    # block (the bins of one profile share the flow's fluctuations: not independent)
    c2=$("$ANALYSE" div "$(for n in $(row_runs $r); do block_slope $n 3.0:7.0; done | mean_runs)" 2)
    emit "curl2_row$r" $c2
    T=$(for n in $(row_runs $r); do get $n torque_on_colloid_y; done | mean_runs)
    # each run's own torque, for the replicas' agreement (README)
    [ "$(row_runs $r)" = row$r ] || for n in $(row_runs $r); do emit "torque_run_$n" $(get $n torque_on_colloid_y); done
    emit "torque_row$r" $T
    the=$("$ANALYSE" couette-torque $MU $R "$(cut -f1 <<< "$c2")" $W)
    emit "theory_row$r" "$the" 0
    "$ANALYSE" div "$T" $the torque_ratio_row$r >> "$OUT/summary.tsv"
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\ttorque_ratio_row%s\n' $r $W $C "$c2" "$T" "$the" "$(paper_T $r)" $r >> "$OUT/table1.tsv"
    cp "$OUT/runs/row$r/profile.tsv" "$OUT/profile_row$r.tsv"
done
# linear response (issue 23 item 5; reported, no band: computed after the rows were seen): the torque
# per unit drive (curl/2 - Omega, measured curl/2) of the harder-driven row over the softer one's, at
# Omega = 0 (row 2 over row 1: the drive doubled) and at Omega = -0.2 (row 4 over row 3: x 1.5);
# relative errors of the torques in quadrature (the curl/2 errors are 0.1-0.2 %)
if [ "$TIER" != quick ]; then
    for p in 1:2 3:4; do
        a=${p%:*} b=${p#*:}
        "$ANALYSE" per-drive-ratio "$(get . torque_row$a)" "$(get . curl2_row$a)" $(row_omega $a) \
            "$(get . torque_row$b)" "$(get . curl2_row$b)" $(row_omega $b) torque_per_drive_row${b}_vs_row$a >> "$OUT/summary.tsv"
    done
fi
# the control-variate diagnostic: one "D R" line per run, sphere and component; the intensities
# (variance of a run mean x its 10 time units) of D, R and D + R, their correlation rho, and the
# variance factor 1 - rho^2 of the best D + c R (stderrs: a variance's sqrt(2 / (n - 1)), and
# (1 - rho^2) / sqrt(n - 3) for rho)
if [ "$TIER" = reduced ]; then
    cvs=(); for i in $(seq 1 $CV_RUNS); do cvs+=("$OUT/runs/cv$(printf %02d $i)/summary.tsv"); done
    "$ANALYSE" cv-pairs "${cvs[@]}" > "$OUT/random_part_cv.tsv"
    "$ANALYSE" control-variate "$OUT/random_part_cv.tsv" >> "$OUT/summary.tsv"
fi
# the torque's noise per row (reduced and paper tiers, 50 blocks per run): variance of the row's mean x
# its production time (torque^2 x time, all its runs; dt = 0.01, couette-sphere.cfg), the number that
# sets each row's run length (README); its stderr that of a variance from the runs' blocks,
# sqrt(2 / (runs x 49))
if [ "$TIER" != quick ]; then
    for r in $ROWS; do
        k=$(row_runs $r | wc -w)
        "$ANALYSE" noise-row torque_noise_row$r "$(get . torque_row$r | cut -f2)" $(( $(row_steps $r) * k / 100 )) $((k * 49)) >> "$OUT/summary.tsv"
    done
fi
# what paper.md says in words (issue 40 item 7): each row's measured curl/2 against its nominal drive,
# and the control variate's total noise over D's
for r in $ROWS; do emit_pct curl2_row${r}_pct_from_nominal "$(get . curl2_row$r)" "$(row_curl $r)"; done
if [ "$TIER" = reduced ]; then emit_ratio cv_noise_total_over_D . cv_noise_total . cv_noise_D; fi
}
experiment
