#!/usr/bin/env bash
# No output may damage a file (issue 37, item 1): an output path that is an input, a file an
# input names, the running program or another output of the same run is refused (exit 2,
# both named) for every derived name (VECTO per-gear files, sidecars) and every command;
# concurrent runs onto one output leave a CSV and a sidecar of the same run; a dead run's
# temporary is removed by the next run on that target; SIGHUP, SIGQUIT and SIGPIPE end a run
# like SIGTERM; a reader that closes standard output ends a streamed map at once.
# Every file is written in a mktemp -d directory (cli_common.sh), never onto /dev/...; the
# program-overwrite checks run a COPY of the binary.
# Usage: cli_file_safety.sh GEARLOSS_BINARY SOURCE_DIR
set -u
source "$(dirname "$0")/cli_common.sh" "$@"
cd "$tmp" || exit 1
no_temporary() { ! find . -name '*.tmp.gearloss-*' | grep -q .; }

# refused NAME FILE_KEPT MESSAGE_REGEX COMMAND...: exit 2, the message names both files and
# FILE_KEPT is byte for byte what it was (then it is put back as it was, for the next case).
refused() {
    local name=$1 kept=$2 re=$3
    shift 3
    cp "$kept" kept.before
    "$@" > refused.out 2> refused.err
    local rc=$?
    check "$name: exit 2 (got $rc)" test $rc -eq 2
    check "$name: message" grep -qE -- "$re" refused.err
    check "$name: $kept unchanged" cmp -s "$kept" kept.before
    check "$name: no temporary" no_temporary
    cp kept.before "$kept"  # each case on its own, whatever the one before did
}

# 1. VECTO per-gear files t_<gear>.vtlm: the case itself, or its oil file.
mkdir vecto && cd vecto || exit 1
cp -r "$src/configs/oils" .
cp "$src/configs/manual-6speed.yaml" t_g1.vtlm
grid=(--speed 1000,2000rpm --torque 100,200Nm --oil-temp 70degC --format vecto)
refused "vecto: t_g1.vtlm is the case" t_g1.vtlm "--output \(gear g1\) 't_g1.vtlm' is the input config 't_g1.vtlm'" \
    "$bin" map t_g1.vtlm "${grid[@]}" -o t.vtlm
cp "$src/configs/manual-6speed.yaml" case.yaml
cp oils/75W90-A.yaml t_g2.vtlm
sed -i 's|^oil: .*|oil: t_g2.vtlm|' case.yaml
refused "vecto: t_g2.vtlm is the case's oil" t_g2.vtlm "--output \(gear g2\) 't_g2.vtlm' is the input named by the case at 'oil'" \
    "$bin" map case.yaml "${grid[@]}" -o t.vtlm
cp "$src/configs/manual-6speed.yaml" plain.yaml
refused "vecto: the sidecar t_g3.vtlm.meta.json is --oil (a link to it)" oils/75W140-A.yaml \
    "--output \(gear g3\) \(its metadata t_g3.vtlm.meta.json\) 't_g3.vtlm.meta.json' is the input --oil" \
    bash -c 'ln -s oils/75W140-A.yaml t_g3.vtlm.meta.json && "$0" map plain.yaml --oil t_g3.vtlm.meta.json "$@" -o t.vtlm' \
    "$bin" "${grid[@]}"
rm -f t_g3.vtlm.meta.json
"$bin" map plain.yaml "${grid[@]}" -o ok.vtlm
check "vecto: six gears written when nothing collides" test "$(ls ok_g?.vtlm | wc -l)" -eq 6
cd "$tmp" || exit 1

# 2. diagnose --json / --residuals / --write-config onto the case's oil file, an oil named in
#    the recordings' oil column and the case's bearing catalogue.
mkdir diag && cd diag || exit 1
cp -r "$src/configs/oils" .
cp "$src/configs/bearings/catalogue.yaml" mycat.yaml
{ echo "bearing_catalogue: mycat.yaml"; cat "$src/configs/transfer-box.yaml"; } > case.yaml
"$bin" synth case.yaml --speed 600,900rpm --torque 100,200Nm -o rec.csv
cp oils/75W140-A.yaml oilB.yaml
awk 'NR == 1 { print $0 ",oil"; next } /^#/ { print; next } { print $0 ",oilB.yaml" }' rec.csv > rec-oil.csv
refused "diagnose --json onto the case's oil" oils/75W90-A.yaml "--json 'oils/75W90-A.yaml' is the input named by the case at 'oil'" \
    "$bin" diagnose case.yaml rec.csv --json oils/75W90-A.yaml
