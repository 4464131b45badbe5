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
