"""Tests of kernel_vectors.py: its reading of disassembly, a real render and the probes on PoCL.

    python3 tools/bench/kernel_vectors/test_kernel_vectors.py [CLRT [PROBE_PROGRAM]]
    (CTest: bench_kernel_vectors)
"""

import contextlib
import io
import pathlib
import sys
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import kernel_vectors  # noqa: E402

CLRT = pathlib.Path(sys.argv.pop(1)) if len(sys.argv) > 1 else kernel_vectors.clrt_run.CLRT
PROBE_PROGRAM = pathlib.Path(sys.argv.pop(1)) if len(sys.argv) > 1 else kernel_vectors.PROBE_PROGRAM


def table_rows(arguments):
    """kernel_vectors' exit status and its table's rows by kernel name."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        status = kernel_vectors.main(arguments)
    return status, {line.split("|")[1].strip(): line for line in out.getvalue().splitlines()[2:]}

DISASSEMBLY = """
    1000:\tvaddss %xmm1,%xmm2,%xmm3
    1004:\tvmulss (%rax),%xmm0,%xmm0
    1008:\tvsqrtsd %xmm1,%xmm1,%xmm1
    100c:\tvmulps %xmm1,%xmm2,%xmm3
    1010:\tvfmadd231ps %ymm1,%ymm2,%ymm3
    1014:\tvcmpltps %ymm4,%ymm5,%k1
    1018:\tvmaxps %zmm1,%zmm2,%zmm3
    101c:\tvmovaps %ymm1,(%rax)
    1020:\tvpaddd %ymm1,%ymm2,%ymm3
    1024:\tadd $0x4,%rax
    1028:\tcmp %eax,%ebx
    102c:\tvunpcklps %xmm1,%xmm2,%xmm3
"""


class Disassembly(unittest.TestCase):
    def test_floating_point_arithmetic_is_counted_by_width(self):
        counts = kernel_vectors.instruction_forms(DISASSEMBLY)
        self.assertEqual(counts["scalar"], 3)  # vaddss, vmulss, vsqrtsd
        self.assertEqual(counts["xmm"], 1)     # vmulps
        self.assertEqual(counts["ymm"], 2)     # vfmadd231ps, vcmpltps
        self.assertEqual(counts["zmm"], 1)     # vmaxps

    def test_moves_integers_and_shuffles_are_not_arithmetic(self):
        counts = kernel_vectors.instruction_forms(DISASSEMBLY)
        self.assertEqual(sum(counts.values()), 7)


# PoCL's remark stream as it comes, every remark run into the next: two kernels' compiles, the
# second's loop of its own before PoCL inlines it into its work-group function.
REMARKS = (
    "<unknown>:0:0: '_pocl_kernel_generate' inlined into '_pocl_kernel_generate_workgroup' with "
    "(cost=always): always inlinerkernels/generate.cl:10:22: loop not vectorized: instruction "
    "return type cannot be vectorizedkernels/generate.cl:10:22: loop not vectorized: instruction "
    "return type cannot be vectorizedkernels/generate.cl:7:0: 213 instructions in function"
    "<unknown>:0:0: 225 instructions in functionkernels/render/lights.h:29:3: loop not "
    "vectorized: loop contains a switch statement<unknown>:0:0: '_pocl_kernel_shade' inlined "
    "into '_pocl_kernel_shade_workgroup' with (cost=always): always inlinerkernels/shade.cl:27:5:"
    " vectorized loop (vectorization width: 8, interleaved count: 1)kernels/shade.cl:20:1: "
    "400 instructions in function")


class Remarks(unittest.TestCase):
    def test_reasons_go_to_the_kernel_whose_compile_they_came_in(self):
        reasons = kernel_vectors.vectoriser_reasons(REMARKS)
        self.assertEqual(reasons["generate"],
                         ["instruction return type cannot be vectorized (kernels/generate.cl:10:22)"])
        self.assertEqual(reasons["shade"],
                         ["loop contains a switch statement (kernels/render/lights.h:29:3)"])

    def test_a_stream_without_remarks_gives_no_reasons(self):
        self.assertEqual(kernel_vectors.vectoriser_reasons(""), {})


class RealRender(unittest.TestCase):
    def test_every_kernel_of_a_render_is_reported(self):
        status, rows = table_rows(["--clrt", str(CLRT), "--resolution", "16x12"])
        self.assertEqual(status, 0)
        for kernel in ("generate", "intersect", "shade", "shadow", "gather_shadows", "resolve"):
            self.assertIn(kernel, rows)
        # shade is the largest kernel: it cannot have compiled to no arithmetic at all.
        shade = [int(cell) for cell in rows["shade"].split("|")[3:7]]
        self.assertGreater(sum(shade), 100)

    def test_why_names_places_in_the_kernels(self):
        status, rows = table_rows(["--clrt", str(CLRT), "--resolution", "16x12", "--why"])
        self.assertEqual(status, 0)
        # shade walks the lights in loops of its own, which PoCL 3.1 does not vectorise.
        self.assertRegex(rows["shade"].split("|")[7], r"\(kernels/[\w/]+\.(cl|h):\d+:\d+\)")


class Probes(unittest.TestCase):
    def test_every_probe_kernel_is_reported(self):
        status, rows = table_rows(["--probes", "--probe-program", str(PROBE_PROGRAM)])
        self.assertEqual(status, 0)
        source = kernel_vectors.PROBES.read_text()
        probes = {line[len("PROBE("):line.index(")")] for line in source.splitlines()
                  if line.startswith("PROBE(")}
        self.assertGreaterEqual(len(probes), 7)
        self.assertEqual(set(rows), probes)


if __name__ == "__main__":
    unittest.main()