refused "diagnose --residuals onto the case's oil" oils/75W90-A.yaml "--residuals 'oils/75W90-A.yaml' is the input named by the case" \
    "$bin" diagnose case.yaml rec.csv --residuals oils/75W90-A.yaml
refused "diagnose --write-config onto an oil of the recordings' oil column" oilB.yaml \
    "--write-config 'oilB.yaml' is the input named in the recordings' oil column \(line 2\) '(\./)?oilB.yaml'" \
    "$bin" diagnose case.yaml rec-oil.csv --write-config oilB.yaml
refused "diagnose --json onto the bearing catalogue" mycat.yaml "--json 'mycat.yaml' is the input named by the case at 'bearing_catalogue'" \
    "$bin" diagnose case.yaml rec.csv --json mycat.yaml
refused "diagnose --write-config onto the bearing catalogue (through a link)" mycat.yaml "is the input named by the case at 'bearing_catalogue'" \
    bash -c 'ln -sf mycat.yaml cat-link && "$0" diagnose case.yaml rec.csv --write-config cat-link' "$bin"
cd "$tmp" || exit 1

# ... and cycle --json onto the file a named cycle is read from (the case's cycles/ folder).
mkdir cyc && cd cyc || exit 1
cp -r "$src/configs/oils" . && mkdir cycles && cp "$src/configs/cycles/nedc.csv" cycles/
cp "$src/configs/automatic-6speed.yaml" case.yaml
refused "cycle --json onto the named cycle's file" cycles/nedc.csv "--json 'cycles/nedc.csv' is the input --cycle nedc \(its file\)" \
    "$bin" cycle case.yaml --cycle nedc --start-temp 20degC --json cycles/nedc.csv
cd "$tmp" || exit 1

# 3. The program itself: a copy of the binary, run from here, asked to write onto itself
#    (as /proc/self/exe and by its path).
mkdir prog && cp "$bin" prog/gl && cp -r "$src/configs/oils" prog/ && cp "$src/configs/transfer-box.yaml" prog/case.yaml
cd prog || exit 1
"$PWD/gl" synth case.yaml --speed 600,900rpm --torque 100,200Nm -o rec.csv
small=(--speed 600rpm --torque 100Nm --oil-temp 70degC)
refused "map --json /proc/self/exe" gl "--json '/proc/self/exe' is the running program '.*/prog/gl'" \
    "$PWD/gl" map case.yaml "${small[@]}" -o m.csv --json /proc/self/exe
refused "map -o the program" gl "--output '.*gl' is the running program" "$PWD/gl" map case.yaml "${small[@]}" -o "$PWD/gl"
refused "map sidecar onto the program" gl "--output \(its metadata gl2.meta.json\) 'gl2.meta.json' is the running program" \
    bash -c 'ln -sf gl gl2.meta.json && "$PWD/gl" map case.yaml "$@" -o gl2' _ "${small[@]}"
rm -f gl2.meta.json
refused "report -o /proc/self/exe" gl "--output '/proc/self/exe' is the running program" \
    "$PWD/gl" report case.yaml "${small[@]}" --no-spread -o /proc/self/exe
refused "diagnose --write-config onto the program" gl "--write-config 'gl' is the running program" \
    "$PWD/gl" diagnose case.yaml rec.csv --write-config gl
refused "point --json /proc/self/exe" gl "running program" "$PWD/gl" point case.yaml --speed 600rpm --torque 100Nm --json /proc/self/exe
cd "$tmp" || exit 1

# 4. Concurrent writers of one -o: 30 pairs of maps with different grids (one speed, two
#    speeds); the CSV and its sidecar must come from the same run (the sidecar's command line
#    names the speeds the CSV holds).
cp -r "$src/configs/oils" . && cp "$src/configs/transfer-box.yaml" tb.yaml
torques="$(python3 -c "print(','.join(str(10 + 5 * i) for i in range(40)))")Nm"
mismatch=0
for i in $(seq 30); do
    "$bin" map tb.yaml --speed 600rpm --torque "$torques" --oil-temp 70degC -o race.csv 2> /dev/null &
    a=$!
    "$bin" map tb.yaml --speed 600,700rpm --torque "$torques" --oil-temp 70degC -o race.csv 2> /dev/null &
    b=$!
    wait $a
    wait $b
    python3 - race.csv << 'EOF' || mismatch=$((mismatch + 1))
