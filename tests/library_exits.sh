#!/bin/bash
# library_exits.sh - library code (src/*.c except main.c) never ends the process: no exit(),
# _exit(), _Exit(), quick_exit() or abort(). A failure goes up the call chain as a status, so that
# run_scene closes its files, keeps INCOMPLETE with the reason and main() picks the exit status
# (issue 24, bug 4: rotation.c called exit(4) from inside the force call). Comments are ignored.
# Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh library-exits
for f in src/*/*.c; do
    [ "$f" = src/app/main.c ] && continue
    # strip /* */ and // comments, keep line numbers
    hits=$(perl -0pe 's{/\*.*?\*/}{$& =~ tr/\n//cdr}gse; s{//[^\n]*}{}g' "$f" \
           | grep -nE '(^|[^A-Za-z0-9_])(exit|_exit|_Exit|quick_exit|abort)[[:space:]]*\(' || true)
    if [ -z "$hits" ]; then ok "$f ends no process"
    else bad "$f ends the process" "$(sed "s|^|$f:|" <<<"$hits" | tr '\n' ' ')"; fi
done
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
