#!/usr/bin/env bash
#SBATCH --job-name=gearloss-map
#SBATCH --cpus-per-task=4
#SBATCH --time=02:00:00
#SBATCH --output=gearloss-map-%A_%a.log
# One `gearloss map` job (a grid, or a sweep of variants) spread over a Slurm job array:
# array task K of N computes shard K/N; `gearloss merge` joins the shards into the same
# CSV a single run would write.
#
#   jobid=$(sbatch --parsable --array=1-16 scripts/slurm-map.sh configs/transfer-box.yaml out/ [map options])
#   sbatch --dependency=afterok:$jobid --wrap "gearloss merge out/shard-*.csv -o map.csv"
#
# The binary is $GEARLOSS, else build/app/gearloss next to this script, else `gearloss` on PATH.
set -euo pipefail
if [ $# -lt 2 ]; then
    echo "usage: sbatch --array=1-N $0 CONFIG OUTDIR [gearloss map options...]" >&2
    exit 1
fi
config=$1
outdir=$2
shift 2
: "${SLURM_ARRAY_TASK_ID:?run as a Slurm array job (sbatch --array=1-N)}"
min=${SLURM_ARRAY_TASK_MIN:-1}
max=${SLURM_ARRAY_TASK_MAX:-$SLURM_ARRAY_TASK_ID}
n=${SLURM_ARRAY_TASK_COUNT:-$((max - min + 1))}
k=$((SLURM_ARRAY_TASK_ID - min + 1))
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${GEARLOSS:-}
if [ -z "$bin" ]; then
    if [ -x "$here/build/app/gearloss" ]; then bin="$here/build/app/gearloss"; else bin=gearloss; fi
fi
threads=()
if [ -n "${SLURM_CPUS_PER_TASK:-}" ]; then threads=(--threads "$SLURM_CPUS_PER_TASK"); fi
mkdir -p "$outdir"
exec "$bin" map "$config" --shard "$k/$n" "${threads[@]}" -o "$outdir/shard-$k.csv" "$@"
