#!/usr/bin/env bash
# Pan et al. 2008, Table 3: drag and torque on each of two fixed spheres a distance l
# apart, flow normal to their line of centres, against eq. 23 with the measured
# superficial velocity u.
. "$DPD_ROOT/tools/lib/exp.sh"
MU=3.6388 R=0.2737 FSPH=5.1      # paper mu and R; body force per sphere (N_f g = 2 FSPH)
case $TIER in
    quick) L=8;  ROWS="1 3"; len=() ;;
    paper) L=30; ROWS="1 2 3"; len=(--set equilibration=20000 --set steps=200000) ;;
    # reduced: the paper's rows in a 16^3 box (12288 particles) for 200 time units each,
    # about 10 CPU-minutes; the paper tier needs about 4 CPU-hours per row
    reduced) L=16; ROWS="1 2 3"; len=(--set equilibration=2000 --set steps=20000) ;;
esac
row_l()    { case $1 in 1) echo 2.0;; 2) echo 1.5;; 3) echo 1.0;; esac; }
paper_F()  { case $1 in 1) echo 4.861;; 2) echo 4.857;; 3) echo 4.863;; esac; }
paper_T()  { case $1 in 1) echo 0.0253;; 2) echo 0.0451;; 3) echo 0.113;; esac; }
NF=$(awk -v L=$L 'BEGIN{printf "%d", 3*L^3}')
G=$(awk -v n=$NF -v f=$FSPH 'BEGIN{printf "%.6g", 2*f/n}')
eq23() {  # l u -> F_the T_the (eq. 23)
    awk -v l=$1 -v u=$2 -v m=$MU -v R=$R 'BEGIN{pi = 3.141592653589793; q = R/l
        F = 6*pi*m*R*u * (1 - 3*q/4 + 9*q^2/16 - 59*q^3/64 + 465*q^4/256 - 15813*q^5/7168)
        T = 8*pi*m*R^3*u/l * (3*q/4 - 9*q^2/16 + 27*q^3/64 - 273*q^4/256 + 1683*q^5/1024)
        printf "%.10g %.10g\n", F, T}'
}
printf 'row\tl\tu\tu_se\tdrag\tdrag_se\tdrag_theory\tdrag_paper\ttorque\ttorque_se\ttorque_theory\ttorque_paper\n' > "$OUT/table3.data.tsv"
printf 'l\tu\tF paper\tF ours (N_f g / 2)\tF eq. 23\tF verdict@\tT paper\tT ours\tT eq. 23\tT verdict@\n' > "$OUT/table3.tsv"
for r in $ROWS; do
    l=$(row_l $r) c=$(awk -v L=$L 'BEGIN{printf "%.4f", L/2}')
    ya=$(awk -v c=$c -v l=$l 'BEGIN{printf "%.4f", c - l/2}') yb=$(awk -v c=$c -v l=$l 'BEGIN{printf "%.4f", c + l/2}')
    # start the fluid at eq. 23's u for this force: the total momentum relaxes in N_f / (2 zeta)
    u0=$(eq23 $l 1 | awk -v f=$FSPH '{printf "%.4f", f/$1}')
    dpd_run row$r two-spheres.cfg "${len[@]}" --set "box=[$L.0,$L.0,$L.0]" --set "types.[0].count=$NF" \
        --set "types.[0].body_force=[$G,0.0,0.0]" --set "types.[0].velocity=[$u0,0.0,0.0]" \
        --set "types.[1].positions=([$c,$ya,$c])" --set "types.[2].positions=([$c,$yb,$c])" --set "seed=$((2300 + r))"
    st=$(awk -F'\t' '$1 == "steps" {print $2}' "$OUT/runs/row$r/summary.tsv")
    # superficial velocity: mean fluid velocity; error the larger of the block and the
    # Ornstein-Uhlenbeck estimate sqrt(2 kBT / (zeta T)), zeta = N_f g / u (see fig02-drag-calibration)
    u=$(get row$r mean_velocity_fluid_x | awk -F'\t' -v n=$NF -v g=$G -v T="$(awk -v s=$st 'BEGIN{print s*0.01}')" '{
        ou = sqrt(2 * $1 / (n * g * T)); printf "%.10g\t%.4g", $1, ($2 > ou ? $2 : ou) }')
    emit "u_row$r" $u
    # drag per sphere: the applied force N_f g / 2 (in the steady state the fluid's momentum balance
    # makes it the mean drag exactly, as the paper's nearly constant F_sim suggests); the measured
    # mean of the two drags is kept as a check (drag_measured_row*), its noise is 10x larger.
    # Torque: antisymmetric, (T_a - T_b) / 2 about z (sphere a at lower y).
    Fm=$(paste <(get row$r drag_on_colloid_a_x) <(get row$r drag_on_colloid_b_x) | awk -F'\t' '{printf "%.10g\t%.4g", ($1+$3)/2, sqrt($2^2+$4^2)/2}')
    emit "drag_measured_row$r" $Fm
    F=$(awk -v n=$NF -v g=$G 'BEGIN{printf "%.10g\t0", n*g/2}')
    T=$(paste <(get row$r torque_on_colloid_a_z) <(get row$r torque_on_colloid_b_z) | awk -F'\t' '{printf "%.10g\t%.4g", ($1-$3)/2, sqrt($2^2+$4^2)/2}')
    read -r Fth Tth < <(eq23 $l "$(echo "$u" | cut -f1)")
    emit_drag_torque $r "$F" "$T" "$Fth" "$Tth" "$u"
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' $r $l "$u" "$F" $Fth $(paper_F $r) "$T" $Tth $(paper_T $r) >> "$OUT/table3.data.tsv"
    printf '%s\t%s\t%s\t%s\t%s\t%s\n' $l "$u" "$F" "$T" $Fth $Tth | awk -F'\t' -v r=$r -v pF=$(paper_F $r) -v pT=$(paper_T $r) '{
        printf "%s\t%.4f +- %.4f\t%s\t%.3f +- %.3f\t%.3f\tdrag_ratio_row%s\t%s\t%.4f +- %.4f\t%.4f\ttorque_ratio_row%s\n",
               $1, $2, $3, pF, $4, $5, $8, r, pT, $6, $7, $9, r }' >> "$OUT/table3.tsv"
done
