#!/usr/bin/env bash
# Checks that every literature citation in lib/, app/, tests/ and scripts/ resolves to an
# entry of docs/bibliography.md (see its header for the citation forms):
#   author-year  "Schlenk (1994)", "Pereira 2017 eq. 2.10", "Changenet & Velex (2007, 2008)",
#                "Gold et al. 2001", "Alefeld, Potra & Shi 1995", "von Karman 1921": the first
#                author's surname (accents and case ignored) and every year must be in the
#                bold key of one entry;
#   standards    "ISO/TS 6336-20", "ANSI/HI 9.6.7 (2010)", "UN GTR No. 15": the number must be
#                in the bold key of an entry of the same body;
#   seeds        "seed 001": must be a row of the seed table.
# In C++ only comments and string literals are read (code is masked out); shell, Python and
# CMake files are read whole, as their quoting is too varied to mask reliably and their code
# is lower-case identifiers that the patterns below do not take for names.
# Warnings only: entries that nothing cites (code, README, docs/, configs/), and citations in
# README, docs/ and configs/ that do not resolve (the bibliography promises the code only).
#
# Usage: scripts/check-citations.sh
# Exit status: 0 when every citation resolves (a count summary is printed), 1 otherwise
# (each unresolved citation as "file:line: 'citation' not in docs/bibliography.md").
set -euo pipefail
cd "$(dirname "$0")/.."
exec python3 - <<'PY'
import os, re, sys, unicodedata

BIB = "docs/bibliography.md"
SELF = "scripts/check-citations.sh"   # its comments show citation forms, they cite nothing
CPP = (".hpp", ".cpp", ".h", ".cc")
WHOLE = (".sh", ".py", ".cmake")

def fold(s):
    """Accents, case and a possessive do not matter: 'Karman' cites 'Kármán'."""
    s = unicodedata.normalize("NFKD", s)
    return re.sub(r"['’]s$", "", "".join(c for c in s if not unicodedata.combining(c))).lower()

YEAR = r"(?:1[89]\d\d|20[0-2]\d)"   # 1800-2029: Willis (1841), Sutherland (1893) are cited
UP = "[" + "".join(chr(c) for c in range(0x41, 0x250) if chr(c).isupper()) + "]"
LET = r"[^\W\d_]"
# A surname: capitalised, with inner hyphens/apostrophes (André, Höhn, Dowson-Higginson,
# Cochran's), optionally after a particle (von Kármán, de Vaujany).
NAME = rf"(?:(?:von|van|de|du|der|den|di|da|le|la)\s+)?{UP}{LET}*(?:[-–'’]{LET}+)*"
AUTH = rf"(?<![\w-]){NAME}(?:(?:\s*,\s*|\s+(?:&|and)\s+|\s+){NAME})*(?:\s+et\s+al\.?)?"
# "(1994", "(2007, 2008", "(2004/2013" or a bare " 1994"; never part of a longer number,
# a decimal, a date or a version (1994.1, 2004-05-01, 2017/2400, 2010:...).
CITE = re.compile(rf"(?P<auth>{AUTH})(?:\s*\((?P<py>{YEAR}(?:\s*[,/]\s*{YEAR})*)|\s+(?P<by>{YEAR}))"
                  rf"(?![\w]|[.:/-]\d)")
STD = re.compile(r"\b(?P<org>ISO(?:/T[RS])?|DIN(?: EN)?|ASTM|ANSI/HI|AGMA|VDI)\s+"
                 r"(?P<num>[A-Z]?\d+(?:\.\d+)*(?:-\d+)*)(?::\d{4})?(?:\s*\(\d{4}\))?"
                 r"|\b(?P<reg>GTR|Regulation)\s+No\.\s*(?P<rnum>\d+)")
