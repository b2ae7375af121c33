#!/usr/bin/env python3
"""How wide the arithmetic of clrt's kernels is in the machine code PoCL compiled for one render:
whether a kernel runs its work-items side by side in SIMD lanes or one after another.

PoCL compiles each kernel for each local size into a shared object in its cache. This script
renders a scene into empty caches of its own (PoCL's and clrt's), disassembles every kernel's
object and counts its floating-point arithmetic instructions (add, sub, mul, div, sqrt, min,
max, fused multiply-adds, compares) by form:
  scalar      one float at a time (vaddss, ...): a work-item's arithmetic, one item after another;
  xmm         packed in 128-bit registers: mostly a work-item's own float3 and float4 arithmetic
              (vectors the kernel source spells out, packed by LLVM's SLP vectoriser);
  ymm, zmm    packed 8 or 16 wide: work-items side by side in the lanes (PoCL's work-group loop
              vectorised by LLVM's loop vectoriser), or a work-item's own 8-wide arithmetic
              (the traversal tests a BVH node's 8 children at once: kernels/shared/bvh.h).
A kernel without ymm or zmm arithmetic runs its work-items one at a time.

With --probes it does the same for the probe kernels of probes.cl instead of a render: a few
lines each, one feature of clrt's kernels apiece (a float4 record, float3 arithmetic, a loop, a
switch), so that what keeps the work-items out of the lanes can be told apart.

With --why it adds LLVM's reasons, from the loop vectoriser's remarks while PoCL compiled each
kernel (POCL_VECTORIZER_REMARKS=1), each with the place in kernels/ it names: PoCL builds the
program with debug lines for this (POCL_EXTRA_BUILD_FLAGS=-g, which changes no instruction), so
a remark says which line of which file holds the instruction that kept the work-group loop (or
a loop of the kernel's own) from being vectorised.

Usage: /usr/bin/python3 tools/bench/kernel_vectors/kernel_vectors.py [SCENE] [--clrt PATH]
           [--resolution WxH] [--why] [-- CLRT_ARGUMENTS...]
       e.g. ... scenes/reflect.ray -- --integrator megakernel
       /usr/bin/python3 tools/bench/kernel_vectors/kernel_vectors.py --probes
Prints a Markdown table; exits 1 when nothing left kernel objects (a device other than PoCL's CPU
device keeps none), 2 on a usage error.
"""

import argparse
import collections
import os
import pathlib
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import clrt_run  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
PROBES = HERE / "probes.cl"
PROBE_PROGRAM = clrt_run.BUILD / "tools" / "bench" / "kernel_vectors" / "clrt-kernel-probes"

FP_OPERATIONS = ("add", "sub", "mul", "div", "sqrt", "min", "max", "fmadd", "fmsub", "fnmadd",
                 "fnmsub", "cmp")
# An AVX or SSE floating-point instruction: v?OPERATION(...)(ss|sd|ps|pd).
FP_INSTRUCTION = re.compile(r"^v?(%s)\w*?(ss|sd|ps|pd)$" % "|".join(FP_OPERATIONS))
REGISTER = re.compile(r"%([xyz])mm\d+")
FORMS = ("scalar", "xmm", "ymm", "zmm")


def instruction_forms(disassembly):
    """Counts of the floating-point arithmetic instructions in objdump's output, by form."""
    counts = collections.Counter()
    for line in disassembly.splitlines():
        fields = line.split("\t")
        if len(fields) < 2:
            continue
        words = fields[-1].split(None, 1)
        if not words:
            continue
        match = FP_INSTRUCTION.match(words[0])
        if not match:
            continue
        if match.group(2) in ("ss", "sd"):
            counts["scalar"] += 1
            continue
        widths = REGISTER.findall(words[1] if len(words) > 1 else "")
        counts[max(widths, default="x") + "mm"] += 1
    return counts


def kernel_objects(cache):
    """(kernel, local size, object path) for every kernel object PoCL wrote under `cache`."""
    out = []
    for path in sorted(pathlib.Path(cache).rglob("*.so")):
        kernel = path.stem
        local_size = path.parent.name.split("-goffs")[0].replace("-", "x")
        out.append((kernel, local_size, path))
    return out


