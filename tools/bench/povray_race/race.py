#!/usr/bin/python3
"""Races clrt against POV-Ray 3.7 on the seven SPD standard scenes, on the same work.

Per scene, POV-Ray renders SPD's own POV-Ray export (../shared/scenes/spd-pov/NAME.pov) and clrt
the same scene as a .ray conversion (../shared/scenes/spd-ray/NAME.ray, or the NFF original with
--clrt-input nff), both at the same size with one sample a pixel, five ray levels (camera ray
plus four bounces), the same lights and hard shadows and two threads. The runs interleave (POV-Ray,
clrt, POV-Ray, clrt, ...) so that load from other work on the machine falls on both alike. What
is measured and why is in README.md beside this script.

Usage (from the repository root, after the build; POV-Ray from Debian: apt-get install povray):
    /usr/bin/python3 tools/bench/povray_race/race.py [--runs 3] [--resolution 1024] [--threads 2]
        [--only NAME] [--clrt-input ray|nff] [--device SPEC] [--keep DIR] [--json FILE]
Exit status: 0 when every scene meets the target (clrt's command at most a third of POV-Ray's
parse + bounding + trace time), 1 when one misses it or a render fails, 2 on a usage error.
"""

import argparse
import json
import os
import pathlib
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import clrt_run  # noqa: E402
from clrt_run import RunFailed  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
SHARED_SCENES = clrt_run.REPO.parent / "shared" / "scenes"
SCENES = ["balls-4", "gears-4", "mount-6", "rings-7", "teapot-12", "tetra-6", "tree-11"]
TARGET = 1.0 / 3.0
PICTURE_THRESHOLD = 8  # steps of 1/255: differences below this are shading detail, not geometry
# POV-Ray's global settings for the race (see README.md): read before each scene by +HI.
POVRAY_HEADER = HERE / "race_settings.inc"
# SPD's rule: a ray tree five levels deep counting the camera ray; clrt counts bounces.
CLRT_MAX_DEPTH = 4

POVRAY_TIME = re.compile(r"^\s*(Parse|Bounding|Trace) Time:.*\(\s*([0-9.]+) seconds\)", re.M)
POVRAY_COUNTS = {
    "camera": re.compile(r"^Pixels:\s+([0-9]+)", re.M),
    "all": re.compile(r"^Rays:\s+([0-9]+)", re.M),
    "shadow": re.compile(r"^Shadow Ray Tests:\s+([0-9]+)", re.M),
    "reflection": re.compile(r"^Reflected Rays:\s+([0-9]+)", re.M),
    # POV-Ray counts rays bent at an interface and rays passing straight through a filtering
    # surface apart; clrt's refraction rays are both.
    "refraction": re.compile(r"^(?:Refracted|Transmitted) Rays:\s+([0-9]+)", re.M),
}


def povray_command(povray, scene, out, size, threads):
    # -A: no antialiasing (none of the seven asks for it); -D: no display window; +V: the
    # statistics and times this script reads; +FN: PNG, as clrt writes.
    return [povray, f"+I{scene}", f"+O{out}", f"+W{size}", f"+H{size}", "-A", f"+WT{threads}",
            "-D", "+V", "+FN", f"+HI{POVRAY_HEADER}"]


def clrt_arguments(scene, out, size, device):
    return [scene, "-o", out, "--resolution", f"{size}x{size}", "--spp", "1", "--max-depth",
            str(CLRT_MAX_DEPTH), "--device", device, "-q"]


def parse_povray(run):
    """POV-Ray's times and ray counts, which it prints (+V) on standard error."""
    text = run.stderr + run.stdout
    times = {name.lower(): float(seconds) for name, seconds in POVRAY_TIME.findall(text)}
    missing = {"parse", "bounding", "trace"} - times.keys()
    if missing:
        raise RunFailed(f"POV-Ray printed no {', '.join(sorted(missing))} time:\n{text[-2000:]}")
    counts = {}
    for kind, pattern in POVRAY_COUNTS.items():
        counts[kind] = sum(int(found) for found in pattern.findall(text))
    return times, counts


def clrt_stats(clrt, scene, out, size, device, env):
    """clrt's own split of one extra run: seconds per stage and rays by kind."""
    stats = clrt_run.run_clrt(clrt_arguments(scene, out, size, device), clrt, stats=True, env=env).stats
    return stats["seconds"], stats["rays"]


