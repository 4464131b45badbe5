#!/usr/bin/env python3
"""Generated valid gearboxes for the operating-envelope suite: seeded and deterministic,
single- and two-stage, spur and helical, sizes and forms drawn independently of the shipped
cases. Geometry is consistent: each mesh's working centre distance is the one ISO 21771
gives for the chosen profile shifts (inv a_wt = inv a_t + 2 tan a_n (x1 + x2) / (z1 + z2),
a_w = a_d cos a_t / cos a_wt), bearings are designations of the shipped catalogue sized to
the shaft, the oil is a shipped oil and the lowest wheel dips into it.

    generate_cases.py --source DIR --out DIR [--seed N] [--count N]
"""
import argparse
import math
import os
import random
import re
import sys

ALPHA_N = math.radians(20.0)   # ISO 53 basic rack


def involute(a):
    return math.tan(a) - a


def inverse_involute(v):
    """Newton on inv(a) = v (monotone on (0, pi/2))."""
    a = (3.0 * v) ** (1.0 / 3.0)
    for _ in range(50):
        f = involute(a) - v
        a -= f / math.tan(a) ** 2
        if abs(f) < 1e-15:
            break
    return a


def working_centre_distance(z1, z2, m_n, beta, x1, x2):
    """ISO 21771 (2007) eqs. for the working transverse pressure angle and centre distance [mm]."""
    alpha_t = math.atan(math.tan(ALPHA_N) / math.cos(beta))
    inv_wt = involute(alpha_t) + 2.0 * math.tan(ALPHA_N) * (x1 + x2) / (z1 + z2)
    alpha_wt = inverse_involute(inv_wt)
    a_d = m_n * (z1 + z2) / (2.0 * math.cos(beta))
    return a_d * math.cos(alpha_t) / math.cos(alpha_wt)


def read_catalogue(path):
    """(series, type, designation, d, D, width) rows of the shipped catalogue, read as text."""
    rows, series, btype = [], None, None
    with open(path) as f:
        lines = f.readlines()
    for line in lines:
        m = re.match(r'\s*- series: "([^"]+)"', line)
        if m:
            series = m.group(1)
        m = re.match(r"\s*type: (\w+)", line)
        if m:
            btype = m.group(1)
        m = re.match(r'\s*- \["([^"]+)", ([\d.]+), ([\d.]+), ([\d.]+)', line)
        if m and series:
            rows.append((series, btype, m.group(1), float(m.group(2)), float(m.group(3)),
                         float(m.group(4))))
    return rows


# Bearing arrangements of a shaft: (series of the locating one, of the floating one). Tapered and
# angular-contact bearings are used in pairs (both locating), as they are built.
ARRANGEMENTS = [("62", "62"), ("63", "63"), ("63", "NJ 2"), ("62", "NU 2"), ("63", "NJ 3"),
                ("302", "302"), ("303", "303"), ("72 B", "72 B")]


def pick_bearing(rows, series, d_min):
    fits = sorted((r for r in rows if r[0] == series and r[3] >= d_min), key=lambda r: r[3])
    if not fits:
        fits = sorted((r for r in rows if r[0] == series), key=lambda r: -r[3])
    return fits[0]


def shaft_bore(torque_Nm):
    """Shaft diameter [mm] for a 40 MPa nominal torsional stress: d = (16 T / (pi tau))^(1/3)."""
    return max(20.0, (16.0 * torque_Nm / (math.pi * 40e6)) ** (1.0 / 3.0) * 1000.0)


def contact_torque(z1, u, m_n, beta, b, sigma_H=1100.0):
    """Pinion torque [N m] for a nominal Hertz stress sigma_H [MPa] of the pitch-point line
    contact without load factors: F_t = sigma_H^2 b d1 u / ((u + 1) (Z_E Z_H)^2), Z_E 189.8 sqrt(MPa), Z_H ~ 2.45."""
    d1 = m_n * z1 / math.cos(beta)
    F_t = sigma_H ** 2 * b * d1 * u / ((u + 1.0) * (189.8 * 2.45) ** 2)
    return F_t * d1 / 2000.0


