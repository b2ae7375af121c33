"""Runs warm_start.py on a tiny render and checks its table (CTest: bench_warm_start).

    python3 tools/bench/warm_start/test_warm_start.py CLRT
"""

import pathlib
import re
import subprocess
import sys
import unittest

CLRT = sys.argv.pop(1)
SCRIPT = pathlib.Path(__file__).resolve().parent / "warm_start.py"


class WarmStart(unittest.TestCase):
    def test_both_programs_are_timed(self):
        out = subprocess.run([sys.executable, SCRIPT, "--clrt", CLRT, "--runs", "2", "--warmup", "0",
                              "--resolution", "32x24"], capture_output=True, text=True, check=True)
        rows = [line for line in out.stdout.splitlines() if line.startswith(f"| {CLRT} ")]
        self.assertEqual([row.split("|")[1].split()[-1] for row in rows], ["cached", "source"])
        for row in rows:
            median, mean, best, worst = (float(v) for v in re.findall(r"\| ([0-9.]+)", row))
            self.assertLessEqual(best, median)
            self.assertLessEqual(median, worst)
            self.assertGreater(best, 0.0)
        self.assertNotIn("no program entry", out.stderr)


if __name__ == "__main__":
    unittest.main()