# Where a remark starts in PoCL's stream, which runs them together: the place it names.
REMARK_START = re.compile(r"(<unknown>:0:0: |kernels/[\w/.-]+\.(?:cl|h):\d+:\d+: )")
# PoCL compiles one kernel after another: remarks on the kernel's own loops, PoCL inlining it into
# its work-group function, remarks on the work-group loop, then the sizes of the functions made.
KERNEL_NAME = re.compile(r"'_pocl_kernel_(\w+)' inlined into '_pocl_kernel_\1_workgroup'")
FUNCTION_SIZE = re.compile(r"\d+ instructions in function")
NOT_VECTORISED = re.compile(r"^(kernels/\S+?):? loop not vectorized: (.+)$")


def vectoriser_reasons(remarks):
    """{kernel: [reason (place), ...]} from PoCL's remark stream: the loop vectoriser's reasons
    for not vectorising a loop while PoCL compiled the kernel, each once, in the order they
    came."""
    reasons = {}
    kernel, found, closing = None, [], False
    for line in REMARK_START.sub(r"\n\1", remarks).splitlines():
        if FUNCTION_SIZE.search(line):
            closing = True
            continue
        if closing:  # the sizes ended one kernel's compile
            if kernel:
                reasons[kernel] = found
            kernel, found, closing = None, [], False
        named = KERNEL_NAME.search(line)
        if named:
            kernel = named.group(1)
        match = NOT_VECTORISED.match(line.strip())
        if match:
            reason = f"{match.group(2).strip()} ({match.group(1)})"
            if reason not in found:
                found.append(reason)
    if kernel:
        reasons[kernel] = found
    return reasons


def report(rows, reasons=None):
    why = reasons is not None
    lines = ["| kernel | local size | scalar | 4 wide (xmm) | 8 wide (ymm) | 16 wide (zmm) |"
             + (" why not vectorised (LLVM) |" if why else ""),
             "|---|---|---:|---:|---:|---:|" + ("---|" if why else "")]
    for kernel, local_size, counts in rows:
        line = f"| {kernel} | {local_size} | " + " | ".join(str(counts[f]) for f in FORMS) + " |"
        if why:
            line += " " + ("; ".join(reasons.get(kernel, [])) or "-") + " |"
        lines.append(line)
    return "\n".join(lines)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", nargs="?", default=str(clrt_run.REPO / "scenes" / "reflect.ray"))
    parser.add_argument("--clrt", default=str(clrt_run.CLRT))
    parser.add_argument("--resolution", default="64x64")
    parser.add_argument("--probes", action="store_true", help="the probe kernels, not a render")
    parser.add_argument("--probe-program", default=str(PROBE_PROGRAM))
    parser.add_argument("--why", action="store_true",
                        help="add LLVM's reasons for not vectorising, with their places in kernels/")
    parser.add_argument("clrt_arguments", nargs="*", help="more of clrt's options, after --")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="clrt-kernel-vectors-") as cache:
        # clrt's own cache too: a program it loads as a binary compiles nothing while we watch.
        env = dict(os.environ, POCL_CACHE_DIR=cache, CLRT_CACHE_DIR=cache)
        if args.why:
            env.update(POCL_VECTORIZER_REMARKS="1", POCL_EXTRA_BUILD_FLAGS="-g")
        if args.probes:
            run = clrt_run.run([args.probe_program, PROBES], env=env)
        else:
            run = clrt_run.run([args.clrt, args.scene, "--resolution", args.resolution, "--no-write",
                                "-q", *args.clrt_arguments], env=env)
        objects = kernel_objects(cache)
        if not objects:
            print("kernel_vectors: no kernel objects were left (not PoCL's CPU device?)",
                  file=sys.stderr)
            return 1
        rows = []
        for kernel, local_size, path in objects:
            disassembly = subprocess.run(["objdump", "-d", "--no-show-raw-insn", str(path)],
                                         check=True, capture_output=True, text=True).stdout
            rows.append((kernel, local_size, instruction_forms(disassembly)))
    print(report(rows, vectoriser_reasons(run.stdout + run.stderr) if args.why else None))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
