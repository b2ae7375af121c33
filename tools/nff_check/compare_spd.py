#!/usr/bin/python3
"""Renders every SPD scene in NFF and its .ray conversion with clrt and compares the images.

The .ray files in ../shared/scenes/spd-ray/ are the SPD's NFF files converted by hand-written
rules (their header comments); clrt reads NFF natively with the same rules (docs/nff.md), so each
pair must give the same image. Not run by CI: it needs ../shared and takes minutes.

Usage (from the repository root, after the build):
    /usr/bin/python3 tools/nff_check/compare_spd.py [--clrt build/clrt] [--nff DIR] [--ray DIR]
        [--resolution WxH] [--only NAME]
Exit status: 0 when every pair renders to the same bytes, 1 otherwise, 2 on a usage error.
"""

import argparse
import pathlib
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "bench"))
import clrt_run  # noqa: E402

REPO = clrt_run.REPO


def read_ppm(path):
    """(width, height, rgb bytes) of a binary P6 file with maxval 255."""
    data = path.read_bytes()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    if fields[0] != b"P6" or fields[3] != b"255":
        raise ValueError(f"{path}: not an 8-bit binary PPM")
    width, height = int(fields[1]), int(fields[2])
    return width, height, data[pos + 1:]


def render(clrt, scene, out, resolution):
    """The command's wall seconds."""
    arguments = [scene, "-o", out, "-q", *(["--resolution", resolution] if resolution else [])]
    return clrt_run.run_clrt(arguments, clrt).wall


def compare(a, b):
    """(pixels that differ, largest difference of one channel) of two same-sized images."""
    if a[:2] != b[:2]:
        return None
    pixels, largest = 0, 0
    rgb_a, rgb_b = a[2], b[2]
    for i in range(0, len(rgb_a), 3):
        if rgb_a[i:i + 3] != rgb_b[i:i + 3]:
            pixels += 1
            largest = max(largest, *(abs(rgb_a[i + k] - rgb_b[i + k]) for k in range(3)))
    return pixels, largest


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--clrt", default=clrt_run.CLRT, type=pathlib.Path)
    parser.add_argument("--nff", default=REPO.parent / "shared" / "scenes" / "spd", type=pathlib.Path)
    parser.add_argument("--ray", default=REPO.parent / "shared" / "scenes" / "spd-ray",
                        type=pathlib.Path)
    parser.add_argument("--resolution", help="WxH (default: each scene's own)")
    parser.add_argument("--only", help="compare only scenes whose name contains this")
    args = parser.parse_args()
    scenes = sorted(p for p in args.nff.glob("*.nff") if not args.only or args.only in p.name)
    if not scenes:
        parser.error(f"no .nff file in {args.nff}")

    failures = 0
    print("| scene | size | differing pixels | largest difference | NFF s | .ray s |")
    print("|---|---|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory(prefix="clrt-nff-check-") as scratch:
        for nff in scenes:
            twin = args.ray / (nff.stem + ".ray")
            if not twin.exists():
                print(f"| {nff.stem} | no .ray twin | | | | |")
                failures += 1
                continue
            out_nff = pathlib.Path(scratch) / (nff.stem + "-nff.ppm")
            out_ray = pathlib.Path(scratch) / (nff.stem + "-ray.ppm")
            seconds_nff = render(args.clrt, nff, out_nff, args.resolution)
            seconds_ray = render(args.clrt, twin, out_ray, args.resolution)
            image_nff, image_ray = read_ppm(out_nff), read_ppm(out_ray)
            result = compare(image_nff, image_ray)
            size = f"{image_nff[0]}x{image_nff[1]}"
            if result is None:
                print(f"| {nff.stem} | {size} vs {image_ray[0]}x{image_ray[1]} | | | | |")
                failures += 1
                continue
            pixels, largest = result
            failures += pixels > 0
            print(f"| {nff.stem} | {size} | {pixels} | {largest} | {seconds_nff:.2f} | "
                  f"{seconds_ray:.2f} |", flush=True)
    print(f"\n{len(scenes) - failures} of {len(scenes)} pairs render to the same bytes")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
