#!/usr/bin/env python3
"""Black-box fuzzing of the gearloss command line, with four oracles.

Every run happens in a fresh temporary directory holding a copy of the shipped configs
(cases, oils, the bearing catalogue, drive cycles), a small recording made by `synth`,
the FVA example REXS model and a copy of the program itself. A run draws a command (check,
point, map, report, compare, cycle, diagnose, synth, merge, mesh-profile, duty, rating, import: a hostile
REXS model, see hostile_rexs), a shipped case, possibly a
mutated case or oil file (a value replaced by a hostile token: no unit, a wrong unit
kind, NaN, 1e308, a negative, a control character, a YAML tag, a duplicate key, a
deleted line) and output paths that are sometimes fresh, sometimes an input, an earlier
output or the program's copy. The oracles:

  crash    the program died on a signal, or exited 4 (internal error) or with a code
           outside the documented ones (0, 1, 2, 3, 129, 130, 131, 141, 143);
  hang     the run took longer than --timeout seconds;
  nan      a run that exited 0 wrote `nan` or `inf` into any output (stdout, files);
  damage   a file that existed before the run changed although it was not an output the
           run was asked to write, or a failed run (exit != 0) changed or created any file
           (a clobbered or half-written output), or a temporary file was left behind;
  message  a run that failed said nothing on stderr, or said "internal error".

Findings are written to DIR/finding-N/ (the command, the inputs, stdout and stderr) and
summarised in the JSON report. Exit status: 0 when nothing was found, 1 otherwise.

Usage: scripts/fuzz-cli.py --binary build/app/gearloss --seconds 1200 [--jobs 2]
       [--seed 1] [--out build-fuzz/cli] [--timeout 60] [--report FILE]
       scripts/fuzz-cli.py --runs 150 --seed 7 ...   (a fixed set of runs: the ctest entry)
"""
import argparse
import concurrent.futures as cf
import hashlib
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = ["transfer-box.yaml", "fzg-c40-paor.yaml", "spur-seed000.yaml", "manual-6speed.yaml",
         "automatic-6speed.yaml", "planetary-test.yaml", "wind-turbine-2.5MW.yaml",
         "transfer-box-75W140.yaml", "fzg-c40-paor-designations.yaml"]
VEHICLE_CASES = ["manual-6speed.yaml", "automatic-6speed.yaml"]
OILS = ["oils/75W90-A.yaml", "oils/MINR.yaml", "oils/PAOR.yaml", "oils/ESTR.yaml", "oils/ATF-A.yaml"]
DOCUMENTED_EXITS = {0, 1, 2, 3, 129, 130, 131, 141, 143}

# Values that replace a scalar of a case or oil file. Each is either nonsense a careful
# program must refuse with a message, or an extreme it must handle without NaN.
HOSTILE_VALUES = [
    "60", "0.3", "-1", "0", "nan", ".nan", "inf", "-.inf", "1e308", "-1e308", "1e-300", "1e-300 um",
    "200 Wh", "200 J", "1000 rpm/rev", "70C", "-273.15degC", "-300 degC", "5000 degC", "-100 degC",
    "1 kJ/degC", "1e-9 mm", "1e9 mm", "60 rad", "400 deg", "-20 deg", "'\x00'", "\"a\\x01b\"",
    "!!binary aGVsbG8=", "!unit 5 mm", "[]", "{}", "~", "''", "\"\"", "yes", "1,5 mm", "4.500000000000001 mm",
    "3 kg", "10 W", "1 Pa", "-5 mm", "0 mm", "1e5 rpm", "0 rpm", "12 N m", "12 Nm", "1 bar",
]
CLI_SPEEDS = ["800rpm", "600,700,800rpm", "1000,5rpm", "0rpm", "1e9rpm", "-100rpm", "nan rpm", "1000 rpm/rev",
              "200 Wh", "", "1e-300rpm", "100,100,100rpm"]
