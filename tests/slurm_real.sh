#!/usr/bin/env bash
# scripts/slurm-map.sh under a REAL single-node Slurm (docs/slurm.md), not an emulated array:
#  - munged, slurmctld and slurmd are started here with a private key, slurm.conf, state and
#    spool folders in a temporary folder and free ports, and stopped by their PIDs on exit
#    (ProctrackType=proctrack/linuxproc: no cgroup freezer needed; TaskPlugin=task/none);
#  - the documented flow from a submit folder holding build/app/gearloss (GEARLOSS unset, so
#    the spooled script must find the binary from SLURM_SUBMIT_DIR): a 4-task array and the
#    afterok merge; the merged map equals a single run byte for byte;
#  - a step array (1-7:2, 4 tasks) without --shards: shards 1..4 of 4, merged equal;
#  - a failed task (shard 3's file already holds a shard of another job, which the script
#    refuses to replace): the afterok merge with --kill-on-invalid-dep=yes is cancelled rather
#    than left pending, the afterany merge refuses the missing shard, the other job's shard is
#    kept byte for byte;
#  - resubmitting one index: without --shards it is refused (the old script computed the
#    whole job as shard 1/1 over a good shard-1.csv); with --shards 4 (and with --array 1-7:2
#    for the step array) it recomputes only its shard, the others untouched, and the merge
#    equals the single run.
# Slurm and MUNGE are installed on first use (scripts/install-deps.sh slurm); exit 77 (ctest
# SKIP_RETURN_CODE) only when they are missing and this user cannot run apt.
# Usage: slurm_real.sh GEARLOSS SOURCE_DIR
bin=$1
src=$2
need() { command -v slurmctld > /dev/null && command -v slurmd > /dev/null && command -v sbatch > /dev/null &&
    command -v munged > /dev/null && command -v mungekey > /dev/null; }
# First use installs them (scripts/install-deps.sh slurm) where this user may run apt.
if ! need && { [ "$(id -u)" -eq 0 ] || sudo -n true 2> /dev/null; }; then
    "$src/scripts/install-deps.sh" slurm || echo "installing Slurm and MUNGE failed"
fi
if ! need; then
    echo "SKIPPED: Slurm and MUNGE are not installed and this user cannot install them (Debian packages slurm-wlm and munge: scripts/install-deps.sh slurm)"
    exit 77
fi
if [ "$(id -u)" -ne 0 ]; then
    echo "SKIPPED: a private slurmd must run as root (it starts the jobs' steps)"
    exit 77
fi

source "$(dirname "$0")/cli_common.sh" "$@"  # tmp, check, pass/fail (its trap is replaced below)
chmod 700 "$tmp"
pids=()
cleanup() {
    local p
    for p in "${pids[@]}"; do kill "$p" 2> /dev/null; done
    for p in "${pids[@]}"; do
        for _ in $(seq 50); do kill -0 "$p" 2> /dev/null || break; sleep 0.1; done
        kill -9 "$p" 2> /dev/null
    done
    rm -rf "$tmp"
}
trap cleanup EXIT
logs() {
    echo "--- slurmctld.log (end)"; tail -n 30 "$tmp/slurmctld.log" 2> /dev/null
    echo "--- slurmd.log (end)"; tail -n 30 "$tmp/slurmd.log" 2> /dev/null
}
free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# MUNGE with its own key and socket.
mkdir -p "$tmp/munge" "$tmp/state" "$tmp/spool"
chmod 700 "$tmp/munge"
mungekey --create --keyfile="$tmp/munge/munge.key" > /dev/null 2>&1 ||
    { dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 2> /dev/null && chmod 400 "$tmp/munge/munge.key"; }
socket="$tmp/munge/munge.socket"
munged --foreground --force --socket="$socket" --key-file="$tmp/munge/munge.key" --log-file="$tmp/munge/munged.log" \
    --pid-file="$tmp/munge/munged.pid" --seed-file="$tmp/munge/munged.seed" > /dev/null 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$socket" ] && break; sleep 0.1; done
if [ ! -S "$socket" ]; then
    echo "FAILED: munged did not start"; cat "$tmp/munge/munged.log" 2> /dev/null; exit 1
fi

