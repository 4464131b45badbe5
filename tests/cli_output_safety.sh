#!/usr/bin/env bash
# Output safety of the gearloss command line (issue 13, part 5): exclusive temporary
# files, symbolic links written through, devices and FIFOs written directly, the same
# file for two outputs refused, every write to stdout checked, a closed pipe the end of the
# run (as SIGPIPE: exit 141, no output file; issue 37),
# signals and kill -9 during the write phase. Every file is written in a mktemp -d
# directory; the only devices written are /dev/null (-o, as root only) and /dev/full
# (stdout redirection).
# Usage: cli_output_safety.sh GEARLOSS_BINARY SOURCE_DIR
set -u
source "$(dirname "$0")/cli_common.sh" "$@"
case_file="$src/configs/transfer-box.yaml"
small=(--speed 600,700rpm --torque 150,200Nm --oil-temp 70degC)
no_temporary() { ! ls -a "$tmp" | grep -q '\.tmp\.'; }
cd "$tmp" || exit 1

# A symbolic link planted at the old predictable name PATH.tmp.PID is not followed (exec
# keeps the PID of the shell that planted it).
echo victim > victim.txt
bash -c 'ln -s victim.txt planted.csv.tmp.$$; exec "$0" map "$1" -o planted.csv' "$bin" "$case_file"
check "planted link: exit 0" test $? -eq 0
check "planted link: victim untouched" test "$(cat victim.txt)" = victim
check "planted link: output is a regular file" bash -c 'test -f planted.csv && ! test -L planted.csv'
check "planted link: output complete" test "$(wc -l < planted.csv)" -eq 10
rm -f planted.csv.tmp.*

# -o on a symbolic link: the link stays, the file it names is replaced; a dangling link
# creates its target.
"$bin" map "$case_file" -o target.csv
ln -s target.csv link.csv
"$bin" map "$case_file" "${small[@]}" -o link.csv
check "link: exit 0" test $? -eq 0
check "link: still a link to target.csv" test "$(readlink link.csv)" = target.csv
check "link: target updated" test "$(wc -l < target.csv)" -eq 5
mkdir sub
ln -s ../made.csv sub/dangling.csv
"$bin" map "$case_file" "${small[@]}" -o sub/dangling.csv
check "dangling relative link: target created" test -f made.csv -a -L sub/dangling.csv
ln -s /proc/self/fd/1 to-stdout
"$bin" map "$case_file" "${small[@]}" -o to-stdout > via-stdout.csv
check "link to /proc/self/fd/1: written to stdout" test "$(wc -l < via-stdout.csv)" -eq 5
check "link to /proc/self/fd/1: still a link" test -L to-stdout
check "links: no temporary left" no_temporary

# Mode (and, as root, owner) of an existing target are kept; a new file gets 0666 & ~umask.
"$bin" map "$case_file" -o moded.csv
chmod 0640 moded.csv
[ "$(id -u)" -eq 0 ] && chown 65534:65534 moded.csv
"$bin" map "$case_file" "${small[@]}" -o moded.csv
check "mode 0640 kept" test "$(stat -c %a moded.csv)" = 640
[ "$(id -u)" -eq 0 ] && check "owner kept (root)" test "$(stat -c %u:%g moded.csv)" = 65534:65534
(umask 027; exec "$bin" map "$case_file" "${small[@]}" -o new.csv)
check "new file: 0666 & ~umask" test "$(stat -c %a new.csv)" = 640

# A FIFO is written directly and stays a FIFO.
mkfifo fifo
cat fifo > from-fifo.csv &
reader=$!
"$bin" map "$case_file" "${small[@]}" -o fifo
check "fifo: exit 0" test $? -eq 0
wait $reader
check "fifo: still a FIFO" test -p fifo
check "fifo: content received" test "$(wc -l < from-fifo.csv)" -eq 5

# -o /dev/null: as root the old code replaced the device by a regular file.
if [ "$(id -u)" -eq 0 ]; then
    "$bin" map "$case_file" "${small[@]}" -o /dev/null
    check "-o /dev/null: exit 0" test $? -eq 0
    check "-o /dev/null: still a character device" test -c /dev/null
fi

# Two outputs on the same file: exit 2 naming both options, before any computation.
same() {  # same NAME MESSAGE_REGEX COMMAND...
    local name=$1 re=$2
    shift 2
    rm -f same.out
    "$@" 2> same.err
    local rc=$?
    check "$name: exit 2" test $rc -eq 2
    check "$name: message" grep -qE -- "$re" same.err
    check "$name: nothing written" test ! -e same.out
}
same "map -o X --json X" '--output and --json name the same file' "$bin" map "$case_file" -o same.out --json same.out
ln -sf same.out same-link
same "map through a link" '--output and --json name the same file' "$bin" map "$case_file" -o same-link --json ./same.out
same "cycle -o X --json X" '--output and --json name the same file' \
    "$bin" cycle "$src/configs/automatic-6speed.yaml" --cycle nedc --start-temp -10degC -o same.out --json same.out
"$bin" synth "$case_file" --speed 400,700,1000rpm --torque 100,200,300Nm --seed 2 -o rec.csv
same "diagnose --json X --residuals X" '--json and --residuals name the same file' \
    "$bin" diagnose "$case_file" rec.csv --json same.out --residuals same.out
touch hard1
ln hard1 hard2
same "map onto two hard links" '--output and --json' "$bin" map "$case_file" -o hard1 --json hard2

