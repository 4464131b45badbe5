#!/usr/bin/env python3
"""Compares a gearloss output with its blessed copy.

CSV: same header, same rows, strings equal, numbers within
|a - b| <= REL * max(|a|, |b|) + ABS. JSON: same keys and values the same way,
except keys that measure time on this machine. The tolerance (1e-5 relative) is
a thousand times tighter than the 1 % change in any component that the net must
catch, and loose enough for the last printed digit and for -O2 against -O3.
Exit 0 when equal, 1 with a list of differences otherwise.
"""
import csv
import json
import math
import sys

REL, ABS = 1e-5, 1e-9
VOLATILE = {"seconds", "points_per_second", "simulation_seconds", "solve_seconds", "elapsed_s", "file"}


def number(s):
    try:
        v = float(s)
    except (TypeError, ValueError):
        return None
    return v


def close(a, b):
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= REL * max(abs(a), abs(b)) + ABS


def compare_csv(new, old, where):
    out = []
    rn = list(csv.reader(open(new, newline="")))
    ro = list(csv.reader(open(old, newline="")))
    if len(rn) != len(ro):
        return [f"{where}: {len(rn)} lines, blessed {len(ro)}"]
    header = ro[0] if ro else []
    for i, (a, b) in enumerate(zip(rn, ro), start=1):
        if len(a) != len(b):
            out.append(f"{where}:{i}: {len(a)} cells, blessed {len(b)}")
            continue
        for j, (x, y) in enumerate(zip(a, b)):
            col = header[j] if j < len(header) else str(j + 1)
            vx, vy = number(x), number(y)
            if vx is not None and vy is not None:
                if not close(vx, vy):
                    rel = (vx - vy) / abs(vy) if vy != 0 else float("inf")
                    out.append(f"{where}:{i}: {col}: {x} (blessed {y}, {rel:+.3%})")
            elif x != y:
                out.append(f"{where}:{i}: {col}: '{x}' (blessed '{y}')")
    return out


def walk(a, b, path, out):
    if isinstance(b, dict):
        if not isinstance(a, dict):
            out.append(f"{path}: not an object")
            return
        keys = (set(a) | set(b)) - VOLATILE
        for k in sorted(keys):
            if k not in a or k not in b:
                out.append(f"{path}.{k}: {'missing' if k not in a else 'not blessed'}")
            else:
                walk(a[k], b[k], f"{path}.{k}", out)
    elif isinstance(b, list):
        if not isinstance(a, list) or len(a) != len(b):
            out.append(f"{path}: list length differs")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            walk(x, y, f"{path}[{i}]", out)
    elif isinstance(b, (int, float)) and not isinstance(b, bool) and isinstance(a, (int, float)):
        if not close(float(a), float(b)):
            rel = (a - b) / abs(b) if b != 0 else float("inf")
            out.append(f"{path}: {a} (blessed {b}, {rel:+.3%})")
    elif a != b:
        out.append(f"{path}: {a!r} (blessed {b!r})")


def main():
    new, old = sys.argv[1], sys.argv[2]
    name = old.rsplit("/", 1)[-1]
    if old.endswith(".json"):
        out = []
        walk(json.load(open(new)), json.load(open(old)), name, out)
    else:
        out = compare_csv(new, old, name)
    for line in out[:40]:
        print(line)
    if len(out) > 40:
        print(f"... and {len(out) - 40} more differences")
    return 1 if out else 0


if __name__ == "__main__":
    sys.exit(main())