def stage(rng, m_n, helical):
    z1 = rng.randint(15, 31)
    u = rng.uniform(1.3, 4.2)
    z2 = max(z1 + 1, round(z1 * u))
    beta = math.radians(rng.uniform(10.0, 25.0)) if helical else 0.0
    x1 = round(rng.uniform(0.0, 0.5), 3)
    x2 = round(rng.uniform(-0.3, 0.3), 3)
    b = round(m_n * rng.uniform(7.0, 13.0), 1)
    return dict(z1=z1, z2=z2, m_n=m_n, beta=beta, x1=x1, x2=x2, b=b,
                a_w=working_centre_distance(z1, z2, m_n, beta, x1, x2))


def tip_radius(z, m_n, beta, x):
    return m_n * z / (2.0 * math.cos(beta)) + m_n * (1.0 + x)


def generate(rng, index, source):
    source = os.path.abspath(source)
    oils = sorted(f for f in os.listdir(os.path.join(source, "configs", "oils")) if f.endswith(".yaml"))
    oil = os.path.join(source, "configs", "oils", rng.choice(oils))
    catalogue = read_catalogue(os.path.join(source, "configs", "bearings", "catalogue.yaml"))
    helical = rng.random() < 0.6
    two_stage = rng.random() < 0.5
    hands = ("right", "left")
    m1 = rng.choice([1.5, 2.0, 2.5, 3.0, 4.0, 5.0])
    stages = [stage(rng, m1, helical)]
    if two_stage:
        stages.append(stage(rng, rng.choice([m1, m1 * 1.25, m1 * 1.5, m1 * 2.0]), helical))
    shafts = ["input", "inter", "output"] if two_stage else ["input", "output"]
    # Input torque: the first stage's pinion at its contact-stress torque, and no more than the
    # second stage's pinion carries after the first stage's ratio.
    T_in = contact_torque(stages[0]["z1"], stages[0]["z2"] / stages[0]["z1"], m1, stages[0]["beta"],
                          stages[0]["b"])
    if two_stage:
        s = stages[1]
        T_in = min(T_in, contact_torque(s["z1"], s["z2"] / s["z1"], s["m_n"], s["beta"], s["b"])
                   * stages[0]["z1"] / stages[0]["z2"])
    T_in = float(f"{T_in:.2g}")
    # Speed: pitch-line velocity of the first pinion up to 15..30 m/s, at most 6000 rpm.
    d1 = m1 * stages[0]["z1"] / math.cos(stages[0]["beta"])
    n_max = min(6000.0, rng.uniform(15.0, 30.0) / (math.pi * d1 / 1000.0) * 60.0)
    n_max = float(f"{n_max:.2g}")

    lines = [f"# Generated by tests/envelope/generate_cases.py (case {index}); dimensions are drawn,",
             "# not measured: a valid gearbox for the operating-envelope properties.",
             f"name: generated {index} ({'two' if two_stage else 'single'}-stage "
             f"{'helical' if helical else 'spur'})", f"oil: {oil}", "", f"shafts: [{', '.join(shafts)}]",
             "", "gears:"]
    gear_lines, mesh_lines, centres, tips = [], [], {"input": (0.0, 0.0)}, []
    axial = 40.0
    torque_on = {"input": T_in}
    for k, s in enumerate(stages):
        a, b = shafts[k], shafts[k + 1]
        angle = rng.uniform(-75.0, -10.0)
        h0, h1 = (hands[k % 2], hands[(k + 1) % 2]) if helical else (None, None)
        for name, shaft, z, x, hand in ((f"p{k + 1}", a, s["z1"], s["x1"], h0),
                                        (f"w{k + 1}", b, s["z2"], s["x2"], h1)):
            g = (f"  - {{name: {name}, shaft: {shaft}, position: {axial:.1f} mm, teeth: {z}, "
                 f"module: {s['m_n']:g} mm, profile_shift: {x:g}, face_width: {s['b']:g} mm")
            if helical:
                g += f", helix_angle: {math.degrees(s['beta']):.3f} deg, hand: {hand}"
            g += f", Ra: {rng.choice([0.2, 0.3, 0.4, 0.5, 0.8]):g} um}}"
            gear_lines.append(g)
        cx, cy = centres[a]
        th = math.radians(angle)
        centres[b] = (cx + s["a_w"] * math.cos(th), cy + s["a_w"] * math.sin(th))
        tips.append((centres[b][1] - tip_radius(s["z2"], s["m_n"], s["beta"], s["x2"]),
                     tip_radius(s["z2"], s["m_n"], s["beta"], s["x2"])))
        mesh_lines.append(f"  - {{name: m{k + 1}, gears: [p{k + 1}, w{k + 1}], angle: {angle:.2f} deg, "
                          f"centre_distance: {s['a_w']:.5f} mm}}")
        torque_on[b] = torque_on[a] * s["z2"] / s["z1"]
        axial += s["b"] + 25.0
    lines += gear_lines + ["", "meshes:  # working centre distances of ISO 21771 for the shifts"]
    lines += mesh_lines + ["", "bearings:"]
    length = axial + 15.0
    seal_lines = []
    for shaft in shafts:
        loc, flo = rng.choice(ARRANGEMENTS)
        d_min = shaft_bore(torque_on[shaft])
        for name, series, pos, locating in ((f"{shaft}_a", loc, 0.0, True),
                                            (f"{shaft}_b", flo, length, loc == flo and loc[0] in "37")):
            row = pick_bearing(catalogue, series, d_min)
            entry = f"  - {{name: {name}, designation: \"{row[2]}\", shaft: {shaft}, position: {pos:.1f} mm"
            lines.append(entry + (", locating: true}" if locating else "}"))
        if shaft in ("input", "output"):
            seal_lines.append(f"  - {{name: {shaft}_seal, shaft: {shaft}, diameter: "
                              f"{pick_bearing(catalogue, loc, d_min)[3]:g} mm}}")
    # Dip lubrication: the oil surface a drawn depth (2 modules up to the wheel's centre) above
    # the lowest wheel tip.
    lowest, r_tip = min(tips)
    depth = rng.uniform(2.0 * m1, 0.9 * r_tip)
    size = max(abs(c[1]) for c in centres.values()) + 2 * r_tip
    lines += ["", "seals:"] + seal_lines + ["", "housing:",
              f"  oil_volume: {max(0.3, round((size / 150.0) ** 2 * rng.uniform(0.6, 1.6), 2)):g} L",
              f"  oil_level: {lowest + depth:.2f} mm", "", "thermal:", "  mode: stabilised",
              "  ambient: 25 degC", f"  heat_capacity: {round(5 + size / 20.0):g} kJ/K",
              "  heat_rejection:",
              f"    housing: {{area: {max(0.1, round((size / 300.0) ** 2 * 1.2, 2)):g} m^2, "
              "emissivity: 0.9, height: 0.3 m}", "", "gearbox:", "  input: input", "  output: output",
              "", "operating:",
              f"  speeds: [{n_max / 4:g} rpm, {n_max / 2:g} rpm, {n_max:g} rpm]",
              f"  torques: [{T_in / 4:g} N*m, {T_in / 2:g} N*m, {T_in:g} N*m]", ""]
    # Windage is off unless a form is chosen (docs/config.md): half the cases choose one, so
    # that its physics is swept too.
    form = rng.choice([None, "anderson_loewenthal", "free_disk"])
    if form:
        lines += ["mechanisms:", f"  windage: {{form: {form}}}", ""]
    return "\n".join(lines)


def write_cases(source, out, seed=2024, count=6):
    rng = random.Random(seed)
    os.makedirs(out, exist_ok=True)
    paths = []
    for i in range(count):
        path = os.path.join(out, f"generated-{seed}-{i}.yaml")
        with open(path, "w") as f:
            f.write(generate(rng, i, source))
        paths.append(path)
    return paths


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--source", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--seed", type=int, default=2024)
    ap.add_argument("--count", type=int, default=6)
    a = ap.parse_args()
    print("\n".join(write_cases(a.source, a.out, a.seed, a.count)))
    sys.exit(0)