# Standard output on /dev/full: exit 3 with a message, for every command.
"$bin" map "$case_file" --shard 1/2 -o part1.csv
"$bin" map "$case_file" --shard 2/2 -o part2.csv
full() {  # full COMMAND ARGS...: stdout is /dev/full
    "$bin" "$@" > /dev/full 2> full.err
    local rc=$?
    check "$1 > /dev/full: exit 3" test $rc -eq 3
    check "$1 > /dev/full: message" grep -q 'cannot write to standard output: No space left on device' full.err
}
full check "$case_file"
full point "$case_file" --speed 800rpm --torque 250Nm
full diagnose "$case_file" rec.csv --bootstrap 4
full cycle "$src/configs/automatic-6speed.yaml" --cycle nedc --start-temp -10degC
full synth "$case_file" --speed 400,700rpm --torque 100Nm
full map "$case_file" "${small[@]}"
full merge part1.csv part2.csv
full compare "$case_file" --oil "$src/configs/oils/75W90-A.yaml" --oil "$src/configs/oils/75W140-A.yaml" --speed 600rpm --torque 150Nm
full mesh-profile "$src/configs/spur-seed000.yaml" --mesh m --speed 1600rpm --torque 720Nm
# ... and a file written with stdout: /dev/full fails too (exit 3, nothing replaced).
"$bin" diagnose "$case_file" rec.csv --bootstrap 4 --json d.json > /dev/full 2> /dev/null
check "diagnose > /dev/full: no JSON file" test ! -e d.json

# A map piped to head -1 (stdout closed after one line): the run ends as on SIGPIPE, exit
# 141 with a message, and its --json summary is not written (issue 37: before, exit 0).
many_speeds="$(python3 -c "print(','.join(str(300+i) for i in range(60)))")rpm"
many_torques="$(python3 -c "print(','.join(str(10+i) for i in range(60)))")Nm"
"$bin" map "$case_file" --speed "$many_speeds" --torque "$many_torques" --oil-temp 70degC --detail -o - \
    --json summary.json 2> pipe.err | head -1 > head.txt
rc=${PIPESTATUS[0]}
check "map | head -1: exit 141 (got $rc)" test "$rc" -eq 141
check "map | head -1: message" grep -q 'interrupted (signal 13: a reader closed its pipe)' pipe.err
check "map | head -1: header line" grep -q '^speed_in_rpm' head.txt
check "map | head -1: no JSON summary" test ! -e summary.json
# A pipe whose reader is already gone, for the commands printing text: exit 141, a message
# on stderr, no output file.
cat > closed_pipe.py <<'EOF'
import os, subprocess, sys
r, w = os.pipe()
os.close(r)
p = subprocess.run(sys.argv[1:], stdout=w, stderr=subprocess.PIPE)
sys.exit(0 if p.returncode == 141 and b"interrupted (signal 13" in p.stderr else 1)
EOF
check "check | closed pipe: exit 141, said" python3 closed_pipe.py "$bin" check "$case_file"
check "point | closed pipe: exit 141, said" python3 closed_pipe.py "$bin" point "$case_file" --speed 800rpm --torque 250Nm
python3 closed_pipe.py "$bin" cycle "$src/configs/automatic-6speed.yaml" --cycle nedc --start-temp -10degC --json cyc.json
check "cycle | closed pipe: exit 141, said" test $? -eq 0
check "cycle | closed pipe: no JSON" test ! -e cyc.json

# A signal during the write phase (the CSV is complete in its temporary file, the JSON
# summary waits for a reader on a FIFO): 143 / 130, the previous CSV kept, no temporary.
"$bin" map "$case_file" -o kept.csv
cp kept.csv kept-before.csv
mkfifo nobody-reads
write_phase_signal() {  # write_phase_signal SIGNAL EXIT_CODE
    "$bin" map "$case_file" "${small[@]}" -o kept.csv --json nobody-reads 2> signal.err &
    local pid=$!
    check "$1 in write phase: temporary file made" wait_for_temporary
    kill -"$1" $pid
    wait $pid
    local rc=$?
    check "$1 in write phase: exit $2" test $rc -eq "$2"
    check "$1 in write phase: previous file kept" cmp -s kept.csv kept-before.csv
    check "$1 in write phase: no temporary" no_temporary
}
write_phase_signal TERM 143
write_phase_signal INT 130

# kill -9 in the write phase leaves one temporary file, TARGET.tmp.gearloss-XXXXXX; the
# next run of the same output removes it at once: it is not locked, so its writer is gone
# (tests/cli_file_safety.sh: a running writer's locked temporary is kept).
"$bin" map "$case_file" "${small[@]}" -o kept.csv --json nobody-reads 2> /dev/null &
pid=$!
wait_for_temporary
{ kill -KILL $pid; wait $pid; } 2> /dev/null
check "kill -9: one temporary, named after the target" test "$(ls -a | grep -cE '^kept\.csv\.tmp\.gearloss-[A-Za-z0-9]{6}$')" -eq 1
check "kill -9: previous file kept" cmp -s kept.csv kept-before.csv
# The run's outputs are one transaction: the sidecar kept.csv.meta.json has its own temporary
# when the kill came after it was opened; the next run on each target removes it.
"$bin" map "$case_file" -o kept.csv
check "dead run's temporary removed by the next run" no_temporary

echo "$pass passed, $fail failed"
test $fail -eq 0
