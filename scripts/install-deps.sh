#!/usr/bin/env bash
# Installs the Debian packages gearloss builds with; does nothing when they are present.
set -euo pipefail
packages=(g++ cmake make libeigen3-dev libcli11-dev libyaml-cpp-dev libfmt-dev catch2 libboost-dev python3 python3-dev python3-matplotlib python3-numpy python3-pandas ccache nlohmann-json3-dev chromium poppler-utils pybind11-dev python3-pybind11 libpugixml-dev libzip-dev)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "installing: ${missing[*]}"
    sudo_cmd=""
    [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
    $sudo_cmd apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${missing[@]}" > /dev/null
fi