def compare_images(clrt_img, pov_png, clrt_png):
    """(PSNR in dB, share of pixels with a channel more than 8/255 apart) of the two pictures.
    clrt-img exits 1 when pixels differ, which here is expected."""
    result = subprocess.run([str(clrt_img), "diff", str(pov_png), str(clrt_png), "--threshold",
                             str(PICTURE_THRESHOLD)], capture_output=True, text=True)
    psnr = re.search(r"^PSNR: (\S+) dB", result.stdout, re.M)
    differing = re.search(r"^differing pixels: ([0-9]+)", result.stdout, re.M)
    pixels = re.search(r"^pixels: ([0-9]+)", result.stdout, re.M)
    if result.returncode not in (0, 1) or not (psnr and differing and pixels):
        raise RunFailed(f"clrt-img diff failed:\n{result.stderr[-2000:]}")
    return float(psnr.group(1)), int(differing.group(1)) / int(pixels.group(1))


def median(values):
    return statistics.median(values) if values else float("nan")


def race_scene(args, name, work):
    pov_scene = args.pov_dir / f"{name}.pov"
    clrt_scene = args.clrt_dir / f"{name}.{args.clrt_input}"
    for path in (pov_scene, clrt_scene):
        if not path.is_file():
            raise RunFailed(f"{path}: no such scene")
    pov_out, clrt_out = work / f"{name}-povray.png", work / f"{name}-clrt.png"
    env = clrt_run.pocl_threads(args.threads)
    # Warm-up at a small size: the scene files into the page cache, clrt's kernels into PoCL's
    # cache (the program never depends on the scene, so a user's second render finds it).
    clrt_run.run(povray_command(args.povray, pov_scene, pov_out, 64, args.threads))
    clrt_run.run_clrt(clrt_arguments(clrt_scene, clrt_out, 64, args.device), args.clrt, env=env)

    samples = {"pov_wall": [], "pov_cpu": [], "pov_mib": [], "parse": [], "bounding": [],
               "trace": [], "clrt_wall": [], "clrt_cpu": [], "clrt_mib": []}
    counts = None
    for _ in range(args.runs):
        pov = clrt_run.run(
            povray_command(args.povray, pov_scene, pov_out, args.resolution, args.threads))
        times, counts = parse_povray(pov)
        for key in ("parse", "bounding", "trace"):
            samples[key].append(times[key])
        clrt = clrt_run.run_clrt(
            clrt_arguments(clrt_scene, clrt_out, args.resolution, args.device), args.clrt, env=env)
        for renderer, run in (("pov", pov), ("clrt", clrt)):
            samples[f"{renderer}_wall"].append(run.wall)
            samples[f"{renderer}_mib"].append(run.peak_mib)
            samples[f"{renderer}_cpu"].append(run.cpu)
    split, rays = clrt_stats(args.clrt, clrt_scene, work / f"{name}-stats.png", args.resolution,
                             args.device, env)
    psnr, differing = compare_images(args.clrt_img, pov_out, clrt_out)
    pbt = [p + b + t for p, b, t in zip(samples["parse"], samples["bounding"], samples["trace"])]
    result = {key: median(values) for key, values in samples.items()}
    result.update(name=name, pov_pbt=median(pbt), pov_pbt_best=min(pbt),
                  clrt_wall_best=min(samples["clrt_wall"]), clrt_split=split, clrt_rays=rays,
                  pov_rays=counts, psnr=psnr, differing=differing, runs=samples)
    result["ratio"] = result["clrt_wall"] / result["pov_pbt"]
    result["ratio_best"] = result["clrt_wall_best"] / result["pov_pbt_best"]
    if args.keep:
        for path in (pov_out, clrt_out):
            shutil.copy(path, args.keep / path.name)
    return result


