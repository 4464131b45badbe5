#!/usr/bin/env bash
# Installs the Debian packages gearloss needs; does nothing when they are present.
#   scripts/install-deps.sh        everything the test command (scripts/test.sh) uses: the CLI's
#                                  build, Catch2, ccache, Python with numpy/pandas/matplotlib and
#                                  pybind11, Chromium (report rendering), Slurm and MUNGE (the
#                                  real-Slurm test, docs/slurm.md)
#   scripts/install-deps.sh cli    only what building and running the CLI needs (scripts/run-example.sh)
# apt's output goes to $GEARLOSS_APT_LOG (default: a temporary file) and is shown only on failure.
set -euo pipefail
cli=(g++ make cmake pkg-config libeigen3-dev libcli11-dev libyaml-cpp-dev libfmt-dev libboost-dev nlohmann-json3-dev
     libpugixml-dev libzip-dev)
rest=(catch2 ccache python3 python3-dev python3-matplotlib python3-numpy python3-pandas pybind11-dev python3-pybind11
      chromium poppler-utils slurm-wlm munge)
case ${1:-all} in
    cli) packages=("${cli[@]}") opts=(--no-install-recommends) ;;  # the fewest bytes to fetch
    all) packages=("${cli[@]}" "${rest[@]}") opts=() ;;
    *) echo "usage: $0 [cli|all]" >&2; exit 1 ;;
esac
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
