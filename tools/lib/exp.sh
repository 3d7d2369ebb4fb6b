# tools/lib/exp.sh - sourced by experiments/*/*/run.sh.
# Environment from tools/run-experiment: DPD (simulator), TIER, OUT (result dir).
set -euo pipefail
: "${DPD:?run through tools/run-experiment}" "${OUT:?}" "${TIER:?}"
# the analysis layer (tools/analysis.py, issue 40): every statistic, formula and derived simulation
# argument of the experiments; "$ANALYSE" SUBCOMMAND ARGS... writes TSV rows
ANALYSE=$DPD_ROOT/tools/analyse
# analyse_serve: from here on "$ANALYSE" runs in one analysis server (tools/analysis_server.py),
# through the static build/analyse-client, instead of a python of its own per call (about 60 ms of
# CPU each on the CI machines; an analysis makes hundreds). The same tables: a call runs in the
# server itself when nothing of it can wait on another call (no pipe on its stdin; analysis.py
# keeps no state between calls), else in a fork of the server as it was after importing
# analysis.py, on the caller's own descriptors. The server starts at the first call (an analysis
# that makes none pays nothing), from whichever subshell makes it, on a socket fixed here, and ends
# when this shell does. Nothing changes when the client is not built, the server does not start,
# or DPD_ANALYSE_SERVER=0: a call the client cannot hand over runs tools/analyse itself.
analyse_serve() {
    [ "${DPD_ANALYSE_SERVER:-1}" = 1 ] && [ -x "$DPD_ROOT/build/analyse-client" ] || return 0
    _analyse_dir=${TMPDIR:-/tmp}/dpd-analyse.$$.$RANDOM$RANDOM
    export DPD_ANALYSE_SOCKET=$_analyse_dir/socket DPD_ANALYSE_FALLBACK=$DPD_ROOT/tools/analyse
    ANALYSE=_analyse_call
}
_analyse_call() {
    [ -S "$DPD_ANALYSE_SOCKET" ] || _analyse_start
    "$DPD_ROOT/build/analyse-client" "$@"
}
# (the first call: one caller creates the directory and starts the server, detached so that a bare
# `wait` here does not wait for it, watching this shell ($$, also in a subshell); a concurrent
# first call finds the directory taken and falls back; the server says "ready" once it listens)
_analyse_start() {
    local line=
    mkdir -m 700 "$_analyse_dir" 2> /dev/null && mkfifo "$_analyse_dir/ready" || return 0
    ( exec "$DPD_ROOT/tools/analyse" --serve "$DPD_ANALYSE_SOCKET" $$ < /dev/null > "$_analyse_dir/ready" 2> /dev/null & )
    read -r -t 30 line < "$_analyse_dir/ready" || true
    rm -f "$_analyse_dir/ready"
}
# tsv_lookup FILE Q [WHO] -> "value<TAB>stderr" of the first row named Q, exit 1 (saying so as WHO)
# if none: selection only, in bash without a process, for the lookups an analysis makes in its loops
tsv_lookup() {
    _tsv_row "$1" "$2" && { printf '%s\n' "$_got"; return 0; }
    [ -z "${3:-}" ] || echo "$3: no $2 in $1" >&2
    return 1
}
# _tsv_row FILE Q: the first row of FILE whose first tab-separated field is Q, its second and third
# fields into _got_v and _got_se (each empty when absent; an empty field stays a field) and
# "value<TAB>stderr" into _got; exit 1 if no row is named Q. Read in the shell, no process: the one
# parser of get, getv, the copying helpers and tsv_lookup.
_tsv_row() {
    local line rest
    _got= _got_v= _got_se=
    [ -f "$1" ] || return 1
    while IFS= read -r line || [ -n "$line" ]; do
        [[ $line == "$2" || $line == "$2"$'\t'* ]] || continue
        rest=; [[ $line == *$'\t'* ]] && rest=${line#*$'\t'}
        _got_v=${rest%%$'\t'*}
        [[ $rest == *$'\t'* ]] && { rest=${rest#*$'\t'}; _got_se=${rest%%$'\t'*}; }
        _got=$_got_v$'\t'$_got_se
        return 0
    done < "$1"
    return 1
}
mkdir -p "$OUT/runs"
[ -n "${DPD_KEEP_RUNS+set}" ] || [ -f "$OUT/summary.tsv" ] || printf 'quantity\tvalue\tstderr\n' > "$OUT/summary.tsv"

# dpd_run NAME SCENE [--set k=v ...]: the simulation NAME of this experiment, in $OUT/runs/NAME.
# A simulation already complete with the same arguments and the same scene file content is kept
# (never rerun); one that ended with a deterministic failure (its .exit: 1 usage, 2 bad scene,
# 3 unstable) returns that status again without rerunning; any other is (re)run, resuming from its
# checkpoint (written every DPD_CHECKPOINT_EVERY steps, default 5000, but not sooner than
# DPD_CHECKPOINT_WALL seconds, default 60, after the last: a checkpoint holds every sampled series
# and reaches hundreds of MB in long runs; the result is bit-identical either way). The arguments
# are compared with the checkout's root removed from paths (a result made in another clone or
# worktree matches), the scene by the sha256 recorded in .scene_sha256 (runs made before it was
# recorded are matched by their arguments alone).
# Three modes:
#  - DPD_PLAN=1 (tools/run-experiment and tools/plan, a plan pass of one round, DPD_ROUND, see
#    `experiment` below): a simulation that must run is recorded, not run: its directory gets
#    .args, .scene_sha256 and .cwd (all tools/run-simulation needs) and its name goes to
#    $OUT/.plan; dpd_run returns 0 and the declaration goes on to the next one. run-experiment
#    then runs the planned simulations on its engine.
#  - DPD_VERIFY=1 (tools/verify-result): never run; a simulation that would run marks the result
#    stale ($OUT/.verify-stale) and stops the script.
#  - neither: run it here and now (tools/run-simulation), as a script run by hand does.
# dpd_run is called from a run.sh's declared simulations (simulations, simulations_K), never from
# its analysis unless the run.sh declares analysis_runs_simulations=1.
# _scene_sha SCENE -> _sha: the sha256 of the scene file ("missing" if there is none). A pass calls
# dpd_run for every simulation, most of them on a few scenes: the sums of the experiments' own
# scene files (under experiments/, which no run.sh writes) are kept for the rest of the pass, by
# path; any other file (one a run.sh writes, e.g. under $OUT) is read each time.
declare -gA _scene_sha_of=()   # (-g: exp.sh may be sourced inside a function)
_scene_sha() {
    local p=$1
    case $p in /*) ;; *) p=$PWD/$p ;; esac
    case $p in "$DPD_ROOT"/experiments/*) _sha=${_scene_sha_of[$p]:-}; [ -z "$_sha" ] || return 0 ;; *) p= ;; esac
    _sha=missing
    if [ -f "$1" ]; then _sha=$(sha256sum < "$1"); _sha=${_sha%% *}; fi
    [ -z "$p" ] || _scene_sha_of[$p]=$_sha
}
# _planned NAME: NAME is in $OUT/.plan already (read in the shell: the plan passes call it for every
# simulation they plan)
_planned() {
    local l _pl=()
    [ -f "$OUT/.plan" ] || return 1
    mapfile -t _pl < "$OUT/.plan"
    for l in ${_pl[@]+"${_pl[@]}"}; do [ "$l" = "$1" ] && return 0; done
    return 1
}
dpd_run() {
    local name=$1 scene=$2; shift 2
    local dir=$OUT/runs/$name args sha st rec recsha
    _declared_here dpd_run "$name"
    # (in the shell, not in pipelines: the plan and verify passes make this call for every
    # simulation of every result, and each process costs milliseconds)
    printf -v args '%s\n' "$scene" "$@"; _args_norm_text "$args"; args=$_args_text
    _scene_sha "$scene"; sha=$_sha
    _args_recorded_text "$dir"; rec=$_args_text
    recsha=$sha; [ -f "$dir/.scene_sha256" ] && { IFS= read -r recsha < "$dir/.scene_sha256" || true; }
    if [ "$rec" = "$args" ] && [ "$recsha" = "$sha" ]; then
        if [ -s "$dir/summary.tsv" ] && [ ! -e "$dir/INCOMPLETE" ]; then
            [ "${DPD_PLAN:-0}" = 1 ] || echo "dpd_run: $name already complete, kept" >&2
            return 0
        fi
        # a kept run that stopped (e.g. unstable, deliberately): with the same arguments and
        # seed it stops again; the recorded outcome stands (verification: runs kept from before
        # .exit was recorded count as unstable)
        st=$(_final_status "$dir")
        if [ -n "$st" ]; then return "$st"; fi
        if [ "${DPD_VERIFY:-0}" = 1 ] && [ -e "$dir/INCOMPLETE" ]; then return 3; fi
        _verify_refuse "$name" "it is incomplete"
    else
        _verify_refuse "$name" "its arguments or scene ($scene) differ from the recorded ones"
        [ ! -e "$dir" ] || rm -rf "$dir"
        mkdir -p "$dir"
        printf '%s\n' "$scene" "$@" > "$dir/.args"
        printf '%s\n' "$sha" > "$dir/.scene_sha256"
    fi
    pwd > "$dir/.cwd"
    if [ "${DPD_PLAN:-0}" = 1 ]; then
        _planned "$name" || printf '%s\n' "$name" >> "$OUT/.plan"
        return 0
    fi
    "$DPD_ROOT/tools/run-simulation" "$dir"
}
# the status of a simulation that ended with a failure it would repeat: its .exit when that is
# 1 (usage), 2 (bad scene) or 3 (unstable); or any failure after DPD_MAX_FAILURES (default 3)
# attempts that failed without being stopped by a signal (tools/run-simulation counts them):
# an I/O error that persists is not retried for ever. Empty when it may run again.
_final_status() {
    local st; st=$(cat "$1/.exit" 2>/dev/null) || return 0
    case $st in 1|2|3) echo "$st"; return 0 ;; esac
    [ "$(cat "$1/.failures" 2>/dev/null || echo 0)" -ge "${DPD_MAX_FAILURES:-3}" ] && echo "$st"
    return 0
}
# _args_recorded_text DIR: the arguments a kept run was made with, normalised (_args_norm_text), into
# _args_text: .args, or for runs made before .args was written, the command line the simulator
# recorded in provenance.tsv
_args_recorded_text() {
    _args_text=
    if [ -f "$1/.args" ]; then _args_norm_text "$(< "$1/.args")"
    elif [ -f "$1/provenance.tsv" ]; then
        _args_norm_text "$(awk -F'\t' '$1 == "command" { n = split($2, w, " "); print w[3]
            for (i = 4; i <= n; i++) {
                if (w[i] == "--out" || w[i] == "--checkpoint-every" || w[i] == "--checkpoint-wall") { i++; continue }
                if (w[i] == "--quiet" || w[i] == "--resume") continue
                print w[i] } }' "$1/provenance.tsv")"
    fi
}
# _args_norm_text TEXT: TEXT's lines (run arguments) with any absolute path into experiments/ made
# relative to the checkout, into _args_text without the trailing newlines; in the shell, not sed
# (it runs for every simulation of every pass). It gives what
#   sed -E 's#^/([^/]+/)*experiments/#experiments/#; s#=/([^/]+/)*experiments/#=experiments/#g'
# gave (the same regular expressions, matched by the same POSIX rules: leftmost, then longest;
# compared on every committed argument list, 2026-12-07)
_ARGS_LEAD='^/([^/]+/)*experiments/' _ARGS_SET='=/([^/]+/)*experiments/'
_args_norm_text() {
    local rest=$1 line out m pre
    _args_text=
    while [ -n "$rest" ]; do
        line=${rest%%$'\n'*}
        if [[ $rest == *$'\n'* ]]; then rest=${rest#*$'\n'}; else rest=; fi
        if [[ $line == *experiments/* ]]; then
            [[ $line =~ $_ARGS_LEAD ]] && line=experiments/${line#"${BASH_REMATCH[0]}"}
            out=
            while [[ $line =~ $_ARGS_SET ]]; do
                m=${BASH_REMATCH[0]}; pre=${line%%"$m"*}
                out+=$pre=experiments/; line=${line#"$pre$m"}
            done
            line=$out$line
        fi
        _args_text+=$line$'\n'
    done
    while [[ $_args_text == *$'\n' ]]; do _args_text=${_args_text%$'\n'}; done
}
_verify_refuse() {
    [ "${DPD_VERIFY:-0}" = 1 ] || return 0
    echo "verify: run '$1' would be (re)run: $2" >&2
    printf '%s: %s\n' "$1" "$2" >> "$OUT/.verify-stale"
    exit 97
}

# ---- the declaration: an experiment's simulations apart from its analysis ----------------------
# Every run.sh states its simulations in functions and its analysis in others, and ends with the
# line `experiment`:
#   simulations     round 1: the simulations (dpd_run, reuse_run) whose arguments the tier fixes
#   analysis        reads them: the tables, summary.tsv
#   simulations_2   (only where needed) round 2: simulations whose arguments an earlier analysis
#                   gives; it reads them with `from_analysis QUANTITY` (a row of summary.tsv the
#                   analysis wrote), which names what it reads
#   analysis_2      (optional) reads round 2; and so on (simulations_3, analysis_3, ...)
# The code outside these functions is the set-up (the tier's lengths and sizes, `needs` lines,
# helper functions); it reads no simulation. dpd_run and reuse_run are refused outside the
# simulations functions: the plan is what they declare, not what an analysis happens to reach.
# An experiment whose analysis runs simulations itself (`dpd run` called directly: the stability
# map's bisections, whose next trial depends on the last) says so by setting
# analysis_runs_simulations=1 in its set-up; tools/run-experiment then runs its analysis on its
# own job slot in the normal mode.
# keep_run NAME (optional, in a run.sh): writes into runs/NAME what the analysis reads from that
# simulation's run.h5 (its per-block tables, say), and succeeds when it is there already. A result
# keeps no run.h5, and tools/carry-partial carries none, so a table the analysis derives from it
# must be made while run.h5 exists: carry-partial runs keep_run for every finished simulation it
# carries (DPD_KEEP_RUNS, a pass of run.sh that runs nothing else) and stops, carrying nothing, when
# one fails (neither the table nor run.h5). The analysis calls the same function.
# experiment: runs the declaration. With DPD_ROUND=K (a plan pass, DPD_PLAN=1: tools/plan K = 1,
# tools/run-experiment every round): the simulations and analyses of rounds 1 .. K-1 (every one
# of their simulations finished), then round K's simulations, and nothing after; it records
# the number of rounds and analysis_runs_simulations in $OUT/.declared. Without DPD_ROUND (the
# analysis pass of tools/run-experiment, tools/verify-result, a run by hand): every round's
# simulations, each followed by its analysis.
_exp_step=
experiment() {
    # (names of its own: the functions it calls assign their variables globally, and bash would
    # give them these locals)
    local _exp_n=1 _exp_k _exp_f
    declare -F simulations > /dev/null && declare -F analysis > /dev/null ||
        { echo "exp.sh: $EXP/run.sh declares no functions simulations and analysis (tools/lib/exp.sh, experiment)" >&2; exit 1; }
    while declare -F "simulations_$((_exp_n + 1))" > /dev/null; do _exp_n=$((_exp_n + 1)); done
    # DPD_KEEP_RUNS="NAME ..." (tools/carry-partial): only the run.sh's keep_run NAME for each
    # finished simulation named, nothing else (see keep_run below)
    if [ -n "${DPD_KEEP_RUNS+set}" ]; then
        declare -F keep_run > /dev/null || return 0
        for _exp_k in $DPD_KEEP_RUNS; do keep_run "$_exp_k" || { echo "exp.sh: keep_run $_exp_k failed" >&2; exit 1; }; done
        return 0
    fi
    # every pass, plan passes included: run-experiment's analysis pass is one (DPD_PLAN=1 without
    # DPD_ROUND), and a round's simulations may derive their arguments by "$ANALYSE" calls (the
    # server starts at the first call: a pass that makes none pays nothing)
    analyse_serve
    if [ "${DPD_PLAN:-0}" = 1 ]; then
        printf 'rounds\t%s\nanalysis_runs_simulations\t%s\n' "$_exp_n" "${analysis_runs_simulations:-0}" > "$OUT/.declared"
    fi
    case ${DPD_ROUND:-} in ""|[1-9]|[1-9][0-9]) ;; *) echo "exp.sh: DPD_ROUND=$DPD_ROUND: not a round number" >&2; exit 1 ;; esac
    [ "${DPD_ROUND:-0}" -le "$_exp_n" ] || { echo "exp.sh: DPD_ROUND=$DPD_ROUND: $EXP/run.sh declares $_exp_n round(s)" >&2; exit 1; }
    for ((_exp_k = 1; _exp_k <= _exp_n; _exp_k++)); do
        _exp_f=simulations; [ "$_exp_k" = 1 ] || _exp_f=simulations_$_exp_k
        _exp_step=simulations
        "$_exp_f"
        _exp_step=
        [ "${DPD_ROUND:-}" != "$_exp_k" ] || return 0
        _exp_f=analysis; [ "$_exp_k" = 1 ] || _exp_f=analysis_$_exp_k
        declare -F "$_exp_f" > /dev/null || continue
        _exp_step=analysis
        "$_exp_f"
        _exp_step=
    done
}
# _declared_here WHAT NAME: refuse a simulation outside the declaration
_declared_here() {
    case $_exp_step:${analysis_runs_simulations:-0} in
        simulations:*|analysis:1) return 0 ;;
        analysis:*) echo "exp.sh: $1 $2 in the analysis of $EXP/run.sh: declare it in its simulations" \
                         "(simulations_K, a later round, if its arguments come from the analysis)" >&2 ;;
        *) echo "exp.sh: $1 $2 outside the declaration of $EXP/run.sh: call it from its function simulations" \
                "(and end run.sh with the line experiment)" >&2 ;;
    esac
    exit 1
}
# from_analysis QUANTITY -> "value<TAB>stderr": a row that an earlier round's analysis wrote to the
# experiment's summary, read by a later round's simulations (the declared input of that round)
from_analysis() { get . "$1"; }

# reuse_run NAME PAPER/EXP TIER [SOURCE_NAME]: the simulation SOURCE_NAME (default NAME) of another
# experiment's complete result (declared with needs), copied into $OUT/runs/NAME instead of run
# again (the same system and settings, e.g. Mai-Duy et al.'s Tables 1 and 2 come from one set of
# TCAF runs). The copy records its origin in REUSED_FROM; tools/run-experiment does not count its
# CPU time again.
reuse_run() {
    local name=$1 id=$2 tier=$3 src_name=${4:-$1} up
    _declared_here reuse_run "$name"
    up=$(upstream "$id@$tier") || exit 1
    local src=$up/runs/$src_name dir=$OUT/runs/$1
    if [ ! -s "$src/summary.tsv" ] || [ -e "$src/INCOMPLETE" ]; then
        echo "reuse_run: $name needs the complete simulation $src_name of results/$id/$tier" \
             "(make results/$id/$tier/summary.tsv, or tools/run-experiment $id $tier)" >&2
        exit 1
    fi
    rm -rf "$dir"; cp -a "$src" "$dir"
    printf 'results/%s/%s/runs/%s\n' "$id" "$tier" "$src_name" > "$dir/REUSED_FROM"
}
# needs TIERS PAPER/EXP[@TIER]: the one declaration that this experiment reads another's complete
# result, when it runs at one of TIERS ("any", or a comma-separated list of tiers): the result of
# the same tier, or with @TIER that fixed tier's (a committed result read as a reference).
# experiments.mk orders `make` by the same-tier declarations (tools/lib/needs.awk reads them from
# run.sh: keep each on a line of its own, starting with `needs`); upstream and reuse_run refuse
# a result that was not declared.
_NEEDS=" "
needs() {
    local tiers=$1 dep=$2
    [ "$tiers" = any ] || [[ ",$tiers," == *",$TIER,"* ]] || return 0
    case $dep in *@*) ;; *) dep=$dep@$TIER ;; esac
    _NEEDS="$_NEEDS$dep "
}
# upstream PAPER/EXP[@TIER] -> results/PAPER/EXP/TIER (TIER: this tier unless given), a declared
# (needs) and complete result; upstream_if: the same, or nothing if that result does not exist
upstream() {
    local dep=$1; case $dep in *@*) ;; *) dep=$dep@$TIER ;; esac
    local id=${dep%@*} tier=${dep#*@} dir=$DPD_ROOT/results/${dep%@*}/${dep#*@}
    [[ "$_NEEDS" == *" $dep "* ]] ||
        { echo "exp.sh: results/$id/$tier read but not declared (add a line 'needs $TIER $id$([ "$tier" = "$TIER" ] || echo "@$tier")' to run.sh)" >&2; return 1; }
    if [ ! -s "$dir/summary.tsv" ] || [ -e "$dir/INCOMPLETE" ]; then
        [ "${2:-}" = optional ] && return 0
        echo "exp.sh: needs the complete result results/$id/$tier (make results/$id/$tier/summary.tsv)" >&2
        return 1
    fi
    printf '%s\n' "$dir"
}
upstream_if() { upstream "$1" optional; }

# get NAME QUANTITY -> "value<TAB>stderr" from a run's summary (NAME "." : the
# experiment's own summary so far, e.g. a mean emit_mean wrote).
get() { _get "$1" "$2" && printf '%s\n' "$_got"; }
# getv NAME QUANTITY -> the value alone: `get NAME QUANTITY | cut -f1` without its two processes
getv() { _get "$1" "$2" && printf '%s\n' "$_got_v"; }
# _get NAME QUANTITY: the same into _got ("value<TAB>stderr", empty when missing), _got_v and
# _got_se (_tsv_row on the run's summary.tsv)
_get() {
    local f=$OUT/runs/$1/summary.tsv; [ "$1" = . ] && f=$OUT/summary.tsv
    _tsv_row "$f" "$2" && return 0
    echo "exp.sh: quantity '$2' missing in run '$1'" >&2
    return 1
}

# h5_series NAME SERIES: the samples of /series/SERIES in run NAME's run.h5,
# one per line at full precision (run.h5 is removed when the experiment is complete:
# keep what the analysis needs from it in a table of the run)
h5_series() {
    local f; f=$(mktemp)
    h5dump -d "/series/$2/value" -y -w 1 -m '%.17g' -o "$f" "$OUT/runs/$1/run.h5" >/dev/null \
        || { rm -f "$f"; echo "exp.sh: no series $2 in run $1" >&2; return 1; }
    tr -d ' ,' < "$f" | grep .; rm -f "$f"
}

# tcaf_fit NAME MODEL[,MODEL...] RHO BOX [ARG...]: `dpd tcaf-fit --model MODEL` of run NAME's stored
# C(k,t), the per-shell eta(k) to runs/NAME/tcaf_fit_MODEL.tsv and the fit's quantities to
# runs/NAME/tcaf_fit_MODEL.out. Several models (comma separated) share one fit: two-mode and integral
# read the same two-mode fit, which costs the call its time (the same files as one call per model).
# It runs in runs/NAME, so that the table's header names its input as tcaf.tsv beside it, not the
# scratch directory the analysis ran in (a reanalysis would otherwise rewrite every header).
tcaf_fit() {
    local run=$1 model=$2 rho=$3 box=$4 dpd=$DPD; shift 4
    # (it runs in the run's directory: a relative DPD made absolute; one process fewer when it is)
    case $dpd in /*) ;; *) dpd=$(realpath "$DPD") || return 1 ;; esac
    (cd "$OUT/runs/$run" && "$dpd" tcaf-fit tcaf.tsv --rho "$rho" --box "$box" --model "$model" \
        --table "tcaf_fit_%m.tsv" --summary "tcaf_fit_%m.out" "$@")
}

# tcaf_k0 NAME MODEL[,MODEL...] BOX -> "value<TAB>stderr" of the first MODEL: eta(k -> 0) of run NAME's
# stored C(k,t) by `dpd tcaf-fit --model MODEL` (README "The simulator"), rho the run's
# tcaf_mass_density, BOX its side; the per-shell eta(k) goes to runs/NAME/tcaf_fit_MODEL.tsv, and a
# further MODEL's (one fit shared) is read after by tcaf_k0_of. The suspension experiments of Mai-Duy
# et al. judge the spring-constrained eta(k -> 0) by MODEL = integral: the time integral of
# C(k,t)/C(k,0), the zero-frequency viscosity of generalised hydrodynamics, free of the fit window
# that makes eq. 28's amplitude-1 exponential (the run's own tcaf_eta_k0, the paper's literal method)
# read the first downswing of an oscillating curve at large phi; two-mode (its slow mode) is their
# second estimator.
tcaf_k0() {
    local rho; _get "$1" tcaf_mass_density || return 1; rho=$_got_v
    tcaf_fit "$1" "$2" "$rho" "$3" || { echo "exp.sh: dpd tcaf-fit --model $2 failed on run $1" >&2; return 1; }
    tcaf_k0_of "$1" "${2%%,*}"
}
# tcaf_k0_of NAME MODEL -> "value<TAB>stderr": eta(k -> 0) of the fit tcaf_k0 or tcaf_fit made
tcaf_k0_of() {
    [ -f "$OUT/runs/$1/tcaf_fit_$2.out" ] || { echo "exp.sh: no tcaf fit by $2 of run $1" >&2; return 1; }
    tsv_lookup "$OUT/runs/$1/tcaf_fit_$2.out" eta_k0 exp.sh
}

# emit QUANTITY VALUE STDERR, or emit QUANTITY "VALUE<TAB>STDERR" (as get and tcaf_k0 give it): a row
# of the experiment summary.
emit() {
    # an empty value is a computation that failed inside $(...) (whose status an argument loses):
    # an error, not a row that a later reading takes for a result
    local v=${2:-}
    [ -n "${v%%$'\t'*}" ] || { echo "exp.sh: emit $1: no value (did the computation that gives it fail?)" >&2; return 1; }
    if [ $# -eq 2 ]; then printf '%s\t%s\n' "$1" "$2" >> "$OUT/summary.tsv"
    else printf '%s\t%s\t%s\n' "$1" "$2" "$3" >> "$OUT/summary.tsv"; fi
}

# emit_from NAME QUANTITY [AS]: copy a run quantity into the summary.
emit_from() {
    _get "$1" "$2" || return 1
    printf '%s\t%s\n' "${3:-$2}" "$_got" >> "$OUT/summary.tsv"
}


# emit_diff QUANTITY NAME1 Q1 NAME2 Q2: value1 - value2 with the errors in quadrature.
emit_diff() {
    local a b
    _get "$2" "$3"; a=$_got; _get "$4" "$5"; b=$_got
    emit "$1" "$("$ANALYSE" diff "$a" "$b")"
}

# emit_ratio QUANTITY NAME1 Q1 NAME2 Q2: value1 / value2 with first-order error propagation.
emit_ratio() {
    local a b
    _get "$2" "$3"; a=$_got; _get "$4" "$5"; b=$_got
    emit "$1" "$("$ANALYSE" ratio "$a" "$b")"
}

# emit_mean AS QUANTITY NAME...: mean over independent runs of a run quantity,
# standard error = sample standard deviation / sqrt(number of runs) (0 for a single run).
emit_mean() {
    local as=$1 q=$2; shift 2
    local vals="" n
    for n in "$@"; do _get "$n" "$q"; vals="$vals $_got_v"; done
    # shellcheck disable=SC2086
    "$ANALYSE" mean-se-row "$as" $vals >> "$OUT/summary.tsv"
}

# lattice_pair KP:KQ DIGITS - the Mai-Duy et al. suspensions: the paper's KP^3
# colloids among 13500 solvent particles in 15^3 run as KQ^3 colloids in a box of
# side 15 KQ / KP (same lattice spacing, particles per colloid cell and phi).
# Sets kp, kq, tag ("phi" and phi to DIGITS decimals), L, count (constituent
# particles, 6 per colloid) and geo (the --set arguments of box and count).
lattice_pair() {
    kp=${1%:*} kq=${1#*:}
    read -r tag L < <("$ANALYSE" lattice-tag "$kp" "$kq" "$2")
    count=$((6 * kq * kq * kq))
    geo=(--set "box=[$L,$L,$L]" --set "types.[1].count=$count")
}

# emit_drag_torque ROW "F se" "T se" F_THEORY T_THEORY "U se" - the Pan et al.
# table rows: drag_rowROW, torque_rowROW, their theories (no error) and the
# ratios simulated / theory, whose errors combine the simulated value's and that
# of the velocity U the theory is linear in, in quadrature.
emit_drag_torque() {
    local r=$1 F=$2 T=$3 Fth=$4 Tth=$5 u=$6 q v th
    emit "drag_row$r" $F
    emit "torque_row$r" $T
    emit "drag_theory_row$r" "$Fth" 0
    emit "torque_theory_row$r" "$Tth" 0
    for q in drag torque; do
        [ $q = drag ] && v=$F th=$Fth || v=$T th=$Tth
        "$ANALYSE" theory-ratio ${q}_ratio_row$r "$v" "$u" "$th" >> "$OUT/summary.tsv"
    done
}

# block_slope NAME LO:HI -> "slope<TAB>stderr": the slope of v_x against position over
# LO <= pos <= HI, fitted to each block's profile (runs/NAME/profile_blocks.tsv: a scene
# with measure.profile.per_block) and averaged; the error from the scatter of the block
# slopes. The bins of one profile share the flow's fluctuations (and at m = 0 are solved
# together), so a fit of the averaged profile taking its bins as independent understates it.
block_slope() { "$ANALYSE" block-stat "$OUT/runs/$1/profile_blocks.tsv" "${2%%:*}" "${2#*:}" slope; }

# block_mean NAME LO:HI -> "mean<TAB>stderr": v_x averaged over the bins with LO < pos < HI
# in each block's profile (runs/NAME/profile_blocks.tsv), then over the blocks; the error
# from the scatter of the block means (neighbouring bins share the flow's fluctuations:
# their errors do not add in quadrature).
block_mean() { "$ANALYSE" block-stat "$OUT/runs/$1/profile_blocks.tsv" "${2%%:*}" "${2#*:}" mean; }

# max_rel_dev PROFILE LO:HI -> "dev<TAB>stderr": the largest relative deviation of a bin's
# density from the mean over the bins with LO <= pos <= HI of a profile.tsv; the error that
# bin's (tools/analysis.py max_rel_dev)
max_rel_dev() { "$ANALYSE" max-rel-dev "$1" "${2%%:*}" "${2#*:}"; }

# couette_viscosity NAME LX BULK: the m = 0 Couette channel of phan-thien-2016
# fig03 (walls bottom_inner/outer, top_inner/outer; run with
# measure.profile.per_block=true) -> "rate rate_se tau tau_se eta eta_se".
# rate: mean of the blocks' straight-line slopes of vx over the bulk bins (BULK
# = LO:HI in y) and its standard error (the m = 0 velocities are solved for the
# whole channel at once, so the bins of one profile are not independent);
# tau: (F_x on the bottom wall - F_x on the top wall) / (2 LX), errors added
# linearly (at m = 0 the fluid's net force vanishes: the walls' forces are
# opposite step by step, and a wall's two layers move together; at m > 0 an
# upper bound); eta = tau / rate.
couette_viscosity() {
    local name=$1 lx=$2 bulk=$3 g gse tau tause
    read -r g gse < <(block_slope "$name" "$bulk" | tr '\t' ' ')
    local q f=()
    for q in force_on_bottom_inner_x force_on_bottom_outer_x force_on_top_inner_x force_on_top_outer_x; do _get "$name" $q; f+=("$_got"); done
    read -r tau tause < <("$ANALYSE" wall-stress "$lx" "${f[@]}")
    printf '%s %s %s %s %s\n' "$g" "$gse" "$tau" "$tause" "$("$ANALYSE" ratio "$tau	$tause" "$g	$gse" | tr '\t' ' ')"
}

# What paper.md says of a result in words ("4 % below the paper's", "the halves differ by") is a
# quantity the analysis writes, not arithmetic in the text (issue 40 item 7):
# paper_number QUANTITY: the paper's number of a claim row of the experiment's bands.tsv (the `paper`
# column, the row of this tier, else of the paper tier); fails if there is none
paper_number() {
    awk -F'\t' -v q="$1" -v t="$TIER" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
        $1 == q && $(c["kind"]) == "claim" && ($(c["tier"]) == t || $(c["tier"]) == "paper") { v[$(c["tier"])] = $(c["paper"]) }
        END { x = (t in v) ? v[t] : v["paper"]; if (x == "" || x == "-") exit 1; print x }' bands.tsv \
        || { echo "exp.sh: no paper number for '$1' in bands.tsv" >&2; return 1; }
}
# emit_pct QUANTITY A B: 100 (a / b - 1), a's deviation from b in per cent; A and B each "value<TAB>stderr"
# (as get gives it) or a number (exact: the paper's, a theory's); first-order error of independent a, b
emit_pct() { emit "$1" "$("$ANALYSE" pct "$2" "$3")"; }
# emit_minus QUANTITY A B: a - b, A and B as for emit_pct, errors in quadrature
emit_minus() { emit "$1" "$("$ANALYSE" minus "$2" "$3")"; }

# two_sphere_blocks NAME BLOCKS: per-block means of the drag per sphere (F_a + F_b) / 2 along x and of
# the torque (T_a - T_b) / 2 about z (sphere a at lower y) of a run with two fixed colloids (pan-2008
# tab03's pair), BLOCKS contiguous blocks of the samples in run.h5 (the first n mod BLOCKS skipped, as
# src/core/blockavg.c), kept in runs/NAME/sphere_blocks.tsv (run.h5 is not kept): the two spheres'
# noises are averaged sample by sample, so their correlation is in the error
two_sphere_blocks() {
    local f=$OUT/runs/$1/sphere_blocks.tsv nb=$2
    [ -f "$f" ] && return 0
    [ -f "$OUT/runs/$1/run.h5" ] || { echo "exp.sh: runs/$1 has neither sphere_blocks.tsv nor run.h5" >&2; return 1; }
    paste <(h5_series $1 drag_on_colloid_a_x) <(h5_series $1 drag_on_colloid_b_x) \
          <(h5_series $1 torque_on_colloid_a_z) <(h5_series $1 torque_on_colloid_b_z) |
        "$ANALYSE" sphere-blocks $nb > "$f.tmp" && mv "$f.tmp" "$f"
}
