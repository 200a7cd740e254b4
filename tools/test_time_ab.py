#!/usr/bin/env python3
"""Tests for tools/time_ab.py's interval: it brackets the median of the pair ratios as often as
it claims, on data whose median is known. Run: python3 tools/test_time_ab.py"""

import os
import random
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from time_ab import median_interval  # noqa: E402


class MedianInterval(unittest.TestCase):
    def test_order_statistics_of_ten_pairs(self):
        # Ten pairs: P(Binomial(10, 1/2) <= 1) = 11/1024 <= 5 %, P(<= 2) = 56/1024 > 5 %: the
        # second smallest and the second largest.
        self.assertEqual(median_interval([float(v) for v in range(10)]), (1.0, 8.0))

    def test_too_few_pairs_give_none(self):
        # Four pairs: even the extremes miss the median with chance 2/16 > 10 %.
        self.assertIsNone(median_interval([1.0, 2.0, 3.0, 4.0]))

    def test_covers_the_true_median_at_least_as_often_as_it_claims(self):
        rng = random.Random(7)
        for n in (6, 10, 16):
            covered = 0
            trials = 2000
            for _ in range(trials):
                # Skewed ratios around a true median of 1.0 (a lognormal's median is exp(mu)).
                values = [rng.lognormvariate(0.0, 0.15) for _ in range(n)]
                lo, hi = median_interval(values)
                covered += lo <= 1.0 <= hi
            self.assertGreaterEqual(covered / trials, 0.88, "n = %d" % n)

    def test_a_clear_speedup_excludes_one(self):
        rng = random.Random(3)
        values = [0.8 * rng.lognormvariate(0.0, 0.08) for _ in range(10)]
        lo, hi = median_interval(values)
        self.assertLess(hi, 1.0)


if __name__ == "__main__":
    unittest.main()
