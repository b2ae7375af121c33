#!/usr/bin/python3
"""Scale-out benchmark of clrt-mpi on one machine (README, "Scale-out").

    /usr/bin/python3 tools/bench/mpi_bench/mpi_bench.py [SCENE] [--build build] [--runs 3]

1. Parallel efficiency: one clrt process with PoCL on every core, against one clrt-mpi rank per
   core with one PoCL thread each, same frame (3840x2160 by default): efficiency = T(process)
   / T(ranks); 100% means the ranks waste nothing on splitting the frame.
2. Tile size against balance and overhead: for each --tile, the time, each rank's share of the
   pixels, and the bytes each rank sends.
3. The figures a model of N nodes needs: load, broadcast, BVH and kernel build per rank, render,
   pixel bytes per frame, write.
Runs alternate between configurations (best of --runs), as on a shared machine only ratios
taken side by side are worth anything.
"""
import argparse
import os
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import clrt_run  # noqa: E402

ROOT_FLAGS = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}


def timed(command, env=None):
    """(wall seconds, --stats=json) of one command, which ends the script if it fails."""
    try:
        result = clrt_run.run(command, env)
        return result.wall, result.stats
    except clrt_run.RunFailed as failure:
        sys.exit(f"error: {failure}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", nargs="?", default="scenes/reflect.ray")
    parser.add_argument("--build", default=clrt_run.BUILD)
    parser.add_argument("--resolution", default="3840x2160")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--ranks", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--tiles", default="32x32,64x64,128x128,256x256,512x512")
    args = parser.parse_args()
    clrt = os.path.join(args.build, "clrt")
    clrt_mpi = os.path.join(args.build, "clrt-mpi")
    frame = [args.scene, "--resolution", args.resolution, "-q", "-o", "/tmp/clrt-mpi-bench.png"]
    mpirun = ["mpirun", "--oversubscribe", "-np", str(args.ranks), "-x", "POCL_MAX_PTHREAD_COUNT=1"]

    single, ranked = [], {}
    tiles = args.tiles.split(",")
    stats = {}
    for _ in range(args.runs):
        seconds, stats["single"] = timed([clrt, *frame, "--stats=json"])
        single.append(seconds)
        for tile in tiles:
            seconds, stats[tile] = timed(
                [*mpirun, clrt_mpi, *frame, "--tile", tile, "--stats=json"],
                {**os.environ, **ROOT_FLAGS})
            ranked.setdefault(tile, []).append(seconds)

    best_single = min(single)
    s = stats["single"]["seconds"]
    print(f"{args.scene} at {args.resolution}, best of {args.runs}; one process with PoCL on "
          f"{os.cpu_count()} cores against {args.ranks} ranks of one PoCL thread each\n")
    print(f"one process: {best_single:.3f} s (load {s['load']:.3f}, BVH {s['bvh']:.3f}, kernel "
          f"build {s['kernel_build']:.3f}, render {s['render']:.3f}, write {s['write']:.3f})\n")
    print("| tile | command s | efficiency | tiles per rank | pixels per rank (max / mean) "
          "| pixel bytes sent per rank | scene bytes sent |")
    print("|---|---:|---:|---|---:|---|---:|")
    for tile in tiles:
        best = min(ranked[tile])
        report = stats[tile]
        per_rank = report["per_rank"]
        pixels = [r["pixels"] for r in per_rank]
        balance = max(pixels) / (sum(pixels) / len(pixels))
        print(f"| {tile} | {best:.3f} | {100 * best_single / best:.0f}% | "
              f"{' / '.join(str(r['tiles']) for r in per_rank)} | {balance:.2f} | "
              f"{' / '.join(str(r['pixel_bytes_sent']) for r in per_rank)} | "
              f"{report['scene_bytes_sent']} |")
    best_tile = min(tiles, key=lambda t: min(ranked[t]))
    print("\nPer rank at the best tile size (" + best_tile + "):\n")
    print("| rank | BVH s | kernel build s | render s (its devices) | rays |")
    print("|---:|---:|---:|---:|---:|")
    for r in stats[best_tile]["per_rank"]:
        t = r["stats"]["seconds"]
        print(f"| {r['rank']} | {t['bvh']:.3f} | {t['kernel_build']:.3f} | {t['render']:.3f} | "
              f"{r['stats']['rays']['total']} |")


if __name__ == "__main__":
    main()
