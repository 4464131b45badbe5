#!/usr/bin/env python3
"""The gear data of an imported REXS case against the REXS file itself, read here with
xml.etree (not with gearloss's reader) and the case with PyYAML (not with gearloss's loader).

usage: rexs_independent.py MODEL.rexs CASE.yaml OIL.yaml   (OIL.yaml "-": a model without a lubricant)
Checks, for every cylindrical gear: teeth, normal module, face width, helix angle and hand
(ISO 21771: positive = right), profile shift and pressure angle of its flanks, position on its
shaft; for every cylindrical stage: its gears and centre distance; the oil's viscosities at
40 and 100 degC and its density. Units: the REXS unit of each attribute (mm, deg or the degree
sign REXS 1.0 and 1.1 exporters write, mm^2/s, kg/dm^3) converted here by hand.
"""
import sys
import xml.etree.ElementTree as ET

import yaml

model, case_file, oil_file = sys.argv[1:4]
root = ET.parse(model).getroot()
comps = {int(c.get("id")): c for c in root.find("components")}
rels = list(root.find("relations"))
case = yaml.safe_load(open(case_file))
oil = None if oil_file == "-" else yaml.safe_load(open(oil_file))
failures = []


def attr(c, name):
    for a in c.findall("attribute"):
        if a.get("id") == name:
            return a.get("unit"), (a.text or "").strip()
    return None, None


def mm(c, name):
    unit, v = attr(c, name)
    assert unit == "mm", (name, unit)
    return float(v)


def qty(text):
    """'117 mm' -> 117.0 (the number; the unit is checked by the caller)"""
    value, unit = str(text).split()
    return float(value), unit


def expect(what, got, want, tol=1e-9):
    if abs(got - want) > tol * max(1.0, abs(want)):
        failures.append(f"{what}: case {got}, REXS {want}")


gears = {g["name"]: g for g in case["gears"]}
n_gears = 0
for cid, c in comps.items():
    if c.get("type") != "cylindrical_gear":
        continue
    n_gears += 1
    g = gears[f"gear_{cid}"]
    expect(f"gear {cid} teeth", g["teeth"], abs(int(attr(c, "number_of_teeth")[1])))
    v, u = qty(g["module"]); assert u == "mm"
    expect(f"gear {cid} module", v, mm(c, "normal_module"))
    v, u = qty(g["face_width"]); assert u == "mm"
    expect(f"gear {cid} face width", v, mm(c, "face_width"))
    v, u = qty(g["position"]); assert u == "mm"
    expect(f"gear {cid} position", v, mm(c, "u_coordinate_on_shaft"))
    unit, beta = attr(c, "helix_angle_reference_diameter")
    assert unit in ("deg", "\u00b0"), unit
    beta = float(beta)
    v, u = qty(g["helix_angle"]); assert u == "deg"
    expect(f"gear {cid} helix angle", v, abs(beta))
    if g["hand"] != ("right" if beta > 0 else "left"):
        failures.append(f"gear {cid} hand {g['hand']} for REXS helix angle {beta}")
    flanks = [comps[int(r.get("id"))] for rel in rels if rel.get("type") == "flank"
              and any(r.get("role") == "gear" and int(r.get("id")) == cid for r in rel)
              for r in rel if r.get("role") in ("left", "right")]
    assert len(flanks) == 2, cid
    for f in flanks:
        expect(f"gear {cid} profile shift", float(g["profile_shift"]), float(attr(f, "addendum_modification_coefficient")[1]))
        v, u = qty(g["pressure_angle"]); assert u == "deg"
        expect(f"gear {cid} pressure angle", v, float(attr(f, "normal_pressure_angle")[1]))

meshes = {m["name"]: m for m in case["meshes"]}
for rel in rels:
    if rel.get("type") != "stage":
        continue
    roles = {r.get("role"): int(r.get("id")) for r in rel}
    m = meshes[f"stage_{roles['stage']}"]
    if m["gears"] != [f"gear_{roles['gear_1']}", f"gear_{roles['gear_2']}"]:
        failures.append(f"stage {roles['stage']} gears {m['gears']}")
    v, u = qty(m["centre_distance"]); assert u == "mm"
    expect(f"stage {roles['stage']} centre distance", v, mm(comps[roles["stage"]], "center_distance"))

lub = next((c for c in comps.values() if c.get("type") == "lubricant"), None)
if (lub is None) != (oil is None):
    failures.append("a lubricant in the model and an oil file go together")
if lub is not None:
    pts = oil["viscosity"]["points"]
    assert attr(lub, "viscosity_at_40_degree_celsius")[0] == "mm^2 / s"
    expect("nu40", qty(pts[0][1])[0], float(attr(lub, "viscosity_at_40_degree_celsius")[1]))
    expect("nu100", qty(pts[1][1])[0], float(attr(lub, "viscosity_at_100_degree_celsius")[1]))
    unit, rho = attr(lub, "density_at_15_degree_celsius")
    assert unit == "kg / dm^3"
    expect("density", qty(oil["density"]["value"])[0], float(rho) * 1000)  # 1 kg/dm^3 = 1000 kg/m^3

if n_gears == 0:
    failures.append("no cylindrical gear in the model")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"{n_gears} gears, {len(meshes)} stages" + ("" if lub is None else " and the oil") + " equal the REXS attributes")
