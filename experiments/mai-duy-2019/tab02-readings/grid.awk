# grid.awk - Table 2's k_eff and eta_eff, at one phi and repulsion, under every combination of the
# open choices of Mai-Duy et al.'s section 4.2.3 (README.md, "The grid"; issue 37 item 4):
#   D  the density in eq. 28 for the constrained system: p the particles' (solvent and constituents,
#      the systems' own: J of eq. 23 sums over them), s the solvent's n = 4, t the total with the
#      rigid bodies' mass; eta scales with rho for every estimator, so D is a factor on eta_c
#   E  the estimator of the constrained eta(k -> 0): exp (eq. 28, amplitude 1, C/C0 >= 0.3: the
#      run's own fit), two_mode (slow mode), integral (zero-frequency viscosity)
#   K  the curve k_eff is read on: free (the same phi's free system, section 4.2.3), solvent (the
#      pure n = 4 solvent), ratio (eta_c / eta_f(k -> 0), both by E, on the free curve divided by
#      its own k -> 0 value)
#   F  the curve eta_eff is read from: constrained (eta_c itself, Table 2's eta by construction),
#      solvent (the pure solvent's eta(k) at k_eff: "the viscosity of the solvent phase"), free
#      (the free system's eta(k) at k_eff)
# usage: num_awk -F'\t' -v a=A -v phi=PHI -v f_p=1 -v f_s=4/RHO_P -v f_t=RHO_T/RHO_P \
#            -v c_exp="V<TAB>SE" -v c_two_mode=... -v c_integral=... -v f0_exp=... -v f0_two_mode=... \
#            -v f0_integral=... -f grid.awk FREE_CURVE SOLVENT_CURVE
#   (curves: k n2 vectors eta eta_se, k increasing: the readings' curve.tsv)
# Output, one line per combination: a phi D E K F k_eff se eta_eff se (nan where the curve does not
# reach the value or k_eff falls outside the curve F is read from).
FNR == 1 { file++ }
/^#/ || $1 == "k" { next }
file == 1 { nf++; fk[nf] = $1; fv[nf] = $4; fs[nf] = $5; next }
file == 2 { ns++; sk[ns] = $1; sv[ns] = $4; ss[ns] = $5; next }
END {
    split("p s t", DS, " "); split("exp two_mode integral", ES, " "); split("free solvent ratio", KS, " ")
    split("constrained solvent free", FS_, " ")
    fac["p"] = f_p; fac["s"] = f_s; fac["t"] = f_t
    split(f0_exp, z, "\t"); f0v["exp"] = z[1]; f0s["exp"] = z[2]
    split(f0_two_mode, z, "\t"); f0v["two_mode"] = z[1]; f0s["two_mode"] = z[2]
    split(f0_integral, z, "\t"); f0v["integral"] = z[1]; f0s["integral"] = z[2]
    split(c_exp, z, "\t"); cv["exp"] = z[1]; cs["exp"] = z[2]
    split(c_two_mode, z, "\t"); cv["two_mode"] = z[1]; cs["two_mode"] = z[2]
    split(c_integral, z, "\t"); cv["integral"] = z[1]; cs["integral"] = z[2]
    # the free curve divided by its own eta(k -> 0) by the run's fit (exp), for K = ratio
    for (i = 1; i <= nf; i++) { nv[i] = fv[i] / f0v["exp"]; ns_[i] = fs[i] / f0v["exp"] }
    for (d = 1; d <= 3; d++) for (e = 1; e <= 3; e++) {
        D = DS[d]; E = ES[e]
        num_scale(cv[E], cs[E], fac[D], c)                  # eta_c with the density D
        for (k = 1; k <= 3; k++) {
            K = KS[k]
            if (K == "free") num_crossing(fk, fv, fs, nf, c["v"], c["se"], ke)
            else if (K == "solvent") num_crossing(sk, sv, ss, ns, c["v"], c["se"], ke)
            else { num_ratio(c["v"], c["se"], f0v[E], f0s[E], r); num_crossing(fk, nv, ns_, nf, r["v"], r["se"], ke) }
            for (f = 1; f <= 3; f++) {
                F = FS_[f]
                if (F == "constrained") { ee["v"] = c["v"]; ee["se"] = c["se"] }
                else if (num_isnan(ke["v"])) { ee["v"] = ee["se"] = "nan" }
                else if (F == "solvent") num_interp(sk, sv, ss, ns, ke["v"], ke["se"], ee)
                else num_interp(fk, fv, fs, nf, ke["v"], ke["se"], ee)
                printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", a, phi, D, E, K, F, num_pair(ke), num_pair(ee)
            }
        }
    }
}