SEED = re.compile(r"\bseed[\s-]+(\d{3})\b", re.I)
# Capitalised words that precede years but are no authors ("Fr 2000 N" is a force; two-letter
# words are symbols: Fr, Fa, Re; a two-letter surname would need adding here).
NOT_NAMES = {"copyright", "version", "since", "until", "january", "february", "march",
             "april", "may", "june", "july", "august", "september", "october", "november",
             "december", "table", "figure", "fig", "eq", "section", "part", "annex"}

def std_key(m):
    """(body, number) of a standard reference: 'ISO/TS 6336-20' -> ('ISO', '6336-20')."""
    if m.group("reg"):
        return m.group("reg"), m.group("rnum")
    num = re.sub(r"-(19|20)\d\d$", "", m.group("num"))   # ANSI/HI 9.6.7-2010: the edition
    return m.group("org").split("/")[0].split(" ")[0], num

# --- the bibliography: bold keys by section, and the seed table --------------------------
bib = open(BIB, encoding="utf-8").read()
entries = []   # key, names (first surname with/without particle), years, stds, aliases, used
section = ""
for line in bib.splitlines():
    if line.startswith("## "):
        section = line
    m = re.match(r"\*\*(.+?)\*\*", line)
    if not m:
        continue
    key = m.group(1)
    first = re.search(NAME, key)
    names = {fold(first.group(0)), fold(first.group(0).split()[-1])} if first else set()
    body = bib[bib.index(line):].split("\n\n")[0]
    entries.append(dict(key=key, names=names, used=False,
                        years=set(re.findall(YEAR, key)) if "Standards" not in section else set(),
                        stds={std_key(s) for s in STD.finditer(key)},
                        aliases=re.findall(r'as "([^"]+)"', body)))
seeds = dict(re.findall(r"^\| seed (\d{3}) \|(.*)\|", bib, re.M))   # seed -> its publication

