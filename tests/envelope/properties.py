"""The physics each loss mechanism must show across the operating envelope, and the curve
tests that check it. Every expectation carries its reason; a mechanism the tool reports that
is not described here gets the generic checks only (finite, no step, no loss below zero)."""
import math

# Relative rise per 2 K allowed for a loss that must fall or stay as the oil warms: the grid's
# numerical noise is far below it, and the Changenet & Velex (2007) regime blend must not add it.
WARMING_RISE_PER_2K = 0.03
# A step: between neighbouring grid points, a change of ln P that differs from what the two
# neighbouring intervals' trend predicts by more than this (0.10 ~ 10 %) and by more than twice
# the spread of the neighbours' own slopes (a smooth curve bends, it does not jump).
STEP_LN = 0.10

# Physics of each mechanism, by the name the tool gives it (point --json "mechanisms").
#   warming: -1 the loss falls or stays as the oil warms, None no sign required (named regimes)
#   speed:   +1 the loss rises (or stays) with speed
#   load:    "none" independent of the transmitted torque, "abs" rises with |torque| on both
#            sides, "positive" rises with torque for torque >= 0 (signed torque near zero is not
#            monotone: a reversed gear force can cancel part of a shaft's weight)
#   turning: True the loss is > 0 whenever its parts turn, whatever the torque
#   speed_falls_in: regimes (as `point` names them) in which the loss may fall with speed
#            although speed=+1: the fall is excused where a component of the mechanism is in
#            one of them at either end of the interval
#   speed_falls_across: (from, to) regimes: a fall is also excused where a component goes from
#            `from` at the lower speed to `to` at the higher one (it passed through
#            speed_falls_in between the grid points)
PHYSICS = {
    "churning": dict(
        warming=-1, speed=+1, load="none", turning=True,
        why="oil drag on dipping gears: Changenet & Velex (2007) torque ~ rho Re^a Fr^b with "
            "Re falling exponents, so a thinner oil never churns more; grows with speed; no "
            "term of the transmitted load"),
    "windage": dict(
        warming=-1, speed=+1, load="none", turning=True,
        why="air/oil-mist drag of the gear faces and teeth (Anderson & Loewenthal 1980): falls "
            "with the medium's viscosity and density, rises with speed, load-free"),
    "seals": dict(
        warming=-1, speed=+1, load="none", turning=True,
        why="lip seal friction (SKF 2004 seal term): a function of shaft diameter and speed; a "
            "warmer, thinner oil under the lip does not raise it; load-free"),
    "clutch_drag": dict(
        warming=-1, speed=+1, load="none", turning=False,
        speed_falls_in=("film_breaking_up",), speed_falls_across=("full_film", "film_broken"),
        why="viscous shear in the open plate gaps (tau = eta omega r / h): falls with viscosity, "
            "rises with slip speed while the film is full, load-free; zero when no pack is open. "
            "Once the supply cannot fill the gap against the centrifugal outflow the full film "
            "shrinks (Yuan et al. 2007) and the oil beyond it runs as streaks whose share falls as "
            "1/omega^2: the drag peaks and falls gradually with speed (measured by Iqbal et al. "
            "2013): a fall is allowed only where `point` names a pack's film breaking up"),
    "auxiliary": dict(
        warming=-1, speed=+1, load="none", turning=False,
        why="parasitic pump/accessory power: constant or viscous, never rises with warming"),
    "bearings": dict(
        warming=None, speed=+1, load="positive", turning=True,
        why="SKF (2004): rolling and drag moments fall with viscosity but sliding friction rises "
            "as phi_bl falls in the mixed regime (no warming sign); every moment grows with speed; "
            "loads grow with gear forces; shaft weights load the bearings, so a turning bearing "
            "always loses power"),
    "mesh": dict(
        warming=None, speed=+1, load="abs", turning=False,
        why="Coulomb friction on the flanks, P = mu F_N v_g: Schlenk mu ~ eta^-0.05 rises as the "
            "film thins (no warming sign); F_N ~ |torque|; mu ~ v^-0.2 cannot beat v in P; "
            "zero at zero torque (no normal load)"),
}


def section_of(name):
    """The prefix of the `point` report section of mechanism `name` (gearloss_cli.point_regimes
    keys are '<section>:<component>'): 'chur' for churning, 'clut' for clutch_drag."""
    return name.split("_")[0][:4]


def regime_changes(ra, rb, name, with_status=True):
    """Keys of mechanism `name` (and the point's status) whose named regime differs at two points."""
    sec = section_of(name)
    return sorted(k for k in set(ra) | set(rb) if ra.get(k) != rb.get(k)
                  and ((with_status and k == "status") or k.startswith(sec)))


def regimes_in(r, name, wanted):
    """Components of mechanism `name` whose regime at a point is one of `wanted`."""
    sec = section_of(name)
    return sorted(k for k, v in r.items() if k.startswith(sec) and v in wanted)


def ln(v):
    return math.log(v) if v > 0 else None


def find_steps(xs, ys, tol=STEP_LN):
    """Intervals i (between xs[i] and xs[i+1]) whose change of ln y is a step. Points with
    y <= 0 break the curve into pieces examined separately. Returns (i, excess)."""
    out = []
    ly = [ln(y) if y == y else None for y in ys]
    for i in range(1, len(xs) - 2):
        if None in (ly[i - 1], ly[i], ly[i + 1], ly[i + 2]):
            continue
        g = [(ly[j + 1] - ly[j]) / (xs[j + 1] - xs[j]) for j in (i - 1, i, i + 1)]
        dx = xs[i + 1] - xs[i]
        predicted = dx * (g[0] + g[2]) / 2.0
        excess = abs(dx * g[1] - predicted)
        spread = abs(dx * (g[2] - g[0]))
        if excess > tol and excess > 2.0 * spread:
            out.append((i, excess))
    return out


class Findings:
    """Failures per property: (property, case, mechanism, text). `named` keeps the steps that a
    reported regime change explains (not failures)."""

    def __init__(self):
        self.items, self.named, self.checked = [], [], {}

    def fail(self, prop, case, mech, text, worst=0.0):
        self.items.append(dict(property=prop, case=case, mechanism=mech, detail=text, worst=worst))

    def count(self, prop, n=1):
        self.checked[prop] = self.checked.get(prop, 0) + n

    def worst_per_key(self):
        """One line per (property, case, mechanism): the worst instance and how many there are."""
        groups = {}
        for it in self.items:
            k = (it["property"], it["case"], it["mechanism"])
            g = groups.setdefault(k, dict(it, n=0))
            g["n"] += 1
            if it["worst"] > g["worst"]:
                g.update(detail=it["detail"], worst=it["worst"])
        return [groups[k] for k in sorted(groups)]
