#!/bin/bash
# analyse_server.sh - the analysis server (tools/analysis_server.py) and its client
# (build/analyse-client, tools/lib/analyse-client.c) against the plain tools/analyse: the same
# stdout, stderr and exit status for calls that print, read stdin, read a file relative to the
# caller's directory, fail on bad arguments, a missing file or an unknown subcommand; twenty
# calls at once; which calls run in the server itself and which in a fork; stdout and stderr one
# file; an output larger than a pipe holds, read by another call; the fallback to tools/analyse when the server cannot be reached or a
# descriptor is closed; exp.sh's analyse_serve switching "$ANALYSE" to the client; the server
# ending with the shell that started it, its socket removed; and the caller's pipes not held by
# it. Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh analyse-server
root=$PWD
client=$root/build/analyse-client plain=$root/tools/analyse
[ -x "$client" ] || { echo "FAIL no $client (make build/analyse-client)"; echo "0 passed, 1 failed"; exit 1; }

# start_server DIR: a server on DIR/socket watching this shell, as exp.sh starts it
start_server() {
    local line=
    mkdir -p "$1"; mkfifo "$1/ready"
    ( exec "$plain" --serve "$1/socket" $$ < /dev/null > "$1/ready" 2> /dev/null & )
    read -r -t 30 line < "$1/ready"
    [ "$line" = ready ]
}
if start_server "$tmp/s"; then ok "the server starts and says it is ready"; else bad "server start" "no ready line"; fi
export DPD_ANALYSE_SOCKET=$tmp/s/socket DPD_ANALYSE_FALLBACK=$plain

# same NAME STDIN_FILE ARGS...: client and plain tools/analyse give the same stdout, stderr and status
printf 'lags\tvalue\tstderr\neta\t3.5\t0.25\nrho\t4\t0\n' > "$tmp/summary.tsv"
printf '1.5\n2.5\n4\n' > "$tmp/values"
same() {
    local name=$1 in=$2 rc_c=0 rc_p=0; shift 2
    (cd "$tmp" && "$client" "$@" < "$in" > "$tmp/c.out" 2> "$tmp/c.err") || rc_c=$?
    (cd "$tmp" && env -u DPD_ANALYSE_SOCKET "$plain" "$@" < "$in" > "$tmp/p.out" 2> "$tmp/p.err") || rc_p=$?
    if [ $rc_c != $rc_p ]; then bad "$name" "status $rc_c, plain tools/analyse $rc_p"
    elif ! cmp -s "$tmp/c.out" "$tmp/p.out"; then bad "$name" "stdout '$(cat "$tmp/c.out")', plain '$(cat "$tmp/p.out")'"
    elif ! cmp -s "$tmp/c.err" "$tmp/p.err"; then bad "$name" "stderr '$(cat "$tmp/c.err")', plain '$(cat "$tmp/p.err")'"
    else ok "$name (status $rc_c)"; fi
}
same "a computed value" /dev/null plus 1.25 2.5
same "a table read on stdin" "$tmp/values" mean-se
same "a file named relative to the caller's directory" /dev/null lookup summary.tsv eta
same "a row not in the file (status 1)" /dev/null lookup summary.tsv nosuch
same "a missing file (status 1, the message)" /dev/null lookup nosuch.tsv eta
same "missing arguments (status 2, the message)" /dev/null plus
same "an unknown subcommand (status 2, the usage)" /dev/null no-such-subcommand
same "no subcommand (status 2)" /dev/null

# the calls run in the server's forks, not in a python of their own
out=$("$client" plus 2 3)
[ "$out" = 5 ] && ok "a call answered through the socket" || bad "call through the socket" "'$out'"
strace_ok=0
if command -v strace > /dev/null && strace -f -qq -e trace=execve -o "$tmp/trace" "$client" plus 2 3 > /dev/null 2>&1; then
    strace_ok=1
    if grep -q python "$tmp/trace"; then bad "no python started per call" "$(grep -c python "$tmp/trace") execve of python"
    else ok "no python started per call (strace: the client execs nothing)"; fi
fi
[ $strace_ok = 1 ] || echo "SKIP no strace: the per-call check"

# twenty calls at once, each its own answer
pids=(); for i in $(seq 20); do "$client" plus "$i" 1000 > "$tmp/par.$i" & pids+=($!); done
wait   # (the server is no child of this shell: a bare wait does not wait for it)
good=0; for i in $(seq 20); do [ "$(cat "$tmp/par.$i")" = $((i + 1000)) ] && good=$((good + 1)); done
[ $good = 20 ] && ok "twenty calls at once, each its own answer" || bad "twenty calls at once" "$good of 20 right"

