#!/usr/bin/env python3
"""Unit tests of metrics.py, the race's arithmetic: plain Python, no bpy or numpy.
Run: python3 tools/bench/path_race/test_metrics.py"""
import math
import pathlib
import sys
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import metrics  # noqa: E402


class Metrics(unittest.TestCase):
    def test_rmse(self):
        self.assertEqual(metrics.rmse([1, 2, 3], [1, 2, 3]), 0.0)
        self.assertAlmostEqual(metrics.rmse([1, 1, 1, 1], [0, 0, 0, 0]), 1.0)
        self.assertAlmostEqual(metrics.rmse([3, 0], [0, 4]), math.sqrt(12.5))
        self.assertAlmostEqual(metrics.mse([0.5, -0.5], [0, 0]), 0.25)
        with self.assertRaises(ValueError):
            metrics.rmse([1, 2], [1])
        with self.assertRaises(ValueError):
            metrics.rmse([], [])

    def test_noise(self):
        # Two renders 2 apart in every channel: each is sqrt(2) from their mean, the variance 1.
        self.assertAlmostEqual(metrics.noise_rmse([[1, 1], [3, 3]]), math.sqrt(2))
        # Three renders: the mean of the three pairs' squared differences (4, 16, 4) over 2.
        self.assertAlmostEqual(metrics.noise_rmse([[0], [2], [4]]), math.sqrt(8 / 2))
        self.assertEqual(metrics.noise_rmse([[5, 6], [5, 6]]), 0.0)
        with self.assertRaises(ValueError):
            metrics.noise_rmse([[1, 2]])

    def test_pooled(self):
        # The root of the mean MSE, not the mean of the roots.
        self.assertAlmostEqual(metrics.pooled_rmse([3, 4]), math.sqrt(12.5))
        self.assertAlmostEqual(metrics.pooled_rmse([2, 2, 2]), 2.0)

    def test_efficiency_is_independent_of_samples(self):
        # RMSE ~ 1/sqrt(spp) and time ~ spp: the same efficiency at 16 and 64 spp.
        e16 = metrics.efficiency(0.1, 2.0)
        e64 = metrics.efficiency(0.05, 8.0)
        self.assertAlmostEqual(e16, e64)
        self.assertAlmostEqual(e16, 50.0)
        with self.assertRaises(ValueError):
            metrics.efficiency(0.0, 1.0)

    def test_speedup(self):
        # Half the noise in the same time: a quarter of the samples reach the same quality.
        self.assertAlmostEqual(metrics.speedup(0.05, 1.0, 0.1, 1.0), 4.0)
        # The same noise in twice the time: half as fast.
        self.assertAlmostEqual(metrics.speedup(0.1, 2.0, 0.1, 1.0), 0.5)
        self.assertAlmostEqual(metrics.speedup(0.1, 3.0, 0.2, 1.5), 2.0)

    def test_median_and_means(self):
        self.assertEqual(metrics.median([3, 1, 2]), 2)
        self.assertEqual(metrics.median([4, 1, 2, 3]), 2.5)
        self.assertEqual(metrics.relative_differences([1.01, 2, 0], [1, 2, 0]), [0.010000000000000009, 0.0, 0.0])
        self.assertTrue(metrics.means_agree([1.009, 0.5], [1.0, 0.5], 0.01))
        self.assertFalse(metrics.means_agree([1.011, 0.5], [1.0, 0.5], 0.01))
        self.assertFalse(metrics.means_agree([1.0], [0.0], 0.01))


if __name__ == "__main__":
    unittest.main()
