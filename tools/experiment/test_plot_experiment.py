"""Tests of plot_experiment.py on made-up summaries: a sweep is drawn only for what an experiment
varied, never for devices whose defaults merely differ.

    python3 tools/experiment/test_plot_experiment.py      (CTest: plot_experiment)
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))


def entry(device, variant, local_size, wavefront, mrays):
    return {"scene": "scenes/a.ray", "device_spec": device, "device_name": device,
            "variant": variant, "integrator": "wavefront", "local_size": local_size,
            "wavefront": wavefront, "runs": 3, "failed": 0, "flagged": 0, "short": 0,
            "mrays_per_second": mrays, "spread": {"mrays_per_second": [mrays * 0.9, mrays * 1.1]},
            "kernels": {"shade": 0.5, "intersect": 0.3}}


class PlotExperiment(unittest.TestCase):
    def plots(self, summary):
        with tempfile.TemporaryDirectory(prefix="plot-experiment-test-") as work:
            results = os.path.join(work, "results.json")
            with open(results, "w") as f:
                json.dump({"title": "64x48, 1 spp, on 0:0 PoCL, 1:0 Intel " * 3,
                           "summary": summary}, f)
            subprocess.run([sys.executable, os.path.join(HERE, "plot_experiment.py"), results, work],
                           check=True)
            return sorted(name for name in os.listdir(work) if name.endswith(".png"))

    def test_devices_with_other_defaults_sweep_nothing(self):
        # PoCL's local size 64 and Intel's 128, each its device's default: not a sweep.
        names = self.plots([entry("0:0", "wavefront", 64, 16384, 10.0),
                            entry("1:0", "wavefront", 128, 16384, 12.0)])
        self.assertEqual(names, ["kernels.png", "mrays.png"])

    def test_a_swept_setting_is_drawn(self):
        names = self.plots([entry("0:0", "wavefront-1024", 64, 1024, 8.0),
                            entry("0:0", "wavefront-16384", 64, 16384, 10.0),
                            entry("1:0", "wavefront-1024", 128, 1024, 9.0)])
        self.assertEqual(names, ["kernels.png", "mrays.png", "wavefront.png"])

    def test_many_configurations_and_a_long_title_plot(self):
        self.plots([entry(f"0:{n}", "wavefront", 64, 16384, 1.0 + n) for n in range(24)])


if __name__ == "__main__":
    unittest.main()
