#!/usr/bin/env bash
# Installs the Debian packages gearloss needs; does nothing when they are present.
#   scripts/install-deps.sh [all]   everything the test command (scripts/test.sh) uses
#   scripts/install-deps.sh cli     only what building and running the CLI needs (scripts/run-example.sh)
#   scripts/install-deps.sh GROUP.. one or more optional parts, installed when first used:
#       plots   Python with numpy/pandas/matplotlib (scripts/plot.sh)
#       python  the Python module's build (pybind11, python3-dev, venv; docs/python.md)
#       report  Chromium and poppler-utils (gearloss report --pdf, the report rendering test)
#       slurm   Slurm and MUNGE (the real-Slurm test, docs/slurm.md)
#       tests   Catch2 and ccache (the test suite's build)
# apt's output goes to $GEARLOSS_APT_LOG (default: a temporary file) and is shown only on failure.
set -euo pipefail
cli=(g++ make cmake pkg-config libeigen3-dev libcli11-dev libyaml-cpp-dev libfmt-dev libboost-dev nlohmann-json3-dev
     libpugixml-dev libzip-dev)
plots=(python3 python3-matplotlib python3-numpy python3-pandas)
python=(python3 python3-dev python3-venv python3-pip python3-setuptools python3-numpy python3-pandas pybind11-dev
        python3-pybind11)
report=(chromium poppler-utils)
slurm=(slurm-wlm munge)
tests=(catch2 ccache)
packages=() opts=()
[ $# -eq 0 ] && set -- all
for group in "$@"; do
    case $group in
        cli) packages+=("${cli[@]}") opts=(--no-install-recommends) ;;  # the fewest bytes to fetch
        plots) packages+=("${plots[@]}") ;;
        python) packages+=("${python[@]}") ;;
        report) packages+=("${report[@]}") ;;
        slurm) packages+=("${slurm[@]}") ;;
        tests) packages+=("${tests[@]}") ;;
        all) packages+=("${cli[@]}" "${tests[@]}" "${plots[@]}" "${python[@]}" "${report[@]}" "${slurm[@]}") ;;
        *) echo "usage: $0 [all|cli|plots|python|report|slurm|tests ...]" >&2; exit 1 ;;
    esac
done
# Several groups: recommended packages too, unless only the CLI was asked for.
[ $# -gt 1 ] && opts=()
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
log=${GEARLOSS_APT_LOG:-$(mktemp)}
if ! { "${sudo_cmd[@]}" apt-get update -qq && DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq \
        "${opts[@]}" "${missing[@]}"; } > "$log" 2>&1; then
    cat "$log" >&2
    echo "apt-get failed (output above)" >&2
    exit 1
fi
