#!/usr/bin/env python3
"""Time-at-level load spectrum of a wind-turbine gearbox over one year (standard library only).

The hub-height wind speed follows a Weibull distribution (shape k, scale c; k = 2 is the
Rayleigh distribution of the IEC 61400-1 turbine classes), split into 1 m/s bins centred on
the whole speeds from cut-in to cut-out. Each bin's rotor (gearbox input) power comes from a
generic power curve: zero below cut-in, the cubic rise
    P(v) = P_rated (v^3 - v_in^3) / (v_rated^3 - v_in^3)      v_in <= v < v_rated
and P_rated from rated to cut-out. The rotor speed follows a constant tip-speed ratio,
n = 60 lambda v / (2 pi R), held between the minimum and the rated rotor speed; the torque is
P / omega. Outside cut-in..cut-out the rotor idles or stands still: those hours are left out
(the gearbox's idling losses are not part of this spectrum).

Usage: scripts/wind-spectrum.py [-k 2] [-c 8] [-o configs/spectra/wind-2.5MW-weibull.csv]
"""
import argparse
import math
import sys

HOURS_PER_YEAR = 8760.0


def weibull_cdf(v, k, c):
    return 1.0 - math.exp(-((max(v, 0.0) / c) ** k))


def rotor_power(v, p_rated, v_in, v_rated, v_out):
    if v < v_in or v > v_out:
        return 0.0
    if v >= v_rated:
        return p_rated
    return p_rated * (v ** 3 - v_in ** 3) / (v_rated ** 3 - v_in ** 3)


def rotor_speed_rpm(v, tsr, radius, n_min, n_rated):
    n = 60.0 * tsr * v / (2.0 * math.pi * radius)
    return min(max(n, n_min), n_rated)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("-k", type=float, default=2.0, help="Weibull shape (default 2)")
    p.add_argument("-c", type=float, default=8.0, help="Weibull scale at hub height, m/s (default 8)")
    p.add_argument("--rated-power", type=float, default=2.5e6, help="rotor power at rated wind, W (default 2.5e6)")
    p.add_argument("--cut-in", type=float, default=3.0, help="m/s (default 3)")
    p.add_argument("--rated", type=float, default=12.0, help="m/s (default 12)")
    p.add_argument("--cut-out", type=float, default=25.0, help="m/s (default 25)")
    p.add_argument("--tsr", type=float, default=8.0, help="tip-speed ratio below rated (default 8)")
    p.add_argument("--radius", type=float, default=50.0, help="rotor radius, m (default 50)")
    p.add_argument("--min-speed", type=float, default=9.0, help="minimum rotor speed, rpm (default 9)")
    p.add_argument("--rated-speed", type=float, default=16.0, help="rated rotor speed, rpm (default 16)")
    p.add_argument("-o", "--output", default="-", help="CSV file ('-' = stdout)")
    a = p.parse_args(argv)
    rows = []
    for v in range(int(math.ceil(a.cut_in)), int(math.floor(a.cut_out)) + 1):
        share = weibull_cdf(v + 0.5, a.k, a.c) - weibull_cdf(v - 0.5, a.k, a.c)
        power = rotor_power(v, a.rated_power, a.cut_in, a.rated, a.cut_out)
        n = rotor_speed_rpm(v, a.tsr, a.radius, a.min_speed, a.rated_speed)
        torque = power / (n * math.pi / 30.0)
        rows.append((v, n, torque, share * HOURS_PER_YEAR))
    lines = [
        f"# Weibull k = {a.k:g}, c = {a.c:g} m/s; generic {a.rated_power / 1e6:g} MW power curve "
        f"(cut-in {a.cut_in:g}, rated {a.rated:g}, cut-out {a.cut_out:g} m/s); rotor speed at tip-speed ratio "
        f"{a.tsr:g}, R = {a.radius:g} m, within {a.min_speed:g}..{a.rated_speed:g} rpm; one year = {HOURS_PER_YEAR:g} h",
        "# made by scripts/wind-spectrum.py",
        "label,speed_in_rpm,torque_in_kNm,hours",
    ]
    for v, n, t, h in rows:
        lines.append(f"{v} m/s,{n:.4f},{t / 1e3:.3f},{h:.3f}")
    text = "\n".join(lines) + "\n"
    if a.output == "-":
        sys.stdout.write(text)
    else:
        with open(a.output, "w", encoding="utf-8") as f:
            f.write(text)


if __name__ == "__main__":
    main(sys.argv[1:])
