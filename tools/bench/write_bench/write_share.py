#!/usr/bin/python3
"""Prints how much of clrt's command writing the image takes, per scene and output format.

For each scene and format, clrt renders at the given size (default 1920x1080) `--runs` times
with `--stats=json`, which reports the write step's seconds (encoding, the temporary file,
fsync, rename) and clrt's own total, and as many times without it, which gives the command's
wall time as a user sees it (process start to image on disk, no profiling). The runs of the two
kinds interleave. Share = median write seconds / median plain command seconds. The
target is a PNG share of at most 5% at 1920x1080.

Usage (from the repository root, after the build):
    /usr/bin/python3 tools/bench/write_bench/write_share.py [SCENES...] [--formats png,ppm,fsf,pfm,exr]
        [--resolution 1920x1080] [--runs 3] [--clrt build/clrt] [--target 0.05]
Default scenes: scenes/*.ray. Exit status: 0 when every PNG share is within the target, 1 when
one is not or a render fails, 2 on a usage error.
"""

import argparse
import pathlib
import statistics
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import clrt_run  # noqa: E402


def measure(args, scene, image_format, work):
    out = work / f"{scene.stem}.{image_format}"
    command = [scene, "-o", out, "--resolution", args.resolution, "-q"]
    write, clrt_total, wall = [], [], []
    for _ in range(args.runs):
        seconds = clrt_run.run_clrt(command, args.clrt, stats=True).stats["seconds"]
        write.append(seconds["write"])
        clrt_total.append(seconds["total"])
        wall.append(clrt_run.run_clrt(command, args.clrt).wall)
    return {"scene": scene.name, "format": image_format, "write": statistics.median(write),
            "stats_total": statistics.median(clrt_total), "command": statistics.median(wall),
            "bytes": out.stat().st_size}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenes", nargs="*", type=pathlib.Path)
    parser.add_argument("--clrt", default=clrt_run.CLRT, type=pathlib.Path)
    parser.add_argument("--formats", default="png,ppm,fsf,pfm,exr")
    parser.add_argument("--resolution", default="1920x1080")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--target", type=float, default=0.05, help="largest PNG share")
    args = parser.parse_args()
    scenes = args.scenes or sorted((clrt_run.REPO / "scenes").glob("*.ray"))
    formats = [f for f in args.formats.split(",") if f]
    missing = [str(s) for s in scenes if not s.is_file()]
    if missing:
        parser.error(f"no such scene: {', '.join(missing)}")
    if args.runs < 1:
        parser.error("--runs must be at least 1")
    unknown = set(formats) - {"png", "ppm", "fsf", "pfm", "exr"}
    if unknown:
        parser.error(f"unknown format {', '.join(sorted(unknown))}")

    print(f"clrt {args.resolution}, median of {args.runs}; write and clrt total from --stats, "
          f"command = wall time of the same command without --stats\n")
    print("| scene | format | write ms | clrt total s (--stats) | command s | write share "
          "| file KiB |")
    print("|---|---|---:|---:|---:|---:|---:|")
    rows = []
    with tempfile.TemporaryDirectory(prefix="clrt-write-share-") as work:
        # One render first, so that no row pays for filling PoCL's kernel cache.
        clrt_run.run_clrt([scenes[0], "-o", f"{work}/warm.png", "-q", "--resolution", "64x36"],
                          args.clrt)
        for scene in scenes:
            for image_format in formats:
                try:
                    row = measure(args, scene, image_format, pathlib.Path(work))
                except clrt_run.RunFailed as failure:
                    print(f"error: {failure}", file=sys.stderr)
                    return 1
                rows.append(row)
                print(f"| {row['scene']} | {image_format} | {1e3 * row['write']:.1f} "
                      f"| {row['stats_total']:.3f} | {row['command']:.3f} "
                      f"| {100 * row['write'] / row['command']:.1f}% "
                      f"| {row['bytes'] >> 10} |", flush=True)
    png = [r["write"] / r["command"] for r in rows if r["format"] == "png"]
    if png:
        print(f"\nPNG share: median {100 * statistics.median(png):.1f}%, largest "
              f"{100 * max(png):.1f}% (target {100 * args.target:.0f}%)")
    return 0 if all(share <= args.target for share in png) else 1


if __name__ == "__main__":
    sys.exit(main())
