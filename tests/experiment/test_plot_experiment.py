"""Tests of plot_experiment.py on made-up summaries: a sweep is drawn only for what an experiment
varied, never for devices whose defaults merely differ.

    python3 tests/experiment/test_plot_experiment.py      (CTest: plot_experiment)
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

# The scripts under test, in the tool's folder.
HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "experiment")


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


def drawn(fig):
    """The figure laid out as it is saved, for its artists' places."""
    fig.tight_layout()
    fig.canvas.draw()
    return fig.canvas.get_renderer()


class PlotLayout(unittest.TestCase):
    def setUp(self):
        sys.path.insert(0, HERE)
        import plot_experiment
        self.plot = plot_experiment

    def test_short_renders_are_marked(self):
        short = entry("0:0", "wavefront", 64, 16384, 3.0)
        short["short"] = 2
        other = entry("0:0", "megakernel", 64, 16384, 4.0)
        other["scene"] = short["scene"]
        fig = self.plot.mrays_figure([short, other], "8x8, 1 spp, on 0:0 PoCL")
        ax = fig.axes[0]
        bars = [p for p in ax.patches if p.get_height() > 0]
        hatched = [p for p in bars if p.get_hatch() == "xx"]
        self.assertEqual([p.get_height() for p in hatched], [3.0])
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        self.assertEqual(labels[:2], ["0:0 wavefront", "0:0 megakernel"])
        self.assertTrue(labels[2].startswith("short render"))
        # Without a short render, no mark and no legend entry for one.
        fig = self.plot.mrays_figure([other], "8x8, 1 spp, on 0:0 PoCL")
        self.assertFalse(any(p.get_hatch() == "xx" for p in fig.axes[0].patches))
        self.assertEqual(len(fig.axes[0].get_legend().get_texts()), 1)

    def test_the_kernels_legend_covers_no_tick_label(self):
        one = entry("0:0", "wavefront", 64, 16384, 3.0)
        one["kernels"] = {f"kernel_with_a_long_name_{n}": 0.1 * (n + 1) for n in range(12)}
        fig = self.plot.kernels_figure([one], "8x8, 1 spp, on 0:0 PoCL")
        renderer = drawn(fig)
        ax = fig.axes[0]
        legend = ax.get_legend().get_window_extent(renderer)
        for tick in ax.get_xticklabels() + ax.get_yticklabels():
            if tick.get_text():
                self.assertFalse(legend.overlaps(tick.get_window_extent(renderer)),
                                 tick.get_text())


if __name__ == "__main__":
    unittest.main()
