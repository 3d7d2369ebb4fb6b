#!/bin/bash
# browser.sh - the rendered paper as a reader's browser shows it (`make test-paper`, after
# `make paper`): tests/browser.py drives Debian's Chromium, headless, over the DevTools protocol.
#  1. the checks on the small pages of tests/browser/ (pass.html passes every check; each
#     fail-CHECK-*.html is broken one way: a raw placeholder, an image that does not load, a link to
#     an id the page lacks, a table wider than the page) must fail there and only there, so that no
#     check passes by being unable to fail;
#  2. PAGE (default build/paper.html) at 390 px and at 1366 px: no raw placeholder, every image
#     loaded, every internal link resolved, no table reaching past the page (tables scroll in their
#     div.table-wrap); screenshots of its summary (laptop and phone) and of one experiment section
#     into build/ (paper-summary.png, paper-summary-phone.png, paper-section.png).
# Needs chromium and python3-websocket (tools/deps browser installs them). Prints "N passed, M failed".
# env: SECTION (the experiment whose section is screenshotted; default phan-thien-2016/fig08-compressibility)
set -u
cd "$(dirname "$0")/.."
page=${1:-build/paper.html}
py=/usr/bin/python3
[ -x "$py" ] || py=python3
if [ ! -f "$page" ]; then
    echo "browser.sh: no $page (make paper first)" >&2
    echo "0 passed, 1 failed"
    exit 1
fi
out=$(mktemp); trap 'rm -f "$out"' EXIT
"$py" tests/browser.py --self-test tests/browser > "$out" 2>&1; st1=$?
grep -v ' passed, .* failed$' "$out"
"$py" tests/browser.py --shots build --section "${SECTION:-phan-thien-2016/fig08-compressibility}" "$page" > "$out.2" 2>&1; st2=$?
grep -v ' passed, .* failed$' "$out.2"
pass=$(cat "$out" "$out.2" | grep -c '^PASS'); fail=$(cat "$out" "$out.2" | grep -c '^FAIL')
rm -f "$out.2"
# a run that stopped before its checks (no chromium, a protocol error) is a failure too
if [ $st1 -ne 0 ] || [ $st2 -ne 0 ]; then [ "$fail" -gt 0 ] || fail=1; fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
