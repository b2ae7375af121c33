"""Tests of plot_knob.py on a made-up runs.csv whose medians and crossings are known.

    python3 tests/experiment/test_plot_knob.py      (CTest: plot_knob)
"""
import contextlib
import io
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "experiment"))
import plot_knob  # noqa: E402

HEADER = "scene,device_spec,device,variant,repeat,exit_code,mrays_per_s,msamples_per_s,flagged\n"


def row(k, device, variant, repeat, mrays, exit_code=0, flagged="false"):
    return (f"out/knob-{k:02d}.ray,0:0,{device},{variant},{repeat},{exit_code},{mrays},"
            f"{mrays / 10},{flagged}\n")


class PlotKnob(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.TemporaryDirectory(prefix="plot-knob-test-")
        rows = []
        # Device A: the megakernel is ahead at k = 1, behind from k = 2 on. Device B: ahead at k = 3.
        for k, (wave_a, mega_a, wave_b, mega_b) in enumerate(
                [(1.0, 2.0, 1.0, 0.5), (2.0, 1.0, 1.0, 0.5), (3.0, 1.0, 1.0, 2.0)], start=1):
            for repeat, jitter in enumerate([0.9, 1.0, 1.2]):
                rows.append(row(k, "A dev", "wavefront queue", repeat, wave_a * jitter))
                rows.append(row(k, "A dev", "wavefront by-class", repeat, wave_a))
                rows.append(row(k, "B dev", "wavefront queue", repeat, wave_b))
                rows.append(row(k, "B dev", "wavefront by-class", repeat, wave_b))
                # the megakernel's two variants are one configuration: pooled, median of six
                rows.append(row(k, "A dev", "megakernel queue", repeat, mega_a))
                rows.append(row(k, "A dev", "megakernel by-class", repeat, mega_a))
                rows.append(row(k, "B dev", "megakernel queue", repeat, mega_b))
                rows.append(row(k, "B dev", "megakernel by-class", repeat, mega_b))
        # A failed and a flagged run are left out: they would move A's k = 1 median above 2.
        rows.append(row(1, "A dev", "wavefront queue", 3, 50.0, exit_code=1))
        rows.append(row(1, "A dev", "wavefront queue", 4, 50.0, flagged="true"))
        rows.append(row(1, "A dev", "wavefront queue", 5, 50.0, flagged="true"))
        self.csv = os.path.join(self.work.name, "runs.csv")
        with open(self.csv, "w") as f:
            f.write(HEADER + "".join(rows))

    def tearDown(self):
        self.work.cleanup()

    def test_medians_crossings_and_plot(self):
        png = os.path.join(self.work.name, "knob.png")
        sys.argv = ["plot_knob.py", self.csv, png]
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            plot_knob.main()
        text = out.getvalue()
        self.assertIn("| 1 | 1.00 | 1.00 | 2.00 | 1.00 | 1.00 | 0.50 |", text)
        self.assertIn("| 3 | 3.00 | 3.00 | 1.00 | 1.00 | 1.00 | 2.00 |", text)
        self.assertIn("A dev: the wavefront (queue order) is ahead of the megakernel from k = 2 on", text)
        self.assertIn("B dev: the wavefront (queue order) is ahead of the megakernel at no k to the end",
                      text)
        self.assertGreater(os.path.getsize(png), 10000)


if __name__ == "__main__":
    unittest.main()