host=$(hostname -s)
cpus=$(nproc)
export SLURM_CONF="$tmp/slurm.conf"
cat > "$SLURM_CONF" << EOF
ClusterName=gearloss-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MinJobAge=600
PlugStackConfig=$tmp/plugstack.conf
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
: > "$tmp/plugstack.conf"
slurmctld -D -i -f "$SLURM_CONF" > "$tmp/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$host" > "$tmp/slurmd.out" 2>&1 &
pids+=($!)
up=""
for _ in $(seq 300); do
    state=$(sinfo -h -N -o %T 2> /dev/null | head -n 1)
    [ "$state" = idle ] && { up=1; break; }
    sleep 0.2
done
if [ -z "$up" ]; then
    echo "FAILED: the single-node Slurm did not come up (node state '${state:-none}')"
    cat "$tmp/slurmctld.out" "$tmp/slurmd.out"; logs; exit 1
fi

job_state() { scontrol show job -o "$1" 2> /dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 | sort -u | tr '\n' ' '; }
settled() {  # settled JOBID...: waits (60 s at most) until none of the jobs is pending or running
    local j s
    for _ in $(seq 300); do
        s=""
        for j in "$@"; do s+=$(job_state "$j"); done
        [[ $s =~ PENDING|RUNNING|CONFIGURING|COMPLETING|SUSPENDED ]] || return 0
        sleep 0.2
    done
    echo "still not settled after 60 s: $s"
    return 1
}

# The submit folder as a user has it: the build's binary, the shipped configs and scripts.
sub="$tmp/submit"
mkdir -p "$sub/build/app"
ln -s "$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")" "$sub/build/app/gearloss"
ln -s "$src/configs" "$sub/configs"
ln -s "$src/scripts" "$sub/scripts"
cd "$sub" || exit 1
unset GEARLOSS GEARLOSS_SHARDS GEARLOSS_ARRAY
grid=(--speed 400,600,800,1000,1200rpm --torque 100,150,200,250Nm)
build/app/gearloss map configs/transfer-box.yaml "${grid[@]}" -o single.csv

# The documented flow: 4 tasks, the afterok merge.
jobid=$(sbatch --parsable --array=1-4 scripts/slurm-map.sh --shards 4 configs/transfer-box.yaml out/ "${grid[@]}")
check "sbatch array accepted" test -n "$jobid"
mergeid=$(sbatch --parsable --dependency=afterok:"$jobid" --kill-on-invalid-dep=yes --output=merge-%j.log \
    --wrap "build/app/gearloss merge out/shard-*.csv -o map.csv")
check "sbatch merge accepted" test -n "$mergeid"
settled "$jobid" "$mergeid"
check "flow: every task completed" test "$(job_state "$jobid")" = "COMPLETED "
check "flow: merge completed" test "$(job_state "$mergeid")" = "COMPLETED "
check "flow: 4 shards" test "$(ls out/shard-*.csv | wc -l)" -eq 4
check "flow: binary found from SLURM_SUBMIT_DIR" grep -qF "($sub/build/app/gearloss)" gearloss-map-"${jobid}"_1.log
check "flow: merged map byte-identical to a single run" cmp -s single.csv map.csv
if ! cmp -s single.csv map.csv; then cat gearloss-map-"${jobid}"_*.log merge-*.log 2> /dev/null; logs; fi

# A step array without --shards: indices 1,3,5,7 are shards 1..4 of 4.
stepid=$(sbatch --parsable --array=1-7:2 scripts/slurm-map.sh configs/transfer-box.yaml step/ "${grid[@]}")
settled "$stepid"
check "step array: every task completed" test "$(job_state "$stepid")" = "COMPLETED "
check "step array: shards 1..4 written" test "$(cd step && ls shard-*.csv | tr '\n' ' ')" = "shard-1.csv shard-2.csv shard-3.csv shard-4.csv "
check "step array: index 5 is shard 3/4" grep -q "^# gearloss shard 3/4:" step/shard-3.csv
build/app/gearloss merge step/shard-*.csv -o step-map.csv 2> /dev/null
check "step array: merged map byte-identical to a single run" cmp -s single.csv step-map.csv

