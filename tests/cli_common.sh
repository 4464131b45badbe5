# Shared set-up of the command-line tests (sourced): the binary, the source tree, a
# private temporary directory removed on exit, and the pass/fail counter.
# Usage (from a test script): source "$(dirname "$0")/cli_common.sh" "$@"
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0
fail=0
check() {  # check NAME CONDITION...
    local name=$1
    shift
    if "$@"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAILED: $name"; fi
}
# expect NAME EXIT_CODE MESSAGE_REGEX COMMAND...: the exit code, and the message in stderr (a
# script may define a stricter one after sourcing this file).
expect() {  # expect NAME EXIT_CODE MESSAGE_REGEX COMMAND...
    local name=$1 code=$2 pattern=$3
    shift 3
    "$@" > "$tmp/out" 2> "$tmp/err"
    local rc=$?
    check "$name: exit $code (got $rc)" test $rc -eq "$code"
    [ -n "$pattern" ] && check "$name: message /$pattern/" grep -qE -- "$pattern" "$tmp/err"
}
# await_handler PID SIGNAL: waits (up to 30 s) until the process catches SIGNAL (a name: INT,
# SIGTERM; read from SigCgt in /proc/PID/status). A background job of a script starts with
# SIGINT and SIGQUIT ignored, and any signal sent before main() installs the handler is lost
# or ends the process by the default action; on a loaded machine, an instrumented binary can
# take longer than half a second to get there. The tests time the program's stop, not its start.
await_handler() {
    local pid=$1 num mask end
    num=$(kill -l "${2#SIG}") || return 1
    end=$((${EPOCHREALTIME/./} + 30000000))
    while [ "${EPOCHREALTIME/./}" -lt $end ]; do
        mask=$(awk '/^SigCgt:/ {print $2}' "/proc/$pid/status" 2> /dev/null) || return 1
        [ -n "$mask" ] || return 1
        (((0x$mask >> (num - 1)) & 1)) && return 0
        sleep 0.02
    done
    return 1
}
# wait_for_temporary: waits (up to 10 s) until a run's temporary of kept.csv exists.
wait_for_temporary() {
    for _ in $(seq 100); do
        ls kept.csv.tmp.gearloss-* > /dev/null 2>&1 && return 0
        sleep 0.1
    done
    return 1
}
