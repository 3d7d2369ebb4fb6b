#!/usr/bin/env bash
# Table 1 of Mai-Duy et al. 2019: the cube (eq. 31) and sphere (eq. 32) length
# scales for the 11 volume fractions (k^3 octahedra of 6 particles among 13500
# solvent particles in 15^3), computed by `dpd wavelengths`. Same for both tiers.
. "$DPD_ROOT/tools/lib/exp.sh"
"$DPD" wavelengths --box 15 --n 4 --p 6 --kmin 3 --kmax 13 | tail -n +2 >> "$OUT/summary.tsv"
# table beside the paper's columns (the TCAF column is the paper's only: not built here)
awk -F'\t' 'NR==FNR { if ($1 ~ /^phi_k/) { k = substr($1, 6); phi[k] = $2 }
                      if ($1 ~ /^lambda_cube_/) cube[$1] = $2; if ($1 ~ /^lambda_sphere_/) sph[$1] = $2; next }
    /^#/ || $1 == "k" { next }
    { k = $1; tag = sprintf("phi%.4f", phi[k]);
      printf "%s\t%.4f\t%.4f\t%s\t%.4f\t%s\t%s\n", k, phi[k], sph["lambda_sphere_" tag], $3, cube["lambda_cube_" tag], $4, $5 }' \
    "$OUT/summary.tsv" paper-table1.tsv > "$OUT/body.tsv"
{ printf 'k\tphi\tsphere (eq. 32)\tsphere, paper\tcube (eq. 31)\tcube, paper\tTCAF, paper\n'; cat "$OUT/body.tsv"; } > "$OUT/table1.tsv"
rm "$OUT/body.tsv"
