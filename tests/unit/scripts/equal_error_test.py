#!/usr/bin/python3
"""Unit test of scripts/equal_error.py, the equal-error ratio of `scripts/bench pareto`: the
reference front, the interpolation between the two N that bracket an error, the cheapest and
'beyond' ends. Run by ctest (label unit) as bench.equal_error."""
import os
import sys
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "scripts"))
import equal_error as ee  # noqa: E402

# (n, error, ms): N = 3 came out worse than N = 2 (jitter): it is off the front.
REFS = [(1, 0.20, 10.0), (2, 0.10, 40.0), (3, 0.12, 90.0), (4, 0.05, 160.0), (8, 0.02, 640.0)]


class Front(unittest.TestCase):
    def test_keeps_falling_errors_by_time(self):
        self.assertEqual([p[0] for p in ee.reference_front(REFS)], [1, 2, 4, 8])

    def test_order_of_input_does_not_matter(self):
        self.assertEqual(ee.reference_front(list(reversed(REFS))), ee.reference_front(REFS))

    def test_drops_runs_without_error_or_time(self):
        front = ee.reference_front([(1, None, 5.0), (2, 0.1, None), (4, 0.05, 20.0)])
        self.assertEqual(front, [(4, 0.05, 20.0)])


class Time(unittest.TestCase):
    def setUp(self):
        self.front = ee.reference_front(REFS)

    def test_interpolates_time_and_n_between_bracketing_n(self):
        # 0.075 is half way from N = 2 (0.10, 40 ms) to N = 4 (0.05, 160 ms).
        ms, n, kind = ee.reference_time(self.front, 0.075)
        self.assertEqual(kind, "interpolated")
        self.assertAlmostEqual(ms, 100.0)
        self.assertAlmostEqual(n, 3.0)

    def test_skips_the_off_front_n(self):
        # 0.11 lies between N = 1 and 2 on the front; N = 3's 0.12 plays no part.
        ms, n, _ = ee.reference_time(self.front, 0.11)
        self.assertAlmostEqual(ms, 10.0 + 0.9 * 30.0)
        self.assertAlmostEqual(n, 1.9)

    def test_error_equal_to_a_front_point_is_its_time(self):
        ms, n, kind = ee.reference_time(self.front, 0.05)
        self.assertEqual((ms, n, kind), (160.0, 4.0, "interpolated"))

    def test_error_above_the_cheapest_is_the_cheapest(self):
        self.assertEqual(ee.reference_time(self.front, 0.5), (10.0, 1, "cheapest"))
        self.assertEqual(ee.reference_time(self.front, 0.2), (10.0, 1, "cheapest"))

    def test_error_below_every_reference_is_beyond(self):
        self.assertEqual(ee.reference_time(self.front, 0.01), (640.0, 8, "beyond"))

    def test_empty_front_is_an_error(self):
        with self.assertRaises(ValueError):
            ee.reference_time([], 0.1)


class Ratio(unittest.TestCase):
    def test_ratio_is_time_over_the_reference_time(self):
        ratio, n, kind = ee.equal_error_ratio(50.0, 0.075, ee.reference_front(REFS))
        self.assertAlmostEqual(ratio, 0.5)
        self.assertEqual(kind, "interpolated")

    def test_beyond_is_printed_as_an_upper_bound(self):
        ratio, _, kind = ee.equal_error_ratio(320.0, 0.001, ee.reference_front(REFS))
        self.assertEqual(ee.fmt_ratio(ratio, kind), "<0.50")
        self.assertEqual(ee.fmt_ratio(0.5, "interpolated"), "0.50")


if __name__ == "__main__":
    unittest.main()
