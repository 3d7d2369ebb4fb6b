#!/usr/bin/env bash
# Pan et al. 2008, eqs 16-17: colloid self-diffusion D from the MSD and the
# effective radius R = kBT / (c pi mu D), c = 6, with the paper's mu = 3.6388.
. "$DPD_ROOT/tools/lib/exp.sh"
MU=3.6388 L=10.0
case $TIER in
    quick) tier=(--set steps=12000) ;;
    # reduced: 400 time units (the scene's steps), the committed result (README)
    reduced) tier=() ;;
    # paper: 16500 time units, the length for the paper's 0.5 % statistics on D (README: run-to-run
    # scatter of D x run length about 1.15e-3); not run
    paper) tier=(--set steps=1650000) ;;
esac
dpd_run diff colloid-diffusion.cfg "${tier[@]}"
emit_from diff D D_colloid
emit_from diff D_t_ratio_late_half D_t_ratio_late_half
# eq. 16 with c = 6: R = kBT / (6 pi mu D); error from D alone
get diff D | num_awk -F'\t' -v m=$MU '{ num_rel1(1/(6*3.141592653589793*m*$1), $1, $2, o); print num_row("R", o) }' >> "$OUT/summary.tsv"
# the periodic box slows diffusion by 2.837 kBT / (6 pi mu L) (Yeh & Hummer 2004): D and R corrected
get diff D | num_awk -F'\t' -v m=$MU -v L=$L '{c = 2.837297/(6*3.141592653589793*m*L); D = $1 + c
    printf "D_colloid_box_corrected\t%.10g\t%.4g\n", D, $2
    num_rel1(1/(6*3.141592653589793*m*D), D, $2, o); print num_row("R_box_corrected", o) }' >> "$OUT/summary.tsv"
cp "$OUT/runs/diff/msd.tsv" "$OUT/msd.tsv"
