#!/bin/bash
# claim_groups.sh - every claim row of every experiments/*/*/bands.tsv in exactly one group of its
# claims.tsv (tools/check --groups, tools/lib/groups.awk), the groups the summary and the cards of
# paper.md show: one check per experiment; prints "N passed, M failed" (make test).
# The rule itself is tested on a fixture by tools/test-harness.sh.
cd "$(dirname "$0")/.."
out=$(DPD_ROOT=$PWD tools/check --groups 2>&1)
printf '%s\n' "$out"
pass=$(printf '%s\n' "$out" | grep -c ': ok, ')
fail=$(printf '%s\n' "$out" | grep -v ': ok, ' | grep -v '^groups: ' | cut -d: -f1 | sort -u | grep -c .)
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