CLI_TORQUES = ["250Nm", "0,100Nm", "-100,100Nm", "200 Wh", "200 J", "1e12Nm", "nanNm", "", "1 kN m", "5"]
CLI_TEMPS = ["70degC", "-30degC", "150degC", "70C", "-273.15degC", "-300degC", "1e6degC", "nan degC", "300 K", "20"]
# The program formats numbers with fmt/printf, which spell a non-finite value nan, -nan, inf
# or -inf (lower case); "NaN" in prose (e.g. a note on how MATLAB reads null) is not one.
NAN_RE = re.compile(rb"(?<![A-Za-z_])[-+]?(?:nan|inf|infinity)(?![A-Za-z_])")
SCRIPT_RE = re.compile(rb"<script\b.*?</script>", re.IGNORECASE | re.DOTALL)


def digest(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def snapshot(top):
    files = {}
    for d, _, names in os.walk(top):
        for n in names:
            p = os.path.join(d, n)
            if os.path.islink(p) or not os.path.isfile(p):
                continue
            files[os.path.relpath(p, top)] = digest(p)
    return files


TABLE_TEMPS = ["40 degC", "40 degC", "70 degC", "100 degC", "-40 degC", "300 degC", "40.0000001 degC", "nan degC"]


def mutate_oil_tables(text, rng):
    """Replaces an oil's piezoviscosity or viscosity by a table whose abscissae may repeat,
    run backwards or lie far outside the data (the inputs that once printed -nan)."""
    temps = [rng.choice(TABLE_TEMPS) for _ in range(rng.choice([1, 2, 2, 3]))]
    if rng.random() < 0.5:
        rows = "".join(f"\n  - [{t}, {rng.choice(['1.387e-8', '2e-8', '0', '-1e-8', '1e-3'])} 1/Pa]" for t in temps)
        text = re.sub(r"^piezoviscosity:.*$", "piezoviscosity:" + rows, text, flags=re.MULTILINE)
        if "piezoviscosity:" not in text:
            text += "\npiezoviscosity:" + rows + "\n"
    else:
        rows = "".join(f"\n    - [{t}, {rng.choice(['112 cSt', '36.7 cSt', '16.4 cSt', '0 cSt', '1e9 cSt'])}]"
                       for t in temps)
        text = re.sub(r"^viscosity:\n(?:[ \t]+.*\n)+", "viscosity:\n  points:" + rows + "\n", text,
                      flags=re.MULTILINE)
    return text


def mutate_yaml(text, rng):
    if "base:" in text and rng.random() < 0.4:
        return mutate_oil_tables(text, rng)
    lines = text.split("\n")
    candidates = [i for i, l in enumerate(lines) if re.search(r"\w:\s*[^\s#{\[]", l)]
    if not candidates:
        return text
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        i = rng.choice(candidates)
        line = lines[i]
        kind = rng.random()
        if kind < 0.7:
            # Replace the value of the first "key: value" (block or flow style).
            m = list(re.finditer(r"(\w+):\s*([^,}#\n]+)", line))
            if not m:
                continue
            mm = rng.choice(m)
            lines[i] = line[:mm.start(2)] + rng.choice(HOSTILE_VALUES) + line[mm.end(2):]
        elif kind < 0.8:
            lines.insert(i, line)  # duplicate key
        elif kind < 0.9:
            del lines[i]
            candidates = [c for c in candidates if c < len(lines)]
            if not candidates:
                break
        else:
            pos = rng.randrange(len(line) + 1)
            lines[i] = line[:pos] + rng.choice(["\x00", "\x01", "\x7f", "\t", "\x1b[2J", "\u00e9"]) + line[pos:]
    return "\n".join(lines)


REXS_MODELS = ["FVA-Industriegetriebe_2stufig_1-4.rexs", "FVA-Industriegetriebe_2stufig_1-4.rexsj"]
REXS_KINDS = ["truncated", "empty", "deep", "loop", "huge", "nonfinite", "unit", "duplicate", "bytes", "zip_big",
              "zip_over", "zip_many", "intact"]
REXS_NUMBER_RE = re.compile(r'(>|"floating_point" ?: ?)(-?[0-9][0-9.eE+-]*)')


def hostile_rexs(rng, t):
    """Writes a hostile REXS model into t/rexs/ and returns its relative path. Kinds: truncated
    XML/JSON, an empty file, deep nesting, an assembly loop, huge numbers, NaN/inf values, units
    of another quantity or none REXS knows, duplicate ids, flipped bytes, and .rexsz archives:
    a member that unpacks to 48 MiB (within the 64 MiB bound), one that unpacks beyond it, and
    many members. The import must fail with a message (exit 2) or write a case: never crash."""
    src = rng.choice(REXS_MODELS)
    xml = src.endswith(".rexs")
    with open(os.path.join(t, "rexs", src), encoding="utf-8") as f:
        text = f.read()
    kind = rng.choice(REXS_KINDS)
    ext = ".rexs" if xml else ".rexsj"
    if kind == "truncated":
        text = text[:rng.randrange(len(text))]
    elif kind == "empty":
        text = rng.choice(["", " ", "\n", "\ufeff"])
    elif kind == "deep":
        n = rng.choice([33, 100, 5000, 200000])
        if xml:
            text = text.replace("<components>", "<components>" + "<x>" * n + "</x>" * n, 1)
        else:
            text = text.replace('"model"', '"deep": ' + "[" * n + "]" * n + ', "model"', 1)
    elif kind == "loop":
        # gear 15 sits on shaft 12 (relation 5); a relation making shaft 12 a part of gear 15 closes a loop.
        if xml:
            text = text.replace("<relations>", '<relations><relation id="9999" type="assembly"><ref hint="cylindrical_gear" '
                                'id="15" role="assembly"/><ref hint="shaft" id="12" role="part"/></relation>', 1)
        else:
            text = text.replace('"relations": [', '"relations": [{"id": 9999, "type": "assembly", "refs": [{"id": 15, '
                                '"role": "assembly", "hint": "cylindrical_gear"}, {"id": 12, "role": "part", "hint": '
                                '"shaft"}]}, ', 1)
    elif kind in ("huge", "nonfinite"):
        values = ["1e308", "-1e308", "1e400", "1e-400", "4e15"] if kind == "huge" else ["NaN", "nan", "inf", "-inf",
                                                                                          "Infinity", "1e999"]
        matches = list(REXS_NUMBER_RE.finditer(text))
        for m in sorted(rng.sample(matches, min(len(matches), rng.choice([1, 1, 3, 20]))), key=lambda m: -m.start()):
            text = text[:m.start(2)] + rng.choice(values) + text[m.end(2):]
    elif kind == "unit":
        units = list(re.finditer(r'unit"?\s*[=:]\s*"([^"]*)"', text))
        for m in sorted(rng.sample(units, min(len(units), rng.choice([1, 2, 10]))), key=lambda m: -m.start()):
            text = text[:m.start(1)] + rng.choice(["kg", "furlong", "mm^9", "", "1 / min", "C", "N m", "%"]) + text[m.end(1):]
    elif kind == "duplicate":
        head, sep, comps = text.partition("<components>" if xml else '"components"')
        text = head + sep + re.sub(r'(<component id="|"id" ?: ?)14\b', r"\g<1>13", comps, count=1)
    elif kind == "bytes":
        b = bytearray(text.encode("utf-8"))
        for _ in range(rng.choice([1, 5, 50])):
            b[rng.randrange(len(b))] = rng.randrange(256)
        text = b.decode("utf-8", "replace")
    if kind.startswith("zip"):
        import zipfile
        path = os.path.join("rexs", "h.rexsz")
        with zipfile.ZipFile(os.path.join(t, path), "w", zipfile.ZIP_DEFLATED) as z:
            if kind == "zip_many":
                for i in range(rng.choice([2, 1200])):
                    z.writestr(f"m{i}.txt", "x")
                z.writestr("model" + ext, text)
            else:
                pad = (48 if kind == "zip_big" else 70) << 20
                filler = "<!--" + " " * pad + "-->" if xml else " " * pad
                z.writestr("model" + ext, text.replace("\n", "\n" + filler, 1) if xml else filler + text)
        return path
    path = os.path.join("rexs", "h" + ext)
    with open(os.path.join(t, path), "w", encoding="utf-8", newline="") as f:
        f.write(text)
    return path


def make_template(binary, workdir):
    """configs/ copy, one steady recording per case for diagnose, the REXS models, the program's copy."""
    tpl = os.path.join(workdir, "template")
    shutil.copytree(os.path.join(ROOT, "configs"), os.path.join(tpl, "configs"))
    os.makedirs(os.path.join(tpl, "rexs"))
    for name in REXS_MODELS:
        shutil.copy2(os.path.join(ROOT, "tests", "data", "rexs", name), os.path.join(tpl, "rexs", name))
    for case in ["transfer-box.yaml"]:
        out = os.path.join(tpl, "configs", case.replace(".yaml", "-rec.csv"))
        subprocess.run([binary, "synth", os.path.join(tpl, "configs", case), "--effect", "windage=20W",
                        "--seed", "3", "-o", out], check=True, capture_output=True, timeout=600)
    shutil.copy2(binary, os.path.join(tpl, "gl"))
    return tpl


def draw_run(rng, t):
    """Returns (argv, the outputs the run may write [relative paths], description)."""
    c = "configs/"
    case = c + rng.choice(CASES)
    inputs = [case, c + "oils/75W90-A.yaml", c + "oils/MINR.yaml", c + "bearings/catalogue.yaml",
              c + "cycles/nedc.csv", c + "transfer-box-rec.csv", c + "spectra/wind-2.5MW-weibull.csv", "gl"]
    mutated = None
    if rng.random() < 0.5:
        target = case
        if rng.random() < 0.4:
            with open(os.path.join(t, case), encoding="utf-8") as f:
                m = re.search(r"^oil:\s*([^\s#]+)", f.read(), re.MULTILINE)
            own = os.path.normpath(os.path.join(c, m.group(1))) if m else None
            target = own if own and os.path.isfile(os.path.join(t, own)) else c + rng.choice(OILS)
        with open(os.path.join(t, target), encoding="utf-8") as f:
            text = f.read()
        with open(os.path.join(t, target), "w", encoding="utf-8", newline="") as f:
            f.write(mutate_yaml(text, rng))
        mutated = target
    if rng.random() < 0.15:
        # An earlier output with known content: a failed run must leave it as it was.
        with open(os.path.join(t, "old.csv"), "w") as f:
            f.write("an earlier output\n")
        inputs.append("old.csv")

    def out_path(ext):
        r = rng.random()
        if r < 0.6:
            return f"out{rng.randrange(3)}{ext}"
        if r < 0.7:
            return "old.csv" if os.path.exists(os.path.join(t, "old.csv")) else f"out{ext}"
        if r < 0.95:
            return rng.choice(inputs)
        return rng.choice(["sub/dir/out" + ext, "out" + ext + "/", "./" + case, c + "../" + case])

    def grid():
        a = []
        if rng.random() < 0.9:
            a += ["--speed", rng.choice(CLI_SPEEDS[:3]) if rng.random() < 0.8 else rng.choice(CLI_SPEEDS)]
            a += ["--torque", rng.choice(CLI_TORQUES[:2]) if rng.random() < 0.8 else rng.choice(CLI_TORQUES)]
        if rng.random() < 0.4:
            a += ["--oil-temp", rng.choice(CLI_TEMPS[:3]) if rng.random() < 0.7 else rng.choice(CLI_TEMPS)]
        return a

    cmd = rng.choice(["check", "point", "map", "map", "report", "compare", "cycle", "diagnose", "synth", "merge",
                      "mesh-profile", "duty", "import", "rating"])
    outs = []
    argv = ["./gl", cmd]
    if cmd == "check":
        argv += [case] + (["--json"] if rng.random() < 0.5 else []) + (["--oil-temp", rng.choice(CLI_TEMPS)]
                                                                      if rng.random() < 0.3 else [])
    elif cmd == "point":
        argv += [case, "--speed", rng.choice(CLI_SPEEDS), "--torque", rng.choice(CLI_TORQUES)]
        if rng.random() < 0.5:
            o = out_path(".json"); outs.append(o); argv += ["--json", o]
    elif cmd == "map":
        o = out_path(".csv"); outs += [o, o + ".meta.json"]
        argv += [case, "-o", o] + grid()
        fmt = rng.random()
        if fmt < 0.15:
            argv += ["--format", "vecto"]
            outs += [os.path.splitext(o)[0] + "_*" + os.path.splitext(o)[1]]
        elif fmt < 0.25:
            argv += ["--format", "table"]
        if rng.random() < 0.3:
            j = out_path(".json"); outs.append(j); argv += ["--json", j]
        if rng.random() < 0.1:
            argv += ["--shard", rng.choice(["1/2", "2/2", "", "0/2", "3/2", "1/0", "a/b"])]
        if rng.random() < 0.2:
            argv += ["--detail"]
        if rng.random() < 0.1:
            argv += ["--threads", rng.choice(["1", "2", "0", "-1", "x"])]
    elif cmd == "report":
        o = out_path(".html"); outs.append(o)
        argv += [case, "-o", o, "--no-spread"] + grid()
    elif cmd == "compare":
        o = out_path(".csv"); outs += [o, o + ".meta.json"]
        argv += [case, "--oil", c + rng.choice(OILS), "--oil", c + rng.choice(OILS), "-o", o] + grid()
        if rng.random() < 0.3:
            j = out_path(".json"); outs.append(j); argv += ["--json", j]
    elif cmd == "cycle":
        vcase = c + rng.choice(VEHICLE_CASES)
        o = out_path(".csv"); outs += [o, o + ".meta.json"]
        argv += [vcase, "--cycle", rng.choice(["nedc", c + "cycles/nedc.csv", "artemis-urban", "bogus"]),
                 "--start-temp", rng.choice(CLI_TEMPS[:3]) if rng.random() < 0.8 else rng.choice(CLI_TEMPS),
                 "-o", o]
        if rng.random() < 0.3:
            j = out_path(".json"); outs.append(j); argv += ["--json", j]
    elif cmd == "diagnose":
        argv += [c + "transfer-box.yaml", c + "transfer-box-rec.csv", "--bootstrap", "4", "--quiet"]
        for opt, ext in (("--json", ".json"), ("--write-config", ".yaml"), ("--residuals", ".csv")):
            if rng.random() < 0.4:
                o = out_path(ext); outs.append(o); argv += [opt, o]
                if ext == ".csv":
                    outs.append(o + ".meta.json")  # every CSV written to a file has its sidecar
    elif cmd == "synth":
        o = out_path(".csv"); outs += [o, o + ".meta.json"]
        argv += [case, "-o", o, "--seed", str(rng.randrange(100))] + grid()
        if rng.random() < 0.5:
            argv += ["--effect", rng.choice(["windage=30W", "torque_sensor_gain=1.03", "bogus=1", "windage=nan W",
                                             "windage=-1e308W"])]
    elif cmd == "merge":
        o = out_path(".csv"); outs += [o, o + ".meta.json"]
        argv += [rng.choice(inputs), rng.choice(inputs), "-o", o]
    elif cmd == "duty":
        o = out_path(".csv"); outs += [o, o + ".meta.json"]
        spectrum = rng.choice([c + "spectra/wind-2.5MW-weibull.csv"] * 3 + [c + "cycles/nedc.csv",
                                                                          c + "transfer-box-rec.csv"])
        argv += [case, spectrum, "-o", o]
        if rng.random() < 0.4:
            argv += ["--oil-temp", rng.choice(CLI_TEMPS[:3]) if rng.random() < 0.7 else rng.choice(CLI_TEMPS)]
        if rng.random() < 0.3:
            j = out_path(".json"); outs.append(j); argv += ["--json", j]
    elif cmd == "import":
        model = hostile_rexs(rng, t)
        mutated = model  # its text (a name with "nan" in it) may be echoed into the case
        o = out_path(".yaml")
        outs += [o, os.path.splitext(o)[0] + ".oil.yaml"]
        argv += [model, "-o", o]
        if rng.random() < 0.2:
            argv += ["--oil", c + rng.choice(OILS)]
    elif cmd == "rating":
        o = out_path(".csv"); outs += [o, o + ".meta.json"]
        argv += [case, "-o", o]
        if rng.random() < 0.5:
            argv += ["--speed", rng.choice(CLI_SPEEDS[:3]) if rng.random() < 0.8 else rng.choice(CLI_SPEEDS)]
        if rng.random() < 0.3:
            argv += ["--oil-limit", rng.choice(["95degC", "110degC", "20degC", "nan degC", "-300degC", "95"])]
        if rng.random() < 0.2:
            argv += ["--target-oil-temp", rng.choice(["60degC", "200degC", "x"])]
        if rng.random() < 0.3:
            j = out_path(".json"); outs.append(j); argv += ["--json", j]
    elif cmd == "mesh-profile":
        o = out_path(".csv"); outs += [o, o + ".meta.json"]
        argv += [c + "spur-seed000.yaml", "--mesh", rng.choice(["m1", "mesh", ""]), "--speed",
                 rng.choice(CLI_SPEEDS), "--torque", rng.choice(CLI_TORQUES), "-o", o]
    return argv, outs, mutated, files_read(t, argv)


def files_read(t, argv):
    """The files a run reads (relative to t): they must never change, whatever was asked."""
    reads = {"gl"}
    out_options = {"-o", "--output", "--write-config", "--residuals"} | ({"--json"} if argv[1] != "check" else set())
    args = argv[2:]
    for i, a in enumerate(args):
        if a in out_options or (i > 0 and args[i - 1] in out_options):
            continue
        p = os.path.normpath(a)
        if os.path.isfile(os.path.join(t, p)) and not p.startswith("out") and p != "old.csv":
            reads.add(p)
    for p in list(reads):
        if not p.endswith(".yaml"):
            continue
        with open(os.path.join(t, p), encoding="utf-8", errors="replace") as f:
            text = f.read()
        for m in re.finditer(r"^\s*oil:\s*([^\s#]+)", text, re.MULTILINE):
            q = os.path.normpath(os.path.join(os.path.dirname(p), m.group(1)))
            if os.path.isfile(os.path.join(t, q)):
                reads.add(q)
        if "designation" in text:
            reads.add("configs/bearings/catalogue.yaml")
    return reads


def is_output(rel, outs):
    for o in outs:
        if "*" in o:
            pre, post = o.split("*", 1)
            if rel.startswith(os.path.normpath(pre)) and rel.endswith(post):
                return True
        elif os.path.normpath(o) == rel:
            return True
    return False


def scan_nan(data, html):
    if html:
        data = SCRIPT_RE.sub(b"", data)
    m = NAN_RE.search(data)
    return None if m is None else data[max(0, m.start() - 60):m.end() + 20].decode("utf-8", "replace")


def one_run(args):
    seed, binary_tpl, timeout, out_dir = args
    rng = random.Random(seed)
    t = tempfile.mkdtemp(prefix="gearloss-fuzz-cli-")
    try:
        shutil.copytree(binary_tpl, t, dirs_exist_ok=True)
        argv, outs, mutated, reads = draw_run(rng, t)
        before = snapshot(t)
        start = time.monotonic()
        # Now and then standard output is an input opened for reading and writing without
        # truncation (the shell's `1<>case.yaml`): nothing may be written into it.
        stdout_file = None
        readable = sorted(reads - {"gl"})  # the program's copy cannot be opened for writing while it runs
        if rng.random() < 0.08 and readable:
            stdout_file = open(os.path.join(t, rng.choice(readable)), "r+b")
        try:
            # The program's copy finds no shipped data beside it; import needs the bearing catalogue.
            env = dict(os.environ, GEARLOSS_DATA_DIR=os.path.join(t, "configs")) if argv[1] == "import" else None
            p = subprocess.run(argv, cwd=t, stdout=stdout_file or subprocess.PIPE, stderr=subprocess.PIPE,
                               timeout=timeout, env=env)
            rc, out, err, hung = p.returncode, p.stdout or b"", p.stderr, False
        except subprocess.TimeoutExpired as e:
            rc, out, err, hung = None, e.stdout or b"", e.stderr or b"", True
        finally:
            if stdout_file:
                stdout_file.close()
                argv = argv + [f"1<>{os.path.relpath(stdout_file.name, t)}"]
        elapsed = time.monotonic() - start
        after = snapshot(t)
        problems = []
        if hung:
            problems.append(("hang", f"no exit after {timeout} s"))
        elif rc < 0 or rc not in DOCUMENTED_EXITS or rc == 4:
            problems.append(("crash", f"exit {rc}"))
        if not hung and rc not in (0, None):
            if not err.strip():
                problems.append(("message", f"exit {rc} with nothing on stderr"))
            elif b"internal error" in err.lower():
                problems.append(("message", err.decode("utf-8", "replace").strip()[:300]))
        for rel, h in after.items():
            if ".tmp.gearloss-" in rel and not hung:
                problems.append(("damage", f"temporary file left behind: {rel}"))
        for rel in sorted(reads):
            if before.get(rel) != after.get(rel):
                problems.append(("damage", f"input {rel} changed or removed (exit {rc})"))
        for rel, h in before.items():
            if rel in reads:
                continue
            if rel not in after:
                if not (rc == 0 and is_output(rel, outs)):
                    problems.append(("damage", f"{rel} was removed"))
            elif after[rel] != h and not (rc == 0 and is_output(rel, outs)):
                problems.append(("damage", f"{rel} changed (exit {rc}; outputs asked for: {outs})"))
        if rc not in (0, None):
            for rel in after:
                if rel not in before and ".tmp.gearloss-" not in rel:
                    problems.append(("damage", f"failed run (exit {rc}) created {rel}"))
        # A mutation that wrote nan or inf into the case or oil as text (a name, say) may be
        # echoed back as the user's own text: those runs are not judged by the nan oracle.
        echoed = mutated is not None and NAN_RE.search(open(os.path.join(t, mutated), "rb").read()) is not None
        if rc == 0 and not echoed:
            where = scan_nan(out, False)
            if where:
                problems.append(("nan", f"stdout: ...{where}..."))
            for rel in after:
                if rel in before and after[rel] == before[rel]:
                    continue
                with open(os.path.join(t, rel), "rb") as f:
                    where = scan_nan(f.read(), rel.endswith(".html"))
                if where:
                    problems.append(("nan", f"{rel}: ...{where}..."))
        record = {"seed": seed, "argv": argv, "mutated": mutated, "exit": rc, "seconds": round(elapsed, 2),
                  "problems": problems}
        if problems:
            d = os.path.join(out_dir, f"finding-{seed}")
            shutil.rmtree(d, ignore_errors=True)
            shutil.copytree(binary_tpl, d, ignore=shutil.ignore_patterns("gl"))
            if mutated:
                shutil.copy2(os.path.join(t, mutated), os.path.join(d, mutated))
            with open(os.path.join(d, "run.json"), "w") as f:
                json.dump(record, f, indent=1)
            with open(os.path.join(d, "stdout"), "wb") as f:
                f.write(out[:1 << 20])
            with open(os.path.join(d, "stderr"), "wb") as f:
                f.write(err[:1 << 20])
        return record
    finally:
        shutil.rmtree(t, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default=os.path.join(ROOT, "build/app/gearloss"))
    ap.add_argument("--seconds", type=float, default=300)
    ap.add_argument("--runs", type=int, default=0, help="stop after this many runs (0: run for --seconds); "
                    "with a fixed --seed the same runs each time")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--out", default=os.path.join(ROOT, "build-fuzz/cli"))
    ap.add_argument("--report", help="JSON summary file")
    a = ap.parse_args()
    binary = os.path.abspath(a.binary)
    os.makedirs(a.out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="gearloss-fuzz-cli-tpl-")
    try:
        tpl = make_template(binary, work)
        deadline = time.monotonic() + a.seconds
        runs, found, by_command, by_exit = 0, [], {}, {}
        seed = a.seed * 1_000_003
        with cf.ProcessPoolExecutor(max_workers=a.jobs) as pool:
            pending = set()
            while True:
                while len(pending) < 2 * a.jobs and (
                        (a.runs and seed - a.seed * 1_000_003 < a.runs) or (not a.runs and time.monotonic() < deadline)):
                    pending.add(pool.submit(one_run, (seed, tpl, a.timeout, a.out)))
                    seed += 1
                if not pending:
                    break
                done, pending = cf.wait(pending, return_when=cf.FIRST_COMPLETED)
                for f in done:
                    r = f.result()
                    runs += 1
                    by_command[r["argv"][1]] = by_command.get(r["argv"][1], 0) + 1
                    by_exit[str(r["exit"])] = by_exit.get(str(r["exit"]), 0) + 1
                    if r["problems"]:
                        found.append(r)
                        for kind, what in r["problems"]:
                            print(f"FINDING {kind} (seed {r['seed']}): {' '.join(r['argv'])}: {what}", flush=True)
        summary = {"runs": runs, "seconds": None if a.runs else a.seconds, "findings": len(found), "by_command": by_command,
                   "by_exit": by_exit, "kinds": sorted({k for r in found for k, _ in r["problems"]})}
        print(json.dumps(summary))
        if a.report:
            with open(a.report, "w") as f:
                json.dump({"summary": summary, "findings": found}, f, indent=1)
        return 1 if found else 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
