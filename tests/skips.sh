#!/bin/bash
# skips.sh - a check a suite cannot run is reported as skipped, never as passed:
# tests/io_errors.sh on a machine without unprivileged user and mount namespaces
# (simulated: an `unshare` that fails, first in PATH; only its namespace part,
# IO_ERRORS_PART=namespace) says SKIP for its tmpfs checks
# and ends with "N passed, M failed, K skipped", K > 0, counting no pass for them;
# tests/run-tests.sh adds the skipped checks up beside the passed and failed ones.
# DPD selects the binary. Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh skips
mkdir -p "$tmp/bin"
printf '#!/bin/sh\necho "unshare: unprivileged namespaces are not allowed here (stub)" >&2\nexit 1\n' > "$tmp/bin/unshare"
chmod +x "$tmp/bin/unshare"
PATH="$tmp/bin:$PATH" DPD="$DPD" IO_ERRORS_PART=namespace tests/io_errors.sh > "$tmp/io.log" 2>&1; st=$?
last=$(tail -1 "$tmp/io.log")
if grep -q '^SKIP tmpfs checks' "$tmp/io.log"; then ok "io_errors.sh without namespaces: says SKIP"
else bad "io_errors.sh without namespaces: says SKIP" "$(tail -3 "$tmp/io.log")"; fi
if [[ $last =~ ^([0-9]+)\ passed,\ ([0-9]+)\ failed,\ ([0-9]+)\ skipped$ ]] && [ "${BASH_REMATCH[3]}" -gt 0 ]; then
    ok "io_errors.sh without namespaces: summary counts the skip ($last)"
else bad "io_errors.sh without namespaces: summary counts the skip" "last line '$last'"; fi
if [[ $last =~ ^([0-9]+)\ passed ]] && [ "${BASH_REMATCH[1]}" -eq "$(grep -c '^PASS' "$tmp/io.log")" ]; then
    ok "io_errors.sh without namespaces: passes are only the checks that ran"
else bad "io_errors.sh without namespaces: passes are only the checks that ran" "last line '$last', $(grep -c '^PASS' "$tmp/io.log") PASS lines"; fi
[ $st -eq 0 ] && ok "io_errors.sh without namespaces: a skip is no failure (exit 0)" || bad "io_errors.sh exit status" "$st"
# run-tests.sh reads "N passed, M failed, K skipped" and adds K to its skipped total
# (TEST_SCRIPTS: the scripts it runs instead of its own list; no binaries)
printf '#!/bin/sh\necho "PASS a"; echo "SKIP b"; echo "SKIP c"; echo "1 passed, 0 failed, 2 skipped"\n' > "$tmp/fake1.sh"
printf '#!/bin/sh\necho "PASS d"; echo "1 passed, 0 failed"\n' > "$tmp/fake2.sh"
chmod +x "$tmp/fake1.sh" "$tmp/fake2.sh"
TEST_SCRIPTS="$tmp/fake1.sh $tmp/fake2.sh" tests/run-tests.sh > "$tmp/rt.log" 2>&1; st=$?
if [ "$(tail -1 "$tmp/rt.log")" = "2 passed, 0 failed, 2 skipped" ] && [ $st -eq 0 ]; then
    ok "run-tests.sh adds the suites' skipped checks to its total"
else bad "run-tests.sh adds the suites' skipped checks to its total" "status $st: $(tail -4 "$tmp/rt.log" | tr '\n' '|')"; fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
