#!/usr/bin/env bash
# Fig. 5 of Mai-Duy et al. 2019: fig04-relative-viscosity-a353 with the repulsion a = 6.50
# (a fluid less compressible than water) for every pair. See that run.sh.
export A=6.50
exec "$(dirname "$0")/../fig04-relative-viscosity-a353/run.sh" "$@"
