"""Tests of whole_command.py on a small render of scenes/reflect.ray.

    python3 tools/bench/embree_compare/test_whole_command.py CLRT CLRT_EMBREE_RENDER
    (CTest: bench_whole_command)
"""

import contextlib
import io
import json
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import whole_command  # noqa: E402

CLRT, EMBREE_RENDER = sys.argv.pop(1), sys.argv.pop(1)
SCENE = str(whole_command.clrt_run.REPO / "scenes" / "reflect.ray")


def run(arguments, embree_render=EMBREE_RENDER):
    """whole_command's exit status and what it printed."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        try:
            status = whole_command.main(arguments + ["--clrt", CLRT, "--embree-render", embree_render])
        except SystemExit as exit:
            status = exit.code
    return status, out.getvalue()


class WholeCommand(unittest.TestCase):
    def test_times_both_and_measures_agreement(self):
        with tempfile.TemporaryDirectory() as tmp:
            rows_file = pathlib.Path(tmp) / "rows.json"
            status, out = run([SCENE, "--runs", "1", "--resolution", "64x48", "--json", str(rows_file)])
            rows = json.loads(rows_file.read_text())
        self.assertIn(status, (0, 1))  # which one is faster is the measurement, not the test
        self.assertEqual(len(rows), 1)
        row = rows[0]
        self.assertEqual(row["scene"], "reflect")
        self.assertGreater(row["clrt_median"], 0)
        self.assertGreater(row["embree_median"], 0)
        self.assertAlmostEqual(row["speed"], row["embree_median"] / row["clrt_median"])
        # The two tracers render the same picture: only grazing rays may differ.
        self.assertGreater(row["psnr_db"], 40)
        self.assertEqual(status, 0 if row["speed"] >= 1 else 1)
        self.assertIn("| reflect |", out)

    def test_usage_errors(self):
        self.assertEqual(run([SCENE, "--runs", "0"])[0], 2)
        self.assertEqual(run([SCENE], embree_render="/nonexistent/clrt-embree-render")[0], 2)


if __name__ == "__main__":
    unittest.main()
