#!/usr/bin/env bash
# Start-up of Couette flow from rest, m = 0 against m = 1 (Phan-Thien et al.
# 2016, Fig. 4): fluid equilibrated between walls at rest, walls at -U and +U
# from t = 0; profiles averaged over independent runs; t90 = time to 90 % of
# the steady profile (tools/analysis.py couette_growth).
. "$DPD_ROOT/tools/lib/exp.sh"
case $TIER in
    quick) seeds=(1 2 3); len=(--set equilibration=200 --set steps=2000); b0=500; b1=200; ts=15 ;;
    paper) seeds=(1 2 3 4 5 6 7 8); len=(); b0=1000; b1=400; ts=30 ;;
esac
# the simulations
simulations() {
for m in m0 m1; do
    for seed in "${seeds[@]}"; do
        if [ $m = m0 ]; then blk=(--set measure.every=1 --set measure.blocks=$b0)   # blocks of 4 steps
        else blk=(--set measure.blocks=$b1); fi                                    # blocks of 0.1 time units
        dpd_run ${m}_s$seed $m.cfg "${len[@]}" "${blk[@]}" --set seed=$seed
    done
done
}
analysis() {
# the analysis
for m in m0 m1; do
    files=()
    for seed in "${seeds[@]}"; do
        # the columns couette_growth (tools/analysis.py) reads, kept compressed (profile_blocks.tsv is not committed:
        # ~0.5 MB per run), so that the analysis can be redone from the committed files; written
        # under another name first, so that a failed attempt leaves no empty file to be kept
        vb=$OUT/runs/${m}_s$seed/vx_blocks.tsv.gz
        if [ ! -f "$vb" ]; then
            cut -f1,2,3,5 "$OUT/runs/${m}_s$seed/profile_blocks.tsv" | gzip -9n > "$vb.part"
            mv "$vb.part" "$vb"
        fi
        files+=("$vb")
    done
    zcat "${files[@]}" | "$ANALYSE" couette-growth $ts $m "$OUT" >> "$OUT/summary.tsv"
    runs=(); for seed in "${seeds[@]}"; do runs+=(${m}_s$seed); done
    emit_mean "temperature_$m" temperature "${runs[@]}"
done
emit_ratio t90_ratio_m1_m0 . t90_m1 . t90_m0
# what paper.md says in words (issue 40 item 7): t90 at m = 0 in time steps (dt = 0.01, m0.cfg)
"$ANALYSE" div "$(get . t90_m0)" 0.01 t90_m0_steps >> "$OUT/summary.tsv"
}
experiment