def mask_cpp(src):
    """Comments and string literals kept, code replaced by \\x01 (newlines kept, so line
    numbers hold and a citation wrapped over two comment lines still reads as one)."""
    out, i, n = [], 0, len(src)
    code = lambda s: "".join(c if c.isspace() else "\x01" for c in s)
    while i < n:
        if src.startswith("//", i):
            j = src.find("\n", i); j = n if j < 0 else j
            out.append("  " + src[i + 2:j])
        elif src.startswith("/*", i):
            j = src.find("*/", i + 2); j = n if j < 0 else j + 2
            out.append(re.sub(r"(\n\s*)\*(?!/)", r"\1 ", "  " + src[i + 2:j].replace("*/", "  ")))
        elif src.startswith('R"', i) and (i == 0 or not src[i - 1].isalnum()):
            k = src.find("(", i); end = ")" + src[i + 2:k] + '"'
            j = src.find(end, k); j = n if j < 0 else j + len(end)
            out.append(code(src[i:k + 1]) + src[k + 1:j - len(end)] + code(src[j - len(end):j]))
        elif src[i] in "\"'" and not (src[i] == "'" and i and src[i - 1].isalnum()):
            q, j = src[i], i + 1            # a literal (a ' after a digit is a separator)
            while j < n and src[j] not in (q, "\n"):
                j += 2 if src[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(" " + src[i + 1:j - 1] + " " if q == '"' else code(src[i:j]))
        else:
            j = i + 1
            out.append(code(src[i]))
        i = j
    return "".join(out)

def sources(roots, exts, names=("CMakeLists.txt",)):
    for root in roots:
        for d, dirs, files in os.walk(root):
            dirs.sort()
            for f in sorted(files):
                p = os.path.join(d, f)
                if (f.endswith(exts) or f in names) and p not in (SELF, BIB):
                    yield p

def cites(text):
    """(offset, shown text, kind, value) of every citation in a (masked) text."""
    found = [(m.start(), m.group(0), "std", std_key(m)) for m in STD.finditer(text)]
    text = STD.sub(lambda m: "\x01" * len(m.group(0)), text)   # "ISO 21771 (2007)" is no author
    found += [(m.start(), m.group(0), "seed", m.group(1)) for m in SEED.finditer(text)]
    for m in CITE.finditer(text):
        row = text[text.rfind("\n", 0, m.start()) + 1:text.find("\n", m.end())]
        if re.search(r"copyright|©|SPDX", row, re.I):
            continue
        auth, py = " ".join(m.group("auth").split()), m.group("py")
        # The first author is a word of the first group (before ",", "&", "and", "et al."):
        # "MAAG Gear Book 1990" and "the SKF 2004 model" name MAAG and SKF.
        group = re.split(r"\s*,\s*|\s+(?:&|and)\s+|\s+et\s+al", auth)[0]
        words = [w for w in re.findall(NAME, group) if len(fold(w).split()[-1]) >= 3 and fold(w) not in NOT_NAMES]
        for y in re.findall(YEAR, py or m.group("by")) if words else []:
            shown = f"{auth} ({y if ',' in py or '/' in py else py})" if py else f"{auth} {y}"
            found.append((m.start(), shown, "author", (words, y)))
    return found

def resolve(kind, value):
    """The entries a citation resolves to (empty: unresolved)."""
    if kind == "seed":   # the seed's own key, else the publication its table row names
        return [e for e in entries if e["key"].endswith(f"(seed {value})")] or \
               [e for _, _, k, v in cites(seeds.get(value, "")) if k == "author" for e in resolve(k, v)]
    if kind == "std":
        body, num = value
        return [e for e in entries for b, k in e["stds"] if b == body and (k == num or k.startswith(num + "-"))]
    words, year = value
    cands = {fold(w) for w in words} | {fold(w.split()[-1]) for w in words}
    cands |= {re.split("[-–]", c)[0] for c in cands}   # "Dowson-Higginson (1966)"
    return [e for e in entries if year in e["years"] and e["names"] & cands]

bad, count, files, keys, texts = [], {"author": 0, "std": 0, "seed": 0}, set(), set(), []
docs = [p for p in list(sources(["docs", "configs"], (".md", ".yaml", ".yml"))) + ["README.md"]
        if os.path.exists(p)]
for path in list(sources(["lib", "app", "tests", "scripts"], CPP + WHOLE)) + docs:
    text = open(path, encoding="utf-8", errors="replace").read()
    if path.endswith(CPP):
        text = mask_cpp(text)
    texts.append(text)
    for pos, shown, kind, value in sorted(cites(text), key=lambda c: c[0]):
        hits, where = resolve(kind, value), f"{path}:{text.count(chr(10), 0, pos) + 1}"
        for e in hits:
            e["used"] = True
        if path in docs:      # prose and shipped cases: warned about, and used by the reverse check
            if not hits:
                print(f"check-citations: warning: {where}: '{shown}' not in {BIB}", file=sys.stderr)
            continue
        count[kind] += 1
        files.add(path)
        keys |= {e["key"] for e in hits}
        if not hits:
            bad.append(f"{where}: '{shown}' not in {BIB}")

# Reverse check, warnings only: an entry counts as cited when a citation resolves to it, or
# (no standard number) its first surname or an alias ('as "ARTEMIS"') appears anywhere,
# e.g. "Eyring stress", "Blok partition", "Simrit/Freudenberg".
every = "\n".join(texts)
for e in entries:
    first = re.search(NAME, e["key"])
    names = e["aliases"] + ([first.group(0)] if first and not e["stds"] else [])
    if not e["used"] and not any(re.search(rf"\b{re.escape(a)}\b", every) for a in names):
        print(f"check-citations: warning: '{e['key']}' in {BIB} is cited nowhere", file=sys.stderr)

if bad:
    print("\n".join(bad))
    print(f"check-citations: {len(bad)} unresolved citation(s)", file=sys.stderr)
    sys.exit(1)
print(f"check-citations: {sum(count.values())} citations in {len(files)} files "
      f"({count['author']} author-year, {count['std']} standard, {count['seed']} seed) "
      f"resolve to {len(keys)} of the {len(entries)} entries of {BIB}")
PY
