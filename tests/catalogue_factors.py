#!/usr/bin/env python3
"""Every load factor of the shipped bearing catalogue checked against the contact angle and a
second source (docs/config.md, "Bearing designations").

The YAML is read with PyYAML, not with gearloss's loader, so a slip of the C++ reader cannot hide
a slip of the file. For every row that carries e and Y (the tapered roller rows):

1. Contact-angle relations. A single-row tapered roller bearing of contact angle alpha has
   e = 1.5 tan(alpha) and, for Fa/Fr > e, X = 0.4, Y = 0.4 cot(alpha) (ISO 281:2007, X and Y of
   radial roller bearings with alpha != 0 [table number unconfirmed]); its static factor is
   Y0 = 0.22 cot(alpha) (ISO 76:2006, X0 and Y0 of radial roller bearings [table number
   unconfirmed]). The printed e, Y (and Y0 where given, to a whole unit of its last digit: see
   alpha_interval) must come from one alpha: the angle intervals they allow overlap.
2. ISO 355 contact-angle series. The series printed by the second source (e.g. 3DC for 32210)
   bounds alpha: series 2 over 10 deg up to 13 deg 52', 3 up to 15 deg 59', 4 up to 18 deg 55',
   5 up to 23 deg, 6 up to 27 deg, 7 up to 30 deg (ISO 355:2019 clause 5; the limits as printed
   in NTN (2020) CAT. No. 2203/E, Table 5.4 (1)). The row's alpha interval must meet that band.
3. Second sources (tests/catalogue_factors_sources.tsv): SKF (2017) PUB BU/P1 10000/3 RU, the
   same maker's later edition, for every row; NSK (2005) CAT. No. E1102e, another maker, where it
   lists a bearing of the same ISO 355 series. Each source's own e, Y, Y0 pass check 1 as well
   (a transcription check of the table).

Tolerance: the rounding of the catalogues. They print e to two decimals (0.4 is 0.40) and Y, Y0
to one decimal unless a second one is printed (1.05, 0.72): a printed value stands for any true
value within half a unit of its last digit (e +-0.005, Y +-0.05 or +-0.005). Two prints of one
bearing therefore agree within the sum of their half-units (e: 0.01; Y: 0.1), and the angle
intervals of check 1 are those half-units mapped through the relations. A row outside them is
named with its values and the failing check.

The angular contact ball rows carry no e or Y (only contact_angle): their designation suffix must
name the same angle (SKF: B = 40 deg, AC = 25 deg), and a row that did carry e and Y would be
checked against ISO 281:2007 Table 3 (single row: 25 deg e 0.68, Y 0.87; 30 deg 0.80, 0.76;
40 deg 1.14, 0.57; as printed in NSK (2005) CAT. No. E1102e).

Usage: catalogue_factors.py SOURCE_DIR [CATALOGUE_YAML]
"""
import math
import os
import re
import sys

import yaml

src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
cat_file = sys.argv[2] if len(sys.argv) > 2 else os.path.join(src, "configs", "bearings", "catalogue.yaml")
sources_file = os.path.join(src, "tests", "catalogue_factors_sources.tsv")

DEG = math.pi / 180
# ISO 355 contact-angle series: (over, up to and including), radians.
ANGLE_SERIES = {
    "2": (10 * DEG, (13 + 52 / 60) * DEG),
    "3": ((13 + 52 / 60) * DEG, (15 + 59 / 60) * DEG),
    "4": ((15 + 59 / 60) * DEG, (18 + 55 / 60) * DEG),
    "5": ((18 + 55 / 60) * DEG, 23 * DEG),
    "6": (23 * DEG, 27 * DEG),
    "7": (27 * DEG, 30 * DEG),
}
# ISO 281:2007 Table 3, single-row angular contact ball bearings: contact angle -> (e, Y).
ISO281_ACBB = {25: (0.68, 0.87), 30: (0.80, 0.76), 40: (1.14, 0.57)}
# SKF designation suffixes of the angular contact rows and the angle they name.
ACBB_SUFFIX_ANGLE = {"B": 40, "AC": 25}


def half_unit(printed, min_decimals):
    """Half a unit of the last printed digit, at least min_decimals (catalogues print e as 0.4)."""
    s = printed if isinstance(printed, str) else repr(float(printed))
    dec = len(s.split(".")[1].rstrip("0")) if "." in s else 0
    return 0.5 * 10.0 ** -max(dec, min_decimals)


def alpha_interval(e=None, Y=None, Y0=None):
    """The contact angles (rad) that the printed e, Y, Y0 allow, each within its rounding; None if empty.
    e = 1.5 tan a, Y = 0.4 cot a, Y0 = 0.22 cot a. Y0 is held to a whole unit of its last digit, not
    half: both makers print it from a value of their own (SKF 30302: e 0.28 gives 0.22 cot a = 1.18,
    SKF prints 1.1; NSK 30306: e 0.32 gives 1.03, NSK prints 1.1)."""
    lo, hi = 0.0, math.pi / 2
    if e is not None:
        h = half_unit(e, 2)
        lo, hi = max(lo, math.atan((float(e) - h) / 1.5)), min(hi, math.atan((float(e) + h) / 1.5))
    for val, k, units in ((Y, 0.4, 1), (Y0, 0.22, 2)):
        if val is not None:
            h = units * half_unit(val, 1)
            lo, hi = max(lo, math.atan(k / (float(val) + h))), min(hi, math.atan(k / (float(val) - h)))
    return (lo, hi) if lo <= hi else None


