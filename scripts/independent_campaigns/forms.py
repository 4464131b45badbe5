"""Model-form campaigns: the truth's model part from the same case with another published form.

The form axes and their forms are those docs/config.md lists under `mechanisms:`. case_forms
reads the forms a case selects (its `options:` keys and `mechanisms:` block, with the
documented defaults); checked_forms reads the forms `gearloss check` reports as selected
(the "[...]" of its "loss mechanisms" section), which confirms both the case's forms and a
derived case's. rewrite_case writes a copy of a case with another oil or other forms, merged
into its `mechanisms:` block, the conflicting `options:` key removed and the oil path made
absolute. The expected finding of a form campaign is `<axis>:<form>`.
"""
import re
import subprocess
from pathlib import Path

from .cases import top_level_blocks, strip_comment

# axis -> (mechanism, key under mechanisms.<mechanism>, the flat options key or None, forms, default)
AXES = {
    "friction": ("mesh", "friction", "mesh_friction", ["schlenk", "iso_6336_20", "fernandes_mixed", "ehl_local", "ehl_maxwell"],
                 "schlenk"),
    "loss_factor": ("mesh", "loss_factor", "gear_loss_factor", ["wimmer", "ohlendorf", "buckingham"], "wimmer"),
    "film_correction": ("mesh", "film_correction", "film_thermal_correction", ["gupta", "simplified", "none"],
                        "gupta"),
    "windage": ("windage", "form", None, ["none", "anderson_loewenthal", "free_disk"], "none"),
}
CHECK_NAMES = {"mesh.friction": "friction", "mesh.loss_factor": "loss_factor",
               "mesh.film_correction": "film_correction", "windage.form": "windage"}


def expected_id(axis, form):
    """The effect id `diagnose` should give a form change: friction:<form>, loss_factor:<form>, ..."""
    return f"{axis}:{form}"


def parse_flow_map(s):
    """{a: b, c: d} (one level, no nesting) -> ordered list of (key, value)."""
    s = s.strip()
    if not (s.startswith("{") and s.endswith("}")):
        return None
    items = []
    for part in s[1:-1].split(","):
        if ":" in part:
            k, v = part.split(":", 1)
            items.append((k.strip(), v.strip()))
    return items


def block_body(lines, name):
    """The lines under a top-level key (without the key's own line); [] if absent."""
    return next((lines[s + 1:e] for key, s, e in top_level_blocks(lines) if key == name), [])


def mechanism_settings(lines):
    """{mechanism: {key: value}} of a case's top-level `mechanisms:` block (flow maps or nested)."""
    out, mech = {}, None
    for line in block_body(lines, "mechanisms"):
        body = strip_comment(line)
        m = re.match(r"([A-Za-z_]\w*):\s*(.*)$", body)
        if not m:
            continue
        if len(line) - len(line.lstrip()) <= 2:
            mech = m.group(1)
            out.setdefault(mech, {}).update(parse_flow_map(m.group(2)) or [])
        elif mech:
            out[mech][m.group(1)] = m.group(2)
    return out


def option_settings(lines):
    """{key: value} of the one-line entries of a case's `options:` block."""
    matches = (re.match(r"^\s+([A-Za-z_]\w*):\s*(\S[^#]*)", line) for line in block_body(lines, "options"))
    return {m.group(1): m.group(2).strip() for m in matches if m}


def case_forms(config_path):
    """The form of every axis a case selects, read from its text (mechanisms: wins over options:)."""
    lines = Path(config_path).read_text().splitlines()
    mech, opts = mechanism_settings(lines), option_settings(lines)
    forms = {}
    for axis, (m, k, opt, _, default) in AXES.items():
        forms[axis] = mech.get(m, {}).get(k) or (opts.get(opt) if opt else None) or default
    return forms


def checked_forms(binary, config_path):
    """The forms `gearloss check` reports as selected ("[form]"); {} when check fails."""
    r = subprocess.run(["nice", "-n", "19", binary, "check", str(config_path)], capture_output=True, text=True)
    out = {}
    for line in r.stdout.splitlines():
        m = re.match(r"^\s*([a-z_]+\.[a-z_]+):.*\[(\w+)\]", line)
        if m and m.group(1) in CHECK_NAMES:
            out[CHECK_NAMES[m.group(1)]] = m.group(2)
    return out


def alternatives(forms, axis):
    """The published forms of an axis other than the case's, in the documented order."""
    return [f for f in AXES[axis][3] if f != forms[axis]]


def _set_in_mechanisms(lines, mech, key, value):
    """Merge mechanisms.<mech>.<key> = value into the lines (adds the block if absent)."""
    blocks = [b for b in top_level_blocks(lines) if b[0] == "mechanisms"]
    if not blocks:
        return lines + ["mechanisms:                       # derived case: form set by scripts/independent-campaigns.py",
                        f"  {mech}: {{{key}: {value}}}"]
    _, s, e = blocks[0]
    for j in range(s + 1, e):
        body = lines[j].split("#", 1)[0].rstrip()
        m = re.match(rf"^  {mech}:\s*(.*)$", body)
        if not m:
            continue
        fm = parse_flow_map(m.group(1)) if m.group(1) else None
        if fm is not None:
            d = dict(fm)
            d[key] = value
            lines[j] = f"  {mech}: {{" + ", ".join(f"{k}: {v}" for k, v in d.items()) + "}"
            return lines
        # nested block: replace the key or insert it under the mechanism
        end = j + 1
        while end < e and (not lines[end].strip() or len(lines[end]) - len(lines[end].lstrip()) > 2):
            if re.match(rf"^\s+{key}:", lines[end]):
                lines[end] = f"    {key}: {value}"
                return lines
            end += 1
        return lines[:j + 1] + [f"    {key}: {value}"] + lines[j + 1:]
    return lines[:s + 1] + [f"  {mech}: {{{key}: {value}}}"] + lines[s + 1:]


def rewrite_case(src, dst, header, oil=None, form=None):
    """A copy of case `src` at `dst`: its oil replaced by `oil` (a path) if given, else the oil
    path made absolute; with form = (axis, name), that form set under `mechanisms:` (merged)
    and the axis' flat `options:` key removed so that nothing else selects it."""
    src = Path(src)
    lines = src.read_text().splitlines()
    drop = set()
    if form:
        opt = AXES[form[0]][2]
        for key, s, e in top_level_blocks(lines):
            if key == "options" and opt:
                drop.update(j for j in range(s + 1, e) if re.match(rf"^\s+{opt}:", lines[j]))
    out = []
    for j, line in enumerate(lines):
        if j in drop:
            out.append(f"  # {line.strip()}   <- removed: the form is set under mechanisms")
            continue
        m = re.match(r"^oil:\s*(\S+)(.*)$", line)
        if m and not m.group(1).startswith("{"):
            p = Path(oil) if oil else (src.parent / m.group(1))
            line = f"oil: {p.resolve()}"
        out.append(line)
    if form:
        mech, key = AXES[form[0]][0], AXES[form[0]][1]
        out = _set_in_mechanisms(out, mech, key, form[1])
    Path(dst).write_text(f"# {header}\n" + "\n".join(out) + "\n")
    return Path(dst)
