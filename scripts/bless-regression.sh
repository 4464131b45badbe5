#!/usr/bin/env bash
# Regenerates the blessed outputs of the regression net (tests/regression/blessed/)
# on purpose. A reason is required: it is printed as the first line of the commit
# message to use, followed by the differences against the previous blessed files.
# Usage: scripts/bless-regression.sh --reason "why the numbers moved" [BINARY]
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" != "--reason" ] || [ -z "${2:-}" ]; then
    echo "usage: scripts/bless-regression.sh --reason \"why the numbers moved\" [BINARY]" >&2
    exit 1
fi
reason=$2
bin=${3:-build/app/gearloss}
[ -x "$bin" ] || scripts/build.sh
before=$(bash tests/regression/run.sh "$bin" . 2>&1 || true)
bash tests/regression/run.sh "$bin" . --bless
echo
echo "Commit the blessed files with a message such as:"
echo "  regression net: re-blessed — $reason"
echo
echo "Differences against the previous blessed files:"
echo "$before" | grep -v '^regression:' | head -60 || true
