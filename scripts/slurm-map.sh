#!/usr/bin/env bash
#SBATCH --job-name=gearloss-map
#SBATCH --time=02:00:00
#SBATCH --output=gearloss-map-%A_%a.log
# One `gearloss map` job (a grid, or a sweep of variants) spread over a Slurm job array:
# each array task computes one shard K/N and writes OUTDIR/shard-K.csv; `gearloss merge`
# joins the shards into the same CSV a single run would write (docs/slurm.md).
#
#   jobid=$(sbatch --parsable --array=1-16 scripts/slurm-map.sh --shards 16 configs/transfer-box.yaml out/ [map options])
#   sbatch --dependency=afterok:$jobid --kill-on-invalid-dep=yes --wrap "build/app/gearloss merge out/shard-*.csv -o map.csv"
#   sbatch --array=5 scripts/slurm-map.sh --shards 16 configs/transfer-box.yaml out/ [same options]   # redo shard 5
#
# Options (before CONFIG):
#   --shards N     the job has N shards, array indices 1..N (index K computes shard K/N). Env GEARLOSS_SHARDS.
#   --array SPEC   the job's whole array as given to sbatch (0-15, 1-31:2, 1-8,12): shard K/N is the task's
#                  position K among the N indices. Env GEARLOSS_ARRAY.
# Without either, the running array is the whole job (its indices MIN-MAX:STEP, in order, are shards
# 1..COUNT); a one-task array is refused then, since it is most likely the resubmission of one index
# of a larger job and would compute that whole job as shard 1/1.
#
# sbatch runs a spooled copy of this script, so the binary is $GEARLOSS, else
# $SLURM_SUBMIT_DIR/build/app/gearloss, else the installed one (cmake --install), else
# `gearloss` on PATH. Threads: the task's --cpus-per-task (1 unless given to sbatch).
# A shard is written next to its final name and moved into place only when complete; an
# existing shard-K.csv of a different job (other first line) is never replaced.
set -euo pipefail
die() { echo "slurm-map.sh: $*" >&2; exit 2; }

installed_bin="@GEARLOSS_INSTALLED_BIN@"  # the prefix's bin/gearloss, filled in by cmake --install
spec=${GEARLOSS_ARRAY:-}
shards=${GEARLOSS_SHARDS:-}
while [ $# -gt 0 ]; do
    case $1 in
        --shards) [ $# -ge 2 ] || die "--shards needs a value"; shards=$2; shift 2 ;;
        --shards=*) shards=${1#--shards=}; shift ;;
        --array) [ $# -ge 2 ] || die "--array needs a value"; spec=$2; shift 2 ;;
        --array=*) spec=${1#--array=}; shift ;;
        *) break ;;
    esac