def print_tables(results, args):
    n = args.runs
    print(f"\nPOV-Ray {args.threads} threads (+WT{args.threads} -A) against clrt on device "
          f"'{args.device}' ({args.threads} threads), {args.resolution}x{args.resolution}, median of {n} "
          f"interleaved runs; ratio = clrt command / POV-Ray parse+bound+trace "
          f"(target <= {TARGET:.3f})\n")
    print("| scene | POV parse s | POV bound s | POV trace s | POV P+B+T s | POV wall s "
          "| clrt command s | ratio (best of runs) | target | POV peak MiB | clrt peak MiB |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|")
    for r in results:
        met = "met" if r["ratio"] <= TARGET else "missed"
        print(f"| {r['name']} | {r['parse']:.3f} | {r['bounding']:.3f} | {r['trace']:.3f} "
              f"| {r['pov_pbt']:.3f} | {r['pov_wall']:.3f} | {r['clrt_wall']:.3f} "
              f"| {r['ratio']:.2f} ({r['ratio_best']:.2f}) | {met} | {r['pov_mib']:.0f} "
              f"| {r['clrt_mib']:.0f} |")
    print("\nclrt's split (`clrt --stats`, one extra run), the rays each renderer traced "
          "(clrt / POV-Ray) and how far the two pictures are apart. Cores busy: CPU seconds "
          "over clrt's command time, and over POV-Ray's parse+bound+trace time.\n")
    print("| scene | load s | bvh s | kernel build s | render s | write s | total s "
          "| kernels busy s | CPU s clrt / POV | cores busy clrt / POV | camera | shadow "
          f"| reflection | refraction | PSNR dB | pixels > {PICTURE_THRESHOLD}/255 apart |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---|---|---|---|---|---|---:|---:|")
    for r in results:
        s, c, p = r["clrt_split"], r["clrt_rays"], r["pov_rays"]
        print(f"| {r['name']} | {s['load']:.3f} | {s['bvh']:.3f} | {s['kernel_build']:.3f} "
              f"| {s['render']:.3f} | {s['write']:.3f} | {s['total']:.3f} | {s['device']:.3f} "
              f"| {r['clrt_cpu']:.2f} / {r['pov_cpu']:.2f} "
              f"| {r['clrt_cpu'] / r['clrt_wall']:.2f} / {r['pov_cpu'] / r['pov_pbt']:.2f} "
              f"| {c['camera']} / {p['camera']} | {c['shadow']} / {p['shadow']} "
              f"| {c['reflection']} / {p['reflection']} | {c['refraction']} / {p['refraction']} "
              f"| {r['psnr']:.1f} | {100 * r['differing']:.1f}% |")


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--clrt", default=clrt_run.CLRT, type=pathlib.Path)
    parser.add_argument("--clrt-img", default=clrt_run.CLRT_IMG, type=pathlib.Path,
                        help="compares the two pictures")
    parser.add_argument("--povray", default="povray", help="POV-Ray 3.7 executable")
    parser.add_argument("--pov-dir", default=SHARED_SCENES / "spd-pov", type=pathlib.Path)
    parser.add_argument("--clrt-dir", type=pathlib.Path,
                        help="clrt's scenes (default: ../shared/scenes/spd-ray, or spd with "
                             "--clrt-input nff)")
    parser.add_argument("--clrt-input", choices=["ray", "nff"], default="ray")
    parser.add_argument("--resolution", type=int, default=1024, help="width = height")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--device", default="cpu",
                        help="clrt's --device; another OpenCL implementation's CPU device is "
                             "reached with OCL_ICD_VENDORS (tools/bench/povray_race/README.md)")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--only", action="append", help="race only this scene (repeatable)")
    parser.add_argument("--keep", type=pathlib.Path, help="copy both images of each scene here")
    parser.add_argument("--json", type=pathlib.Path, help="write every figure here")
    args = parser.parse_args()
    if args.clrt_dir is None:
        args.clrt_dir = SHARED_SCENES / ("spd-ray" if args.clrt_input == "ray" else "spd")
    if args.resolution < 1 or args.threads < 1 or args.runs < 1:
        parser.error("--resolution, --threads and --runs must be at least 1")
    unknown = set(args.only or []) - set(SCENES)
    if unknown:
        parser.error(f"unknown scene {', '.join(sorted(unknown))}; the seven are {SCENES}")
    resolved = shutil.which(args.povray)
    if not resolved:
        parser.error(f"{args.povray}: not found; install POV-Ray 3.7 (Debian: apt-get install "
                     f"povray) or name it with --povray")
    args.povray = resolved
    for tool in (args.clrt, args.clrt_img):
        if not os.access(tool, os.X_OK):
            parser.error(f"{tool}: no such executable (build it: bash tools/setup.sh)")
    if args.keep:
        args.keep.mkdir(parents=True, exist_ok=True)
    return args


def main():
    args = parse_arguments()
    scenes = [name for name in SCENES if not args.only or name in args.only]
    results = []
    with tempfile.TemporaryDirectory(prefix="povray-race-") as work:
        for name in scenes:
            print(f"racing {name} ...", file=sys.stderr, flush=True)
            try:
                results.append(race_scene(args, name, pathlib.Path(work)))
            except RunFailed as failure:
                print(f"error: {name}: {failure}", file=sys.stderr)
                return 1
    print_tables(results, args)
    if args.json:
        args.json.write_text(json.dumps(results, indent=2) + "\n")
    return 0 if all(r["ratio"] <= TARGET for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