# a pipeline: the call reads what the one before it writes and writes to the next
out=$(printf '2\n4\n' | "$client" mean-se | cut -f1)
[ "$out" = "$(printf '2\n4\n' | env -u DPD_ANALYSE_SOCKET "$plain" mean-se | cut -f1)" ] && ok "inside a pipeline" || bad "pipeline" "'$out'"

# which calls the server runs itself (no fork): strace on the server counts its forks for one call
# with stdin /dev/null and stdout a file (none), and one with stdin a pipe (a fork)
spid=$(pgrep -f -- "--serve $DPD_ANALYSE_SOCKET" | head -1)
forks() {   # forks CMD...: the server's clone calls while CMD runs
    local n
    strace -qq -f -e trace=clone,clone3,fork,vfork -e signal=none -p "$spid" -o "$tmp/forks" & local st=$!
    for _ in $(seq 100); do grep -q '^TracerPid:[[:space:]]*[1-9]' "/proc/$spid/status" && break; sleep 0.1; done   # attached
    "$@"; sleep 0.5; kill "$st" 2> /dev/null; wait "$st" 2> /dev/null
    n=$(grep -cE 'clone|fork' "$tmp/forks"); echo "$n"
}
if command -v strace > /dev/null && [ -n "$spid" ]; then
    n=$(forks sh -c '"$0" plus 2 3 < /dev/null > "$1"' "$client" "$tmp/inl.out")
    [ "$n" = 0 ] && [ "$(cat "$tmp/inl.out")" = 5 ] && ok "a call without a pipe on stdin runs in the server itself (no fork)" ||
        bad "inline call" "$n forks, '$(cat "$tmp/inl.out")'"
    n=$(forks sh -c 'printf "2\n4\n" | "$0" mean-se > "$1"' "$client" "$tmp/fork.out")
    [ "$n" -ge 1 ] && ok "a call reading a pipe runs in a fork ($n)" || bad "forked call" "$n forks"
else
    echo "SKIP no strace or no server pid: the fork counts"
fi
# stdout and stderr one file (2>&1): in a fork, in the order the call writes them
rc_c=0; rc_p=0
(cd "$tmp" && "$client" lookup nosuch.tsv eta < /dev/null > "$tmp/c.both" 2>&1) || rc_c=$?
(cd "$tmp" && env -u DPD_ANALYSE_SOCKET "$plain" lookup nosuch.tsv eta < /dev/null > "$tmp/p.both" 2>&1) || rc_p=$?
[ $rc_c = $rc_p ] && cmp -s "$tmp/c.both" "$tmp/p.both" && ok "stdout and stderr one file: as tools/analyse (status $rc_c)" ||
    bad "2>&1" "status $rc_c/$rc_p, '$(cat "$tmp/c.both")' vs '$(cat "$tmp/p.both")'"
# an output larger than a pipe holds, read by a call that waits for this server: not a deadlock (a
# fork writes what the pipe has no room for), the same bytes as tools/analyse
awk 'BEGIN { for (i = 1; i <= 20000; i++) printf "%d\t%d\t%d\t%.6f\t%.6f\n", i, i, 6, 1 + i / 7, 0.01 }' > "$tmp/big.tsv"
for order in 1 2; do
    rc=0
    if [ $order = 1 ]; then timeout 60 bash -c '"$0" normalise "$1" 2 < /dev/null | "$0" mean-se' "$client" "$tmp/big.tsv" > "$tmp/big.c" || rc=$?
    else timeout 60 bash -c '"$0" normalise "$1" 2 < /dev/null | { sleep 0.5; "$0" mean-se; }' "$client" "$tmp/big.tsv" > "$tmp/big.c" || rc=$?; fi
    env -u DPD_ANALYSE_SOCKET "$plain" normalise "$tmp/big.tsv" 2 < /dev/null | env -u DPD_ANALYSE_SOCKET "$plain" mean-se > "$tmp/big.p"
    [ $rc = 0 ] && cmp -s "$tmp/big.c" "$tmp/big.p" && ok "a $(wc -c < "$tmp/big.tsv")-byte output into a call on a pipe (reader $order): no deadlock, the same" ||
        bad "big output into a pipe (reader $order)" "status $rc, '$(head -c 100 "$tmp/big.c")' vs '$(head -c 100 "$tmp/big.p")'"
done