done
if [ $# -lt 2 ]; then
    echo "usage: sbatch --array=1-N $0 [--shards N | --array SPEC] CONFIG OUTDIR [gearloss map options...]" >&2
    exit 1
fi
config=$1
outdir=$2
shift 2
: "${SLURM_ARRAY_TASK_ID:?run as a Slurm array job (sbatch --array=1-N)}"
id=$SLURM_ARRAY_TASK_ID
isint() { [[ $1 =~ ^[0-9]+$ ]]; }
isint "$id" || die "SLURM_ARRAY_TASK_ID '$id' is not an index"

# The job's indices, ascending: from --array SPEC (or --shards N = 1-N).
indices=()
if [ -n "$shards" ]; then
    isint "$shards" && [ "$shards" -ge 1 ] || die "--shards '$shards' is not a positive count"
    [ -z "$spec" ] || die "give --shards or --array, not both"
    spec="1-$shards"
fi
if [ -n "$spec" ]; then
    IFS=, read -ra parts <<< "${spec%%\%*}"  # "%4" (at most 4 at a time) does not change the indices
    for part in "${parts[@]}"; do
        if [[ $part =~ ^([0-9]+)-([0-9]+)(:([0-9]+))?$ ]]; then
            a=$((10#${BASH_REMATCH[1]})) b=$((10#${BASH_REMATCH[2]})) s=$((10#${BASH_REMATCH[4]:-1}))
            [ "$s" -ge 1 ] && [ "$a" -le "$b" ] || die "--array '$spec': '$part' is empty"
            for ((i = a; i <= b; i += s)); do indices+=("$i"); done
        elif isint "$part"; then
            indices+=("$((10#$part))")
        else
            die "--array '$spec': '$part' is not N, A-B or A-B:S"
        fi
    done
    mapfile -t indices < <(printf '%s\n' "${indices[@]}" | sort -n -u)
    n=${#indices[@]}
    k=0
    for i in "${!indices[@]}"; do
        if [ "${indices[$i]}" -eq "$id" ]; then k=$((i + 1)); break; fi
    done
    [ "$k" -ge 1 ] || die "array index $id is not one of the job's ($spec)"
else
    min=${SLURM_ARRAY_TASK_MIN:?} max=${SLURM_ARRAY_TASK_MAX:?}
    step=${SLURM_ARRAY_TASK_STEP:-1} n=${SLURM_ARRAY_TASK_COUNT:-}
    [ -n "$n" ] || n=$(((max - min) / step + 1))
    if [ "$n" -eq 1 ]; then
        die "a one-task array (index $id) is taken for the resubmission of one shard: give the job's shard count (--shards N or --array SPEC; env GEARLOSS_SHARDS/GEARLOSS_ARRAY)"
    fi
    if [ $(((id - min) % step)) -ne 0 ] || [ "$n" -ne $(((max - min) / step + 1)) ]; then
        die "the array ($min-$max, step $step, $n tasks) is not evenly spaced: give it with --array SPEC"
    fi
    k=$(((id - min) / step + 1))
fi

# The binary: sbatch runs a copy of this script from its spool folder, so the script's own
# location says nothing; it is looked up where the job was submitted from.
bin=${GEARLOSS:-}
if [ -z "$bin" ]; then
    here=$(cd "$(dirname "$0")/.." 2> /dev/null && pwd || true)
    for c in "${SLURM_SUBMIT_DIR:+$SLURM_SUBMIT_DIR/build/app/gearloss}" "$installed_bin" "${here:+$here/build/app/gearloss}"; do
        if [ -n "$c" ] && [ -f "$c" ] && [ -x "$c" ]; then bin=$c; break; fi
    done
fi
if [ -z "$bin" ]; then
    bin=$(command -v gearloss) || die "gearloss not found: set GEARLOSS, build it in the submit folder (build/app/gearloss), install it or put it on PATH"
fi

threads=()
if [ -n "${SLURM_CPUS_PER_TASK:-}" ]; then threads=(--threads "$SLURM_CPUS_PER_TASK"); fi
mkdir -p "$outdir"
final="$outdir/shard-$k.csv"
work="$outdir/.shard-$k.${SLURM_JOB_ID:-$$}"
rm -rf "$work"
mkdir "$work"
trap 'rm -rf "$work"' EXIT
echo "slurm-map.sh: array index $id is shard $k/$n -> $final ($bin)"
"$bin" map "$config" --shard "$k/$n" "${threads[@]}" -o "$work/shard-$k.csv" "$@"
if [ -f "$final" ]; then
    old=$(head -n 1 "$final")
    new=$(head -n 1 "$work/shard-$k.csv")
    if [[ $old == "# gearloss shard "* ]] && [ "$old" != "$new" ]; then
        was=${old#"# gearloss shard "}
        die "$final holds shard ${was%%:*} of another job (its first line differs from this shard $k/$n's); kept, this one not written"
    fi
fi
[ ! -f "$work/shard-$k.csv.meta.json" ] || mv -f "$work/shard-$k.csv.meta.json" "$final.meta.json"
mv -f "$work/shard-$k.csv" "$final"
