"""The warm start: the whole command for a small render, once every cache is filled, for one or
more clrt binaries run in turn (docs/performance.md#start-up).

    python3 tools/bench/warm_start/warm_start.py [--clrt BIN ...] [--runs 40] [--scene S]
           [--resolution 500x300] [--device SPEC] [--cached-only]

Each binary gets a program cache of its own (XDG_CACHE_HOME in a scratch folder, so none is
shared with the user's), filled the way a user's is: a first render, then, on PoCL, the wait for
the binary the background store makes. Each binary is then timed two ways, alternating run by
run with the others so that the machine's drift falls on all alike:
  cached:  the program from clrt's cache (on PoCL, the binary stored in the background);
  source:  CLRT_CACHE_DIR= (clrt's cache off): the program from the driver's own cache.
It prints the median, mean, best and worst wall time of each in milliseconds. --device picks the
OpenCL device as clrt's option does (e.g. `intel` with OCL_ICD_VENDORS naming Intel's runtime);
--cached-only leaves out the source runs, which take seconds on a driver without a cache of its
own (Intel's).
"""

import os
import pathlib
import statistics
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import clrt_run  # noqa: E402


def wait_for_store(folder, timeout=600.0):
    """Waits while a background store is under way in `folder` (a request is there); returns
    whether the folder then holds an entry."""
    deadline = time.monotonic() + timeout
    while folder.is_dir() and list(folder.glob("*.request")) and time.monotonic() < deadline:
        time.sleep(0.2)
    return folder.is_dir() and bool(list(folder.glob("*.bin")))


def main():
    parser = clrt_run.versions_parser(__doc__, 40, "timed runs of each (default 40)")
    parser.add_argument("--warmup", type=int, default=3, help="untimed runs of each (default 3)")
    parser.add_argument("--scene", type=pathlib.Path, default=clrt_run.REPO / "scenes" / "reflect.ray")
    parser.add_argument("--resolution", default="500x300")
    parser.add_argument("--device", help="clrt's --device (default: clrt's own choice)")
    parser.add_argument("--cached-only", action="store_true", help="time only the cached program")
    args = parser.parse_args()
    binaries = clrt_run.binaries_of(args)

    with tempfile.TemporaryDirectory(prefix="clrt-warm-start-") as work:
        work = pathlib.Path(work)
        image = work / "warm.png"
        command = [args.scene, "-q", "--resolution", args.resolution, "-o", image,
                   *(["--device", args.device] if args.device else [])]
        base = {k: v for k, v in os.environ.items() if k != "CLRT_CACHE_DIR"}
        setups = []
        for i, binary in enumerate(binaries):
            xdg = work / f"xdg-{i}"
            cached = {**base, "XDG_CACHE_HOME": str(xdg)}
            clrt_run.run_clrt(command, clrt=binary, env=cached)
            if not wait_for_store(xdg / "clrt"):
                print(f"{binary}: no program entry (a version that keeps none on this driver): "
                      "cached is the same as source", file=sys.stderr)
            setups.append((f"{binary} cached", binary, cached))
            if not args.cached_only:
                setups.append((f"{binary} source", binary, {**base, "CLRT_CACHE_DIR": ""}))
        for _, binary, env in setups:
            for _ in range(args.warmup):
                clrt_run.run_clrt(command, clrt=binary, env=env)
        times = {label: [] for label, _, _ in setups}
        for _ in range(args.runs):
            for label, binary, env in setups:
                times[label].append(clrt_run.run_clrt(command, clrt=binary, env=env).wall * 1000.0)

    print(f"{args.scene.name} at {args.resolution}, {args.runs} runs each, in turn (ms)")
    print("| clrt, program | median | mean | best | worst |")
    print("|---|---:|---:|---:|---:|")
    for label, values in times.items():
        print(f"| {label} | {statistics.median(values):.1f} | {statistics.mean(values):.1f} | "
              f"{min(values):.1f} | {max(values):.1f} |")


if __name__ == "__main__":
    main()
