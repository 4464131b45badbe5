#!/usr/bin/env bash
# Installs Debian's python3-matplotlib, python3-numpy and python3-pandas if missing
# (scripts/install-deps.sh plots), then runs
# scripts/plot.py (its --help lists the pictures and options).
# Usage: scripts/plot.sh map|compare|cycle|diagnose CSV OUT.png|OUT.svg|OUT.pdf [--kind ...] [--levels ...] [--title TEXT]
set -euo pipefail
# Debian's own interpreter: the apt packages are importable there (not from a pyenv/venv python).
if ! /usr/bin/python3 -c "import matplotlib, numpy, pandas" 2> /dev/null; then
    "$(dirname "$0")/install-deps.sh" plots
fi
exec /usr/bin/python3 "$(dirname "$0")/plot.py" "$@"