# A failed task: shard-3.csv of the output folder holds shard 3/4 of another job (another oil
# temperature); the task refuses to replace it and fails.
mkdir -p bad
build/app/gearloss map configs/transfer-box.yaml "${grid[@]}" --oil-temp 60degC --shard 3/4 -o bad/shard-3.csv
cp bad/shard-3.csv foreign-shard-3.csv
badid=$(sbatch --parsable --array=1-4 scripts/slurm-map.sh --shards 4 configs/transfer-box.yaml bad/ "${grid[@]}")
okmerge=$(sbatch --parsable --dependency=afterok:"$badid" --kill-on-invalid-dep=yes \
    --wrap "build/app/gearloss merge bad/shard-*.csv -o bad-afterok.csv")
anymerge=$(sbatch --parsable --dependency=afterany:"$badid" --output=anymerge-%j.log \
    --wrap "build/app/gearloss merge bad/shard-[0-9].csv -o bad-afterany.csv")
settled "$badid" "$okmerge" "$anymerge"
check "failed task: task 3 failed" bash -c "scontrol show job -o '$badid' | grep 'ArrayTaskId=3 ' | grep -q 'JobState=FAILED'"
check "failed task: the others completed" test "$(scontrol show job -o "$badid" | grep -c 'JobState=COMPLETED')" -eq 3
check "failed task: says why" grep -q "holds shard 3/4 of another job" gearloss-map-"${badid}"_3.log
check "failed task: the other job's shard kept" cmp -s foreign-shard-3.csv bad/shard-3.csv
check "failed task: afterok merge cancelled, not pending" test "$(job_state "$okmerge")" = "CANCELLED "
check "failed task: afterok merge cancelled for its dependency" bash -c "scontrol show job -o '$okmerge' | grep -q 'Reason=DependencyNeverSatisfied'"
check "failed task: afterok merge wrote nothing" test ! -e bad-afterok.csv
check "failed task: afterany merge failed" test "$(job_state "$anymerge")" = "FAILED "
check "failed task: afterany merge names the mixed shard" grep -q "shard" anymerge-"$anymerge".log
check "failed task: afterany merge wrote nothing" test ! -e bad-afterany.csv

# Resubmitting one index. Without the shard count it is refused and writes nothing.
rm -f bad/shard-3.csv bad/shard-3.csv.meta.json
stamp() { stat -c '%Y %s %n' out/shard-*.csv bad/shard-*.csv step/shard-*.csv | sort -k3; }
sleep 1.1  # a rewritten file would show a new modification time
before=$(stamp)
cp out/shard-1.csv good-shard-1.csv
loneid=$(sbatch --parsable --array=2 scripts/slurm-map.sh configs/transfer-box.yaml out/ "${grid[@]}")
settled "$loneid"
check "resubmission without --shards: refused" test "$(job_state "$loneid")" = "FAILED "
check "resubmission without --shards: says why" grep -q "one-task array" gearloss-map-"${loneid}"_2.log
check "resubmission without --shards: good shards untouched" test "$(stamp)" = "$before"
# With it: only shard 3 is computed, into the folder whose task failed; then the merge.
redo=$(sbatch --parsable --array=3 scripts/slurm-map.sh --shards 4 configs/transfer-box.yaml bad/ "${grid[@]}")
redomerge=$(sbatch --parsable --dependency=afterok:"$redo" --kill-on-invalid-dep=yes \
    --wrap "build/app/gearloss merge bad/shard-*.csv -o bad-map.csv")
settled "$redo" "$redomerge"
check "resubmitted index: completed" test "$(job_state "$redo")" = "COMPLETED "
after=$(stamp)
check "resubmitted index: only shard 3 written" test "$(diff <(echo "$before") <(echo "$after") | grep -c '^>')" -eq 1
check "resubmitted index: it is shard 3/4" grep -q "^# gearloss shard 3/4:" bad/shard-3.csv
check "resubmitted index: merged map byte-identical to a single run" cmp -s single.csv bad-map.csv
# Index 5 of the step array again, named by its array: shard 3/4, equal to the first one.
cp step/shard-3.csv step-shard-3.csv
redostep=$(sbatch --parsable --array=5 scripts/slurm-map.sh --array 1-7:2 configs/transfer-box.yaml step/ "${grid[@]}")
settled "$redostep"
check "step array index 5 again: completed" test "$(job_state "$redostep")" = "COMPLETED "
check "step array index 5 again: the same shard 3/4" cmp -s step-shard-3.csv step/shard-3.csv
check "good shard 1 never replaced" cmp -s good-shard-1.csv out/shard-1.csv

echo "slurm_real: $pass passed, $fail failed"
[ "$fail" -eq 0 ] || { logs; exit 1; }
