#!/usr/bin/env bash
# Diagnosis residuals before/after (kept for compatibility): scripts/plot.sh diagnose.
# Usage: scripts/plot-residuals.sh RESIDUALS.csv OUT.png [--title TEXT]
exec "$(dirname "$0")/plot.sh" diagnose "$@"