# the fallback: no server there, or a standard descriptor closed: tools/analyse runs the call
out=$(DPD_ANALYSE_SOCKET=$tmp/none/socket "$client" plus 2 3)
[ "$out" = 5 ] && ok "no server at the socket: tools/analyse runs the call" || bad "fallback without server" "'$out'"
out=$("$client" plus 2 3 <&-)
[ "$out" = 5 ] && ok "stdin closed: tools/analyse runs the call" || bad "fallback with stdin closed" "'$out'"
rc=0; DPD_ANALYSE_SOCKET=$tmp/none/socket DPD_ANALYSE_FALLBACK= "$client" plus 2 3 > /dev/null 2> "$tmp/err" || rc=$?
[ $rc = 127 ] && grep -q 'no analysis server' "$tmp/err" && ok "no server and no fallback: status 127, said" \
    || bad "no server, no fallback" "status $rc, '$(cat "$tmp/err")'"

# exp.sh's analyse_serve: "$ANALYSE" goes through the client; the server starts at the first call
# (none before it), from a subshell too, and ends with the shell that started it, its socket
# directory removed
cat > "$tmp/run.sh" <<EOF
set -euo pipefail
export DPD=/bin/true OUT=$tmp/out TIER=quick DPD_ROOT=$root
. "$root/tools/lib/exp.sh"
analyse_serve
[ -e "\${DPD_ANALYSE_SOCKET:-/nonexistent}" ] && echo early || echo none-yet
sleep 0.1 & wait   # a bare wait: not for the server
printf '%s\n%s\n' "\$ANALYSE" "\${DPD_ANALYSE_SOCKET:-}"
echo "\$("\$ANALYSE" plus 40 2)"
[ -S "\${DPD_ANALYSE_SOCKET:-/nonexistent}" ] && echo listening || echo no-socket
"\$ANALYSE" plus 1 1 > /dev/null & "\$ANALYSE" plus 2 2 > /dev/null & wait
EOF
env -u DPD_ANALYSE_SOCKET timeout 30 bash "$tmp/run.sh" > "$tmp/run.out" 2>&1
mapfile -t r < "$tmp/run.out"
[ "${r[0]:-}" = none-yet ] && ok "analyse_serve starts no server before the first call" || bad "lazy start" "$(cat "$tmp/run.out")"
[ "${r[1]:-}" = _analyse_call ] && [ "${r[3]:-}" = 42 ] && [ "${r[4]:-}" = listening ] \
    && ok "exp.sh analyse_serve: the first call (in a subshell) starts the server and is answered; a bare wait does not wait for it" \
    || bad "analyse_serve" "$(cat "$tmp/run.out")"
gone=0; for _ in $(seq 50); do [ -e "${r[2]:-/nonexistent}" ] || { gone=1; break; }; sleep 0.1; done
[ $gone = 1 ] && [ ! -d "$(dirname "${r[2]:-/x/y}")" ] && ok "the server ends with its shell and removes its socket" \
    || bad "server end" "${r[2]:-} still there 5 s after its shell ended"
env -u DPD_ANALYSE_SOCKET DPD_ANALYSE_SERVER=0 bash "$tmp/run.sh" > "$tmp/run0.out" 2>&1
mapfile -t r0 < "$tmp/run0.out"
[ "${r0[1]:-}" = "$plain" ] && [ "${r0[3]:-}" = 42 ] && ok "DPD_ANALYSE_SERVER=0: \"\$ANALYSE\" is tools/analyse" \
    || bad "DPD_ANALYSE_SERVER=0" "$(cat "$tmp/run0.out")"
# the server keeps none of the caller's descriptors: its open files (/proc) while it serves a shell
# whose stdout, stderr and descriptor 7 are a pipe do not include that pipe (make's output and
# jobserver, a tee)
cat > "$tmp/pipe.sh" <<EOF
set -euo pipefail
export DPD=/bin/true OUT=$tmp/out2 TIER=quick DPD_ROOT=$root
. "$root/tools/lib/exp.sh"
exec 7>&1   # a descriptor inherited beyond 0-2, as make's jobserver pipe is
analyse_serve
"\$ANALYSE" plus 1 1 > /dev/null
spid=\$(pgrep -f -- "--serve \$DPD_ANALYSE_SOCKET" | head -1)
echo "\$(readlink /proc/\$\$/fd/1) \${spid:-none}"
for f in /proc/\$spid/fd/*; do readlink "\$f"; done
EOF
env -u DPD_ANALYSE_SOCKET bash "$tmp/pipe.sh" 2>&1 | cat > "$tmp/pipe.out"
read -r pipe spid < "$tmp/pipe.out"
if [ "${spid:-none}" = none ] || [ "${pipe#pipe:}" = "$pipe" ]; then bad "caller's descriptors" "no server or no pipe: $(head -3 "$tmp/pipe.out")"
elif tail -n +2 "$tmp/pipe.out" | grep -qxF "$pipe"; then bad "caller's descriptors" "the server holds the caller's $pipe"
else ok "the server keeps none of the caller's descriptors ($(($(wc -l < "$tmp/pipe.out") - 1)) open, not its $pipe)"; fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
