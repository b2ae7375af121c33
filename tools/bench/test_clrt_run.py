"""Tests of clrt_run.py, the benchmarks' shared library, on a real clrt.

    python3 tools/bench/test_clrt_run.py [CLRT]     (CTest: bench_clrt_run; default build/clrt)
"""

import pathlib
import sys
import tempfile
import unittest

import clrt_run

CLRT = pathlib.Path(sys.argv.pop(1)) if len(sys.argv) > 1 else clrt_run.CLRT
SCENE = clrt_run.REPO / "scenes" / "reflect.ray"
WIDTH, HEIGHT, SPP = 32, 24, 2


class RunClrt(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory(prefix="clrt-run-test-")
        cls.image = pathlib.Path(cls.work.name) / "reflect.png"
        cls.result = clrt_run.run_clrt(
            [SCENE, "-o", cls.image, "--resolution", f"{WIDTH}x{HEIGHT}", "--spp", str(SPP), "-q"],
            clrt=CLRT, stats=True, env=clrt_run.pocl_threads(1))

    @classmethod
    def tearDownClass(cls):
        cls.work.cleanup()

    def test_the_command_ran_and_wrote_its_image(self):
        self.assertEqual(self.result.command[0], str(CLRT))
        self.assertIn("--stats=json", self.result.command)
        self.assertGreater(self.image.stat().st_size, 0)

    def test_the_statistics_count_the_camera_rays(self):
        rays = self.result.stats["rays"]
        self.assertEqual(rays["camera"], WIDTH * HEIGHT * SPP)
        self.assertEqual(rays["total"],
                         sum(rays[kind] for kind in ("camera", "shadow", "reflection",
                                                     "refraction")))
        # reflect.ray has mirrors and lights: every kind but refraction is traced.
        self.assertGreater(rays["shadow"], 0)
        self.assertGreater(rays["reflection"], 0)

    def test_the_stages_fit_in_clrts_total_and_the_total_in_the_wall_time(self):
        seconds = self.result.stats["seconds"]
        for stage in ("load", "bvh", "kernel_build", "render", "write"):
            self.assertGreaterEqual(seconds[stage], 0, stage)
            self.assertLessEqual(seconds[stage], seconds["total"], stage)
        self.assertLessEqual(seconds["total"], self.result.wall)

    def test_time_and_memory_are_the_processs(self):
        self.assertGreater(self.result.cpu, 0)
        # An OpenCL process maps its runtime and the device's buffers: tens of MiB at least,
        # and far less than the machine.
        self.assertGreater(self.result.peak_mib, 10)
        self.assertLess(self.result.peak_mib, 4096)


class Failures(unittest.TestCase):
    def test_a_failed_command_names_itself_its_status_and_its_error(self):
        with self.assertRaises(clrt_run.RunFailed) as failure:
            clrt_run.run_clrt(["no-such-scene.ray", "-q"], clrt=CLRT)
        message = str(failure.exception)
        self.assertIn("no-such-scene.ray -q exited with 2", message)
        self.assertIn("error", message)

    def test_output_without_statistics_is_a_failure(self):
        result = clrt_run.run(["true"])
        with self.assertRaises(clrt_run.RunFailed):
            result.stats


class Parsing(unittest.TestCase):
    def test_the_first_object_counts_whatever_surrounds_it(self):
        self.assertEqual(clrt_run.parse_stats('rank 0\n{"rays": {"total": 3}}\n{"x": 1}\n'),
                         {"rays": {"total": 3}})

    def test_pocl_threads_sets_both_names_and_keeps_the_rest(self):
        env = clrt_run.pocl_threads(3, {"PATH": "/bin"})
        self.assertEqual(env, {"PATH": "/bin", "POCL_MAX_PTHREAD_COUNT": "3",
                               "POCL_CPU_MAX_CU_COUNT": "3"})


if __name__ == "__main__":
    unittest.main()
