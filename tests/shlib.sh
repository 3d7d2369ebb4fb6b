# shlib.sh - the common preamble of the shell tests, sourced from the repository
# root as `. tests/shlib.sh NAME`: DPD (the binary under test, made absolute),
# tmp (a fresh directory removed on exit), the pass/fail counters and ok/bad.
DPD=${DPD:-bin/dpd}
case $DPD in /*) ;; *) DPD=$PWD/$DPD ;; esac
tmp=$(mktemp -d "${TMPDIR:-/tmp}/dpd-$1-XXXXXX")
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok()  { pass=$((pass + 1)); echo "PASS $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1: $2"; }
# refuse NAME EXPECTED-MESSAGE COMMAND ARGS...: the command fails, says EXPECTED-MESSAGE on stderr
# and writes nothing on stdout
refuse() {
    local name=$1 msg=$2; shift 2
    if "$@" > "$tmp/out" 2> "$tmp/err"; then bad "$name" "exit 0"
    elif ! grep -q -e "$msg" "$tmp/err"; then bad "$name" "message: $(cat "$tmp/err")"
    elif [ -s "$tmp/out" ]; then bad "$name" "wrote a table"
    else ok "$name"; fi
}
# wait_for FILE PID: until FILE exists or the process ended (at most 60 s)
wait_for() { for _ in $(seq 6000); do [ -e "$1" ] && return; kill -0 "$2" 2>/dev/null || return; sleep 0.01; done; }
# reseal FILE VERSION [OFFSET BITS]: rewrite a checkpoint (src/io/checkpoint.c): set its format
# version (empty: keep it) and, with OFFSET, the 8 bytes there to the 64-bit value BITS (hex,
# stored little-endian), then recompute the FNV-1a checksum so that dpd accepts the file.
# The layout starts: magic 8, version 4, scene hash 8, particle count n 4, step 8 (offset 24),
# time 8, Lees-Edwards offset 8, x (count 8, 3n doubles: x[0] at 56), v (count 8, 3n doubles).
reseal() {
    perl -e '
        local $/; open my $f, "<:raw", $ARGV[0] or die; my $b = <$f>; close $f;
        $b = substr($b, 0, length($b) - 8);
        substr($b, 8, 4) = pack("V", $ARGV[1]) if length $ARGV[1];
        substr($b, $ARGV[2], 8) = pack("Q<", hex $ARGV[3]) if @ARGV > 3;
        my ($hi, $lo) = (0x14650fb0, 0x739d0383);            # basis 1469598103934665603 of checkpoint.c
        for my $c (unpack("C*", $b)) {                       # h = (h ^ c) * (2^40 + 435)
            $lo ^= $c;
            my $l = $lo * 435; my $carry = int($l / 4294967296);
            $hi = ($hi * 435 + $carry + (($lo * 256) % 4294967296)) % 4294967296;
            $lo = $l % 4294967296;
        }
        open $f, ">:raw", $ARGV[0] or die; print $f $b, pack("VV", $lo, $hi); close $f;' "$@"
}
