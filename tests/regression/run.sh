#!/usr/bin/env bash
# Runs every case of tests/regression/cases.txt with BINARY from SOURCE_DIR and
# either compares each output with its blessed copy (default) or writes the
# blessed copies (--bless, used by scripts/bless-regression.sh only).
# Usage: run.sh BINARY SOURCE_DIR [--bless]
set -euo pipefail
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
src=$2
mode=${3:-compare}
dir="$src/tests/regression"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$src"
failed=0 passed=0
while IFS= read -r line; do
    case "$line" in ''|'#'*) continue ;; esac
    name=$(echo "${line%%|*}" | xargs)
    args=${line#*|}
    out="$tmp/$name"
    read -r -a argv <<< "${args//OUT/$out}"
    if [[ "$args" == *OUT* ]]; then
        "$bin" "${argv[@]}" > /dev/null 2> "$tmp/stderr" || { echo "FAIL $name: gearloss exited $?"; cat "$tmp/stderr"; failed=$((failed + 1)); continue; }
    else
        "$bin" "${argv[@]}" > "$out" 2> "$tmp/stderr" || { echo "FAIL $name: gearloss exited $?"; cat "$tmp/stderr"; failed=$((failed + 1)); continue; }
    fi
    if [ "$mode" = "--bless" ]; then
        cp "$out" "$dir/blessed/$name"
        echo "blessed $name"
        continue
    fi
    if [ ! -f "$dir/blessed/$name" ]; then
        echo "FAIL $name: no blessed copy (scripts/bless-regression.sh)"
        failed=$((failed + 1))
    elif python3 "$dir/compare.py" "$out" "$dir/blessed/$name" > "$tmp/diff"; then
        passed=$((passed + 1))
    else
        echo "FAIL $name differs from its blessed copy:"
        sed 's/^/    /' "$tmp/diff"
        failed=$((failed + 1))
    fi
done < "$dir/cases.txt"
[ "$mode" = "--bless" ] && exit "$failed"
echo "regression: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