def deg(a):
    return f"{a / DEG:.2f} deg"


def main():
    cat = yaml.safe_load(open(cat_file))
    sources = {}
    for line in open(sources_file):
        if line.startswith("#") or not line.strip():
            continue
        f = line.rstrip("\n").split("\t")
        sources[f[0]] = {"skf": (f[1], f[2], f[3], f[4], f[5]),
                         "nsk": None if f[6] == "-" else (f[6], f[7], f[8], f[9], f[10])}
    bad, checked, seen = [], 0, set()
    for s in cat["series"]:
        cols = s["columns"]
        for r in s["bearings"]:
            row = dict(zip(cols, r))
            d = row["designation"]
            where = f"series '{s['series']}' row '{d}'"
            if s["type"] == "angular_contact_ball":
                suffix = re.match(r"^\d+\s*([A-Z]+)", d)
                angle = ACBB_SUFFIX_ANGLE.get("AC" if suffix and suffix.group(1).startswith("AC") else
                                              "B" if suffix and suffix.group(1).startswith("B") else "")
                stated = s.get("contact_angle")
                if angle is None or stated != f"{angle} deg":
                    bad.append(f"{where}: contact_angle '{stated}' but the suffix names {angle} deg")
                if "e" in row or "Y" in row:
                    want = ISO281_ACBB.get(angle)
                    if want is None or abs(row.get("e", want[0]) - want[0]) > 0.005 or \
                            abs(row.get("Y", want[1]) - want[1]) > 0.005:
                        bad.append(f"{where}: e {row.get('e')}, Y {row.get('Y')} differ from ISO 281 "
                                   f"Table 3 for {angle} deg: {want}")
                continue
            if "e" not in row and "Y" not in row:
                continue
            checked += 1
            seen.add(d)
            e, Y, Y0 = row.get("e"), row.get("Y"), row.get("Y0")
            a = alpha_interval(e, Y, Y0)
            if a is None:
                bad.append(f"{where}: e {e}, Y {Y}" + (f", Y0 {Y0}" if Y0 is not None else "") +
                           " fit no single contact angle (e = 1.5 tan a, Y = 0.4 cot a, Y0 = 0.22 cot a)")
                a = alpha_interval(e)
            src2 = sources.get(d)
            if src2 is None:
                bad.append(f"{where}: no second source in tests/catalogue_factors_sources.tsv")
                continue
            for name, vals in (("SKF (2017) 10000/3 RU", src2["skf"]), ("NSK (2005) E1102e", src2["nsk"])):
                if vals is None:
                    continue
                des2, iso, e2, Y2, Y02 = vals
                if name.startswith("NSK") and iso != src2["skf"][1]:
                    continue  # another design (NSK's own steep angle): not the catalogue's bearing
                if alpha_interval(e2, Y2, Y02) is None:
                    bad.append(f"{where}: {name} '{des2}' e {e2}, Y {Y2}, Y0 {Y02} fit no single contact "
                               "angle (a transcription slip in the sources table?)")
                lo, hi = ANGLE_SERIES.get(iso[:1], (None, None))
                if lo is None:
                    bad.append(f"{where}: {name} '{des2}' ISO 355 series '{iso}' has no contact-angle band")
                elif a[1] <= lo or a[0] > hi:
                    bad.append(f"{where}: e {e} means a contact angle of {deg(a[0])}..{deg(a[1])}, outside "
                               f"ISO 355 angle series {iso[:1]} ({deg(lo)}..{deg(hi)}) that {name} prints "
                               f"for '{des2}' ({iso})")
                tol_e = half_unit(e, 2) + half_unit(e2, 2)
                tol_Y = half_unit(Y, 1) + half_unit(Y2, 1)
                if abs(e - float(e2)) > tol_e + 1e-12 or abs(Y - float(Y2)) > tol_Y + 1e-12:
                    bad.append(f"{where}: e {e}, Y {Y} but {name} prints e {e2}, Y {Y2} for '{des2}' "
                               f"(rounding allows e +-{tol_e:.3f}, Y +-{tol_Y:.3f})")
    for d in sorted(set(sources) - seen):
        bad.append(f"tests/catalogue_factors_sources.tsv: '{d}' is no row with e and Y in the catalogue")
    if checked == 0:
        bad.append("no catalogue row carries e and Y: nothing was checked")
    for b in bad:
        print(f"FAIL {os.path.basename(cat_file)}: {b}")
    print(f"{checked} rows with e and Y checked against the contact-angle relations, the ISO 355 angle "
          f"series and two second sources: {len(bad)} disagreements")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
