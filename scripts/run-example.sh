#!/usr/bin/env bash
# One command from a clean clone: install what the CLI needs (scripts/install-deps.sh cli),
# build the `gearloss` program only (no tests, no Python module) and map the shipped transfer
# gearbox (seed 001 test grid) to out/transfer-box-map.csv, which it prints.
# One line per stage; apt's and the compiler's output go to build/run-example.log, shown only
# when a stage fails. The test command (scripts/test.sh) installs and builds everything.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
mkdir -p "$build" out
log="$build/run-example.log"
: > "$log"
stage() {  # stage N TITLE COMMAND...: runs COMMAND quietly, prints its time; its output on failure
    local n=$1 title=$2 t0=$SECONDS
    shift 2
    printf '[%s/4] %s ... ' "$n" "$title"
    echo "== $title: $*" >> "$log"
    if "$@" >> "$log" 2>&1; then
        echo "$((SECONDS - t0)) s"
    else
        echo "FAILED"
        echo "--- $log (end):" >&2
        tail -n 60 "$log" >&2
        exit 1
    fi
}
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
stage 1 "packages the CLI needs (apt, only when missing)" env GEARLOSS_APT_LOG="$log.apt" scripts/install-deps.sh cli
cat "$log.apt" >> "$log" 2> /dev/null && rm -f "$log.apt"
stage 2 "configure (Release)" cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DGEARLOSS_PYTHON=OFF \
    "${launcher[@]}"
stage 3 "build gearloss ($(nproc) jobs)" cmake --build "$build" --target gearloss -j "$(nproc)"
stage 4 "map configs/transfer-box.yaml" "$build/app/gearloss" map configs/transfer-box.yaml -o out/transfer-box-map.csv
echo "wrote out/transfer-box-map.csv (log: $log):"
column -t -s, out/transfer-box-map.csv 2> /dev/null || cat out/transfer-box-map.csv
