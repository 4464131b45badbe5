#!/usr/bin/env bash
# Checks that README.md and docs/*.md attribute no number to a seed document ("seed 000" ...
# "seed 003", docs/bibliography.md) without saying where in the seed it stands: a sentence (or a
# table cell) that names a seed and holds a number must also hold a location in that seed, a
# section (§4.2, "section 4"), table, figure, equation, chapter, matrix or appendix reference,
# so a reviewer can find it (docs/claims.md lists every such claim with its verdict).
#
# Not counted as numbers: the seed's own id (also "003" in "seed 000 … 003"), years (a citation's "2015"), digits inside a name
# (75W90-A, NJ 406 is counted: "406" stands alone), paths and `code`. Not counted as a claim:
# the shipped cases named after a seed ("the seed 000 case", "seed-000 spur", "(seed 000 spur, ...").
#
# Usage: scripts/check-seed-claims.sh [FILE...]   (default: README.md docs/*.md)
# Exit status: 0 when every such sentence carries a location, 1 otherwise (each one printed as
# "file:line: seed N: sentence").
set -euo pipefail
cd "$(dirname "$0")/.."
exec python3 - "$@" <<'PY'
import glob, re, sys

files = sys.argv[1:] or ["README.md"] + sorted(glob.glob("docs/*.md"))
SEED = re.compile(r"\bseed[\s-]*(00[0-3])\b", re.I)
# Names of shipped cases and grids, not claims about the seed's content.
NAME = re.compile(r"\bseed[\s-]*00[0-3][\s-]+case\b|\bseed-000 spur\b|\bseed 000 spur,|spur-seed000|\bseed000\b", re.I)
LOCATION = re.compile(r"§\s*\d|\b(?:tables?|figs?\.|figures?|eqs?\.|equations?|sections?|chapters?|ch\.|matrix|appendix)"
                      r"\s*\(?(?:[A-Z]\.?)?\d", re.I)
NUMBER = re.compile(r"(?<![\w.\-/])[−-]?\d+(?:[.,]\d+)*(?![\w/])")
YEAR = re.compile(r"^(?:1[89]|20)\d\d$")

def units(path):
    """(line, text) of every sentence or table cell; a paragraph's lines are joined first."""
    lines = open(path, encoding="utf-8").read().split("\n")
    para, start = [], 0
    def flush():
        if para:
            text = " ".join(para)
            for s in re.split(r"(?<=[.!?:;])\s+(?=[A-Z(*`])", text):
                yield start, s
    out, fenced = [], False
    for i, raw in enumerate(lines, 1):
        line = raw.strip()
        if line.startswith("```"):
            out.extend(flush()); para = []
            fenced = not fenced
            continue
        if fenced:                                   # code: each line (a config comment) alone
            out.append((i, line))
            continue
        if line.startswith("|"):
            out.extend(flush()); para = []
            out.extend((i, cell) for cell in line.strip("|").split("|"))
        elif not line or line.startswith(("#", "- ", "* ")) or re.match(r"^\d+\.\s", line):
            out.extend(flush()); para = []
            if line:
                para, start = [line.lstrip("#-* ").strip()], i
        else:
            if not para:
                start = i
            para.append(line)
    out.extend(flush())
    return out

bad = checked = 0
for f in files:
    for line, text in units(f):
        if not SEED.search(text):
            continue
        bare = NAME.sub(" ", text)
        if not SEED.search(bare):
            continue
        bare = re.sub(r"`[^`]*`", " ", bare)          # code and paths
        bare = SEED.sub(" ", bare)
        bare = LOCATION.sub(" LOC ", bare)
        nums = [n for n in NUMBER.findall(bare) if not YEAR.match(n.lstrip("−-")) and not re.match(r"^00[0-3]$", n)]
        if not nums:
            continue
        checked += 1
        if "LOC" not in bare:
            bad += 1
            ids = ", ".join(sorted(set(SEED.findall(text))))
            print(f"{f}:{line}: seed {ids}: number(s) {', '.join(nums[:4])} without a section, table, figure or "
                  f"equation of the seed: {text.strip()[:200]}")
print(f"check-seed-claims: {checked} sentences attribute numbers to a seed in {len(files)} files; "
      f"{bad} without a location", file=sys.stderr)
sys.exit(1 if bad else 0)
PY
