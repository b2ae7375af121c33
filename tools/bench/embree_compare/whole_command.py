#!/usr/bin/python3
"""Times clrt's whole command against clrt-embree-render's (a Whitted tracer on Embree 3's
single-ray API) on the same scenes: process start to image written, both at the same size with
one sample a pixel, the scene's depth, PNG out. The runs alternate (clrt, Embree, clrt, ...) so
that load from other work falls on both alike; the best and the median of each are reported,
with the ratio of the medians (Embree's time over clrt's: above 1, clrt is faster) and how far
the two images agree (clrt-img diff of the two renders as PFM). README.md beside this script
says what is compared.

Usage (from the repository root, after the build with libembree-dev installed):
    /usr/bin/python3 tools/bench/embree_compare/whole_command.py SCENE.ray... [--runs 5]
        [--resolution 1280x720] [--threads 2] [--device SPEC] [--json FILE]
        [--clrt PATH] [--embree-render PATH]
Exit status: 0 when clrt is at least as fast on every scene, 1 when it is slower on one or a
run fails, 2 on a usage error.
"""

import argparse
import json
import pathlib
import re
import statistics
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import clrt_run  # noqa: E402
from clrt_run import RunFailed  # noqa: E402

EMBREE_RENDER = clrt_run.BUILD / "tools" / "bench" / "embree_compare" / "clrt-embree-render"
PSNR = re.compile(r"^PSNR: (\S+) dB", re.M)
LARGEST = re.compile(r"^largest difference: (\S+)", re.M)


def commands(scene, out, args):
    clrt = [args.clrt, scene, "-o", out, "--resolution", args.resolution, "--spp", "1", "-q",
            "--device", args.device]
    embree = [args.embree_render, scene, "-o", out, "--resolution", args.resolution,
              "--threads", str(args.threads)]
    return clrt, embree


def agreement(scene, folder, args):
    """clrt-img diff of the two renders in floats: (PSNR in dB, largest difference)."""
    clrt_pfm, embree_pfm = folder / "clrt.pfm", folder / "embree.pfm"
    clrt, _ = commands(scene, clrt_pfm, args)
    _, embree = commands(scene, embree_pfm, args)
    clrt_run.run(clrt)
    clrt_run.run(embree)
    report = clrt_run.run([clrt_run.CLRT_IMG, "diff", clrt_pfm, embree_pfm, "--threshold", "1e30"]).stdout
    psnr, largest = PSNR.search(report), LARGEST.search(report)
    return (float(psnr.group(1)) if psnr else float("inf")), (float(largest.group(1)) if largest else 0.0)


def race(scene, args):
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp)
        clrt, embree = commands(scene, folder / "out.png", args)
        times = {"clrt": [], "embree": []}
        peaks = {"clrt": 0.0, "embree": 0.0}
        # One untimed round: PoCL compiles kernels for a new grid size on their first launch.
        clrt_run.run(clrt)
        clrt_run.run(embree)
        for _ in range(args.runs):
            for name, command in (("clrt", clrt), ("embree", embree)):
                result = clrt_run.run(command)
                times[name].append(result.wall)
                peaks[name] = max(peaks[name], result.peak_mib)
        psnr, largest = agreement(scene, folder, args)
    clrt_median, embree_median = statistics.median(times["clrt"]), statistics.median(times["embree"])
    return {"scene": pathlib.Path(scene).stem, "clrt_best": min(times["clrt"]), "clrt_median": clrt_median,
            "embree_best": min(times["embree"]), "embree_median": embree_median,
            "speed": embree_median / clrt_median, "clrt_peak_mib": peaks["clrt"],
            "embree_peak_mib": peaks["embree"], "psnr_db": psnr, "largest_difference": largest}


def main(arguments=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scenes", nargs="+", help=".ray scenes the Embree tracer can render")
    parser.add_argument("--runs", type=int, default=5, help="timed runs of each command")
    parser.add_argument("--resolution", default="1280x720", help="WxH for both")
    parser.add_argument("--threads", type=int, default=2, help="the Embree tracer's threads")
    parser.add_argument("--device", default="cpu", help="clrt's --device")
    parser.add_argument("--json", help="also write the rows to this file")
    parser.add_argument("--clrt", type=pathlib.Path, default=clrt_run.CLRT, help="the clrt executable")
    parser.add_argument("--embree-render", type=pathlib.Path, default=EMBREE_RENDER,
                        help="the clrt-embree-render executable")
    args = parser.parse_args(arguments)
    if args.runs < 1 or args.threads < 1:
        parser.error("--runs and --threads take a whole number of at least 1")
    for program in (args.clrt, args.embree_render):
        if not program.exists():
            parser.error(f"{program} is missing: build it (clrt-embree-render needs libembree-dev)")
    rows = []
    try:
        for scene in args.scenes:
            print(f"{scene} ...", file=sys.stderr, flush=True)
            rows.append(race(scene, args))
    except RunFailed as failure:
        print(f"whole_command.py: {failure}", file=sys.stderr)
        return 1
    print(f"{args.resolution}, 1 sample a pixel, {args.runs} alternating runs; clrt on --device {args.device}, "
          f"the Embree tracer on {args.threads} threads\n")
    print("| scene | clrt s (best) | Embree tracer s (best) | clrt's speed (median ratio) | peak MiB clrt / Embree "
          "| PSNR dB | largest difference |\n|---|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r['scene']} | {r['clrt_median']:.3f} ({r['clrt_best']:.3f}) | {r['embree_median']:.3f} "
              f"({r['embree_best']:.3f}) | {r['speed']:.2f}x | {r['clrt_peak_mib']:.0f} / {r['embree_peak_mib']:.0f} "
              f"| {r['psnr_db']:.1f} | {r['largest_difference']:.3g} |")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(rows, indent=2) + "\n")
    return 0 if all(r["speed"] >= 1.0 for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
