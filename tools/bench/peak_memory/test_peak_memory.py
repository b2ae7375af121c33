"""Runs peak_memory.py on small versions of its scenes and checks its table (CTest:
bench_peak_memory).

    python3 tools/bench/peak_memory/test_peak_memory.py CLRT
"""

import pathlib
import subprocess
import sys
import unittest

CLRT = sys.argv.pop(1)
SCRIPT = pathlib.Path(__file__).resolve().parent / "peak_memory.py"


class PeakMemory(unittest.TestCase):
    def test_each_scene_has_its_peak(self):
        out = subprocess.run([sys.executable, SCRIPT, "--clrt", CLRT, "--runs", "1", "--scale", "0.001"],
                             capture_output=True, text=True, check=True)
        rows = [line.split("|") for line in out.stdout.splitlines() if f"| {CLRT} |" in line]
        self.assertEqual([row[1].strip() for row in rows],
                         ["height field, 968 triangles without normals", "3,000 spheres",
                          "texture, 259x259 8-bit", "texture, 129x129 float", "environment, 259x129 float"])
        for row in rows:
            kib = int(row[4].strip().replace(",", ""))
            # More than the process itself, less than anything these small scenes could need.
            self.assertGreater(kib, 10_000)
            self.assertLess(kib, 2_000_000)


if __name__ == "__main__":
    unittest.main()
