#!/usr/bin/env python3
"""The envelope suite's own tools against independent values: the ISO 21771 working centre
distance of the generator against published gear pairs, the step detector on curves whose
answer is known by construction, and the generated cases accepted by `gearloss check`.

    test_envelope_tools.py BINARY SOURCE_DIR
"""
import math
import os
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from generate_cases import generate, working_centre_distance, write_cases  # noqa: E402
from properties import find_steps  # noqa: E402
import random  # noqa: E402

BINARY, SOURCE = sys.argv[1], sys.argv[2]


class CentreDistance(unittest.TestCase):
    def test_fzg_type_c(self):
        # FZG type C gears (Fernandes et al. 2015, Parts I-III): z 16/24, m 4.5 mm, x 0.1817 /
        # 0.1715, spur: the rig's centre distance is 91.5 mm.
        self.assertAlmostEqual(working_centre_distance(16, 24, 4.5, 0.0, 0.1817, 0.1715), 91.5,
                               delta=0.005)

    def test_transfer_box_helical_pairs(self):
        # Seed 001's transfer box: wheels 5-3 and 4-2 share a 95 mm housing bore distance; the
        # pairs' nominal working centre distances are 94.998 and 95.011 mm (Pereira 2017).
        b = math.radians(20.0)
        self.assertAlmostEqual(working_centre_distance(17, 28, 4.0, b, 0.051, -0.240), 94.998, delta=0.001)
        self.assertAlmostEqual(working_centre_distance(27, 23, 3.5, b, 0.161, 0.415), 95.011, delta=0.001)

    def test_zero_shift_is_reference_distance(self):
        # x1 + x2 = 0: a_w = a_d = m_n (z1 + z2) / (2 cos beta)
        b = math.radians(15.0)
        self.assertAlmostEqual(working_centre_distance(20, 41, 3.0, b, 0.3, -0.3),
                               3.0 * 61 / (2 * math.cos(b)), delta=1e-9)


class StepDetector(unittest.TestCase):
    xs = [float(i) for i in range(20)]

    def test_smooth_exponential_and_power_law_pass(self):
        self.assertEqual(find_steps(self.xs, [5 * math.exp(-0.08 * x) for x in self.xs]), [])
        lx = [math.log(x) for x in range(1, 21)]
        self.assertEqual(find_steps(lx, [3 * x ** 1.7 for x in range(1, 21)]), [])

    def test_kink_is_not_a_step(self):
        ys = [math.exp(0.05 * x) if x < 10 else math.exp(0.5 + 0.2 * (x - 10)) for x in self.xs]
        self.assertEqual(find_steps(self.xs, ys), [])

    def test_jump_of_20_percent_is_found_where_it_is(self):
        ys = [math.exp(-0.05 * x) * (1.2 if x >= 11 else 1.0) for x in self.xs]
        steps = find_steps(self.xs, ys)
        self.assertEqual([i for i, _ in steps], [10])
        self.assertAlmostEqual(steps[0][1], math.log(1.2), delta=1e-9)

    def test_zero_values_break_the_curve(self):
        ys = [1.0 + 0.01 * x if x != 7 else 0.0 for x in self.xs]
        self.assertEqual(find_steps(self.xs, ys), [])


class GeneratedCases(unittest.TestCase):
    def test_deterministic(self):
        a = [generate(random.Random(7), i, SOURCE) for i in range(3)]
        b = [generate(random.Random(7), i, SOURCE) for i in range(3)]
        self.assertEqual(a, b)

    def test_accepted_by_check_without_warnings(self):
        with tempfile.TemporaryDirectory() as d:
            for path in write_cases(SOURCE, d, seed=2024, count=6):
                p = subprocess.run([BINARY, "check", path], capture_output=True, text=True)
                self.assertEqual(p.returncode, 0, p.stderr)
                self.assertNotIn("warning", p.stderr + p.stdout, path)
                self.assertNotIn("error", p.stderr, path)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=1)