import json, sys
rows = [l for l in open(sys.argv[1]) if l[:1].isdigit()]
speeds = "600,700rpm" if len(rows) == 80 else "600rpm"
meta = json.load(open(sys.argv[1] + ".meta.json"))
sys.exit(0 if speeds in meta["command_line"] else 1)
EOF
done
check "concurrent writers: CSV and sidecar from one run ($mismatch of 30 mixed)" test $mismatch -eq 0
check "concurrent writers: no temporary" no_temporary

# 5. A temporary left by a dead run (kill -9, or SIGUSR1 that nothing handles) is removed by
#    the next run on that target at once, whatever its age: unlocked means its writer is gone.
mkfifo nobody-reads
for sig in KILL USR1; do
    "$bin" map tb.yaml "${small[@]}" -o kept.csv --json nobody-reads 2> /dev/null &
    pid=$!
    wait_for_temporary
    { kill -"$sig" $pid; wait $pid; } 2> /dev/null
    check "kill -$sig: its temporary left" test "$(ls -a | grep -c '^kept\.csv\.tmp\.gearloss-')" -ge 1
    "$bin" map tb.yaml "${small[@]}" -o kept.csv
    check "kill -$sig: the next run on kept.csv removed the dead run's temporary" no_temporary
done
# ... but a running writer's temporary is left alone (it is locked).
"$bin" map tb.yaml "${small[@]}" -o kept.csv --json nobody-reads 2> /dev/null &
pid=$!
wait_for_temporary
"$bin" map tb.yaml "${small[@]}" -o kept.csv
check "a running writer's temporary is kept" test "$(ls -a | grep -c '^kept\.csv\.tmp\.gearloss-')" -ge 1
kill -TERM $pid
wait $pid 2> /dev/null
check "the writer, ended by SIGTERM, removed its temporaries" no_temporary

