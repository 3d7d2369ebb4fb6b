# tools/lib/pdeath.sh - sourced first (at top level, no arguments) by the harness's processes that a
# driver starts and waits for (tools/run-simulation, tools/slurm-sim): the script runs again, once,
# with SIGTERM as its parent-death signal (prctl PR_SET_PDEATHSIG, through util-linux's setpriv), so
# that it ends when the process that started it ends, even by SIGKILL, instead of running on beside
# a restarted driver. dpd_pdeath: the same prefix for a command (empty without setpriv).
# tools/run-experiment and experiments.mk put it before the children they start; run-experiment
# itself takes it only from make (a run-experiment started by hand under nohup outlives its shell).
# dpd_pdeath_self=0 before sourcing: only the prefix, the script itself is not run again.
dpd_pdeath=()
# (whether setpriv works is asked once per process tree and host: _DPD_SETPRIV, exported, is the
# answer on host $HOSTNAME; a Slurm job that inherits it on another node asks again)
_DPD_SETPRIV=${_DPD_SETPRIV:-}
if [ "${_DPD_SETPRIV%:*}" != "$HOSTNAME" ]; then
    _DPD_SETPRIV=$HOSTNAME:0
    if command -v setpriv >/dev/null 2>&1 && setpriv --pdeathsig TERM true 2>/dev/null; then _DPD_SETPRIV=$HOSTNAME:1; fi
    export _DPD_SETPRIV
fi
if [ "${_DPD_SETPRIV##*:}" = 1 ]; then
    dpd_pdeath=(setpriv --pdeathsig TERM)
    if [ "${dpd_pdeath_self:-1}" = 1 ] && [ "${_DPD_PDEATH_PID:-}" != "$$" ]; then
        export _DPD_PDEATH_PID=$$ _DPD_PDEATH_PARENT=$PPID
        exec setpriv --pdeathsig TERM "$0" "$@"
    fi
    # the parent ended before the signal was set: end now, as the signal would have made us
    [ "${dpd_pdeath_self:-1}" = 0 ] || [ "$PPID" = "$_DPD_PDEATH_PARENT" ] || exit 143
fi