# 6. SIGHUP, SIGQUIT and SIGPIPE end a run like SIGTERM: 128 + the signal, the message, no
#    output or temporary file, within the deadline.
list() { python3 -c "print(','.join(f'{$1 + $2 * i:g}' for i in range($3)))"; }
spur="$src/configs/spur-seed000.yaml"
speeds="$(list 200 10 150)rpm"
spur_torques="$(list 100 4.5 150)Nm"
deadline_ms=${SIGNAL_DEADLINE_MS:-3000}
for s in HUP:1 QUIT:3 PIPE:13 TERM:15; do
    sig=${s%%:*} num=${s##*:}
    rm -rf out && mkdir out
    "$bin" map "$spur" --speed "$speeds" --torque "$spur_torques" -o out/map.csv --json out/map.json 2> sig.err &
    pid=$!
    check "SIG$sig: catches it" await_handler $pid "$sig"
    sleep 0.5
    check "SIG$sig: still running after 0.5 s" kill -0 $pid
    kill -"$sig" $pid
    t0=$(date +%s%N)
    while kill -0 $pid 2> /dev/null && [ $(($(date +%s%N) - t0)) -lt $((deadline_ms * 1000000)) ]; do sleep 0.02; done
    if kill -0 $pid 2> /dev/null; then
        check "SIG$sig: ends the run within $deadline_ms ms" false
        kill -KILL $pid
    fi
    wait $pid 2> /dev/null
    rc=$?
    check "SIG$sig: exit $((128 + num)) (got $rc)" test $rc -eq $((128 + num))
    check "SIG$sig: says it was interrupted" grep -q "interrupted (signal $num" sig.err
    check "SIG$sig: no output or temporary file" test -z "$(ls -A out)"
done

# A SIGHUP ignored from the start (nohup) stays ignored: the run goes on.
nohup "$bin" map "$spur" --speed "$speeds" --torque "$spur_torques" -o nohup.csv > /dev/null 2>&1 &
pid=$!
check "nohup: catches SIGTERM" await_handler $pid TERM
sleep 0.5
kill -HUP $pid 2> /dev/null
sleep 0.5
check "nohup: SIGHUP ignored, still running" kill -0 $pid
kill -TERM $pid 2> /dev/null
wait $pid 2> /dev/null
rm -f nohup.csv

# 7. A reader that closes standard output ends a streamed map at once: 4 million points of the
#    transfer box (minutes of work) piped to head -2 end within a few seconds (1 s is the
#    contract; 5 s for a loaded CI machine), non-zero, with a message.
big_speeds="$(list 300 1 2000)rpm"
big_torques="$(list 10 0.1 2000)Nm"
t0=$(date +%s%N)
timeout 60 "$bin" map "$src/configs/transfer-box.yaml" --speed "$big_speeds" --torque "$big_torques" -o - \
    --json pipe.json 2> pipe.err | head -2 > head.txt
rc=${PIPESTATUS[0]}
ms=$((($(date +%s%N) - t0) / 1000000))
check "map BIG | head -2: ends within 5 s (took $ms ms)" test $ms -lt 5000
check "map BIG | head -2: exit 141 (got $rc)" test $rc -eq 141
check "map BIG | head -2: message" grep -q "interrupted (signal 13: a reader closed its pipe)" pipe.err
check "map BIG | head -2: the two lines arrived" test "$(wc -l < head.txt)" -eq 2
check "map BIG | head -2: no summary written" test ! -e pipe.json
check "map BIG | head -2: no temporary" no_temporary

# The same, timed from the moment the reader closes the pipe (the contract's second; 2 s here
# for a loaded machine): a reader that takes two lines, then closes.
cat > close_after_two.py << 'EOF'
import subprocess, sys, time
p = subprocess.Popen(sys.argv[1:], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
p.stdout.readline(); p.stdout.readline()
p.stdout.close()
t = time.time()
try:
    rc = p.wait(timeout=10)
except subprocess.TimeoutExpired:
    p.kill(); p.wait(); rc = None
print(f"{rc} {(time.time() - t) * 1000:.0f}")
EOF
read -r rc ms < <(python3 close_after_two.py "$bin" map "$src/configs/transfer-box.yaml" --speed "$big_speeds" \
    --torque "$big_torques" -o -)
check "map BIG, reader closes after two lines: exit 141 (got $rc)" test "$rc" = 141
check "map BIG, reader closes after two lines: ends within 2 s of it (took $ms ms)" test "$ms" -lt 2000

# 8. Standard output is an output of every command: when it is a regular file that is an
#    input (`1<> case.yaml` opens the case for writing without emptying it), the text the
#    command prints (check, point, the cycle summary, the diagnosis, -o -) would go into the
#    input; refused before anything is written. A plain `> file` still works.
mkdir stdout && cd stdout || exit 1
cp -r "$src/configs/oils" . && cp "$src/configs/spur-seed000.yaml" spur.yaml && cp "$src/configs/automatic-6speed.yaml" auto.yaml
cp "$src/configs/transfer-box.yaml" tb.yaml
"$bin" synth tb.yaml --speed 600,900rpm --torque 100,200Nm -o rec.csv
refused "check: standard output is the case" spur.yaml "standard output '.*spur.yaml' is the input config 'spur.yaml'" \
    bash -c '"$0" check spur.yaml 1<> spur.yaml' "$bin"
refused "point: standard output is the case" spur.yaml "standard output '.*spur.yaml' is the input config" \
    bash -c '"$0" point spur.yaml --speed 800rpm --torque 50Nm 1<> spur.yaml' "$bin"
refused "cycle: standard output (the summary) is the case" auto.yaml "standard output '.*auto.yaml' is the input config" \
    bash -c '"$0" cycle auto.yaml --cycle nedc --start-temp 20degC 1<> auto.yaml' "$bin"
refused "diagnose: standard output (the diagnosis) is the case's oil" oils/75W90-A.yaml \
    "standard output '.*75W90-A.yaml' is the input named by the case at 'oil'" \
    bash -c '"$0" diagnose tb.yaml rec.csv 1<> oils/75W90-A.yaml' "$bin"
refused "report -o -: standard output is the case" tb.yaml "is the input config" \
    bash -c '"$0" report tb.yaml --speed 600rpm --torque 100Nm --oil-temp 70degC --no-spread -o - 1<> tb.yaml' "$bin"
"$bin" check spur.yaml > check.txt
check "check > check.txt: written" grep -q "spur" check.txt

# 9. The files gearloss ships are never outputs, whether this run reads them or not: a
#    cycle run on wltc, or a map, asked to write onto the shipped nedc cycle.
mkdir data && cp -r "$src/configs/cycles" "$src/configs/bearings" data/
export GEARLOSS_DATA_DIR=$PWD/data
refused "cycle --cycle wltc --json onto the shipped nedc.csv" data/cycles/nedc.csv \
    "--json '.*data/cycles/nedc.csv' is the input the shipped cycle 'nedc'" \
    "$bin" cycle auto.yaml --cycle wltc --start-temp 20degC --json "$GEARLOSS_DATA_DIR/cycles/nedc.csv"
refused "map --json onto a shipped cycle file" data/cycles/artemis-urban.csv "is the input the shipped cycle 'artemis-urban'" \
    "$bin" map tb.yaml --speed 600rpm --torque 100Nm --oil-temp 70degC -o m.csv --json data/cycles/artemis-urban.csv
unset GEARLOSS_DATA_DIR

# 10. The sidecar of an input (the recordings' rec.csv.meta.json, written by synth) is kept
#     like the input.
refused "diagnose --json onto the recordings' sidecar" rec.csv.meta.json \
    "--json 'rec.csv.meta.json' is the metadata 'rec.csv.meta.json' of the input recordings 'rec.csv'" \
    "$bin" diagnose tb.yaml rec.csv --json rec.csv.meta.json
refused "diagnose --residuals onto the recordings' sidecar" rec.csv.meta.json "of the input recordings 'rec.csv'" \
    "$bin" diagnose tb.yaml rec.csv --residuals rec.csv.meta.json
cd "$tmp" || exit 1

# 11. Every command writing to a pipe stops within a second of its reader going away, while
#     the output is still being computed (not only the streamed map): the reader exits at once
#     (`| true`); each run takes 10 s or more to the end. Within 5 s (1 s is the contract; a
#     loaded CI machine), exit 141 with the message, no temporary.
gone_reader() {  # gone_reader NAME COMMAND...: COMMAND's standard output piped to `true`
    local name=$1
    shift
    local t0
    t0=$(date +%s%N)
    timeout 120 "$@" 2> gone.err | true
    local rc=${PIPESTATUS[0]} ms=$((($(date +%s%N) - t0) / 1000000))
    check "$name | true: ends within 5 s (took $ms ms)" test $ms -lt 5000
    check "$name | true: exit 141 (got $rc)" test "$rc" -eq 141
    check "$name | true: message" grep -q "signal 13: a reader closed its pipe" gone.err
    check "$name | true: no temporary" no_temporary
}
mkdir gone && cd gone || exit 1
cp -r "$src/configs/oils" . && cp "$src/configs/transfer-box.yaml" tb.yaml && cp "$src/configs/automatic-6speed.yaml" auto.yaml
gone_reader "synth -o -" "$bin" synth "$spur" --speed "$(list 500 10 151)rpm" --torque "$(list 10 10 80)Nm" -o -
gone_reader "report -o -" "$bin" report tb.yaml -o -
gone_reader "map --spread -o -" "$bin" map tb.yaml --spread -o -
python3 -c "
print('time_s,speed_kmh')
for i in range(400001): print(f'{i},{50 + 30 * ((i // 60) % 2)}')" > long.csv
gone_reader "cycle (400 000 s) summary" "$bin" cycle auto.yaml --cycle long.csv --start-temp 20degC
"$bin" synth tb.yaml --speed 600,800,1000,1200rpm --torque 100,150,200,250,300Nm -o rec20.csv
python3 -c "
lines = open('rec20.csv').read().splitlines()
rows = [l.split(',') for l in lines[1:]]
print(lines[0])
for k in range(150):  # 3000 points, each speed a little apart (a minute of fitting)
    for r in rows: print(','.join([f'{float(r[0]) + 0.01 * k:.3f}'] + r[1:]))" > rec3k.csv
gone_reader "diagnose (3000 points) text" "$bin" diagnose tb.yaml rec3k.csv
cd "$tmp" || exit 1

echo "cli_file_safety: $pass passed, $fail failed"
test $fail -eq 0
