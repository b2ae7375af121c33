#!/usr/bin/env python3
"""render_reference.py SCENE OUT.exr [--clrt CLRT] [--spp N] [--splits K] [--seed S] [--resolution WxH]

Renders a clrt scene with Mitsuba 3 (converted by ray_to_mitsuba.py from clrt's own reading of
it, `clrt --dump-scene`) as K sub-renders of N / K samples per pixel, each with its own seed,
into an estimate (estimates.py: the mean and its variance, as a 32-bit float EXR), the
reference that `clrt --mode path` is compared with (compare.py). Run it with the python of the venv tools/mitsuba/install.sh makes.
"""
import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import estimates  # noqa: E402
import ray_to_mitsuba  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", help="a .ray or .nff file")
    parser.add_argument("out", help="an .exr file")
    parser.add_argument("--clrt", default=ray_to_mitsuba.DEFAULT_CLRT,
                        help="the clrt that reads the scene (default: build/clrt)")
    parser.add_argument("--spp", type=int, help="samples per pixel (default: the scene's `samples`)")
    parser.add_argument("--splits", type=int, default=8, help="independent sub-renders (default 8)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--resolution", help="WxH (default: the scene's `resolution`)")
    parser.add_argument("--variant", default="scalar_rgb",
                        help="Mitsuba variant (default scalar_rgb; llvm_ad_rgb needs a newer LLVM than Debian 12's)")
    args = parser.parse_args()

    import drjit as dr
    import mitsuba as mi
    mi.set_variant(args.variant)
    # Two threads: the machine's share. One is not an option: the Phong plugin's Python code
    # then waits forever for the interpreter lock the render holds.
    dr.set_thread_count(2)
    if args.splits < 2:
        sys.exit("render_reference.py: error: --splits must be 2 or more")
    try:
        scene = ray_to_mitsuba.read_scene(args.clrt, args.scene)
        spp = -(-(args.spp or scene.samples) // args.splits)
        d = ray_to_mitsuba.to_mitsuba(scene, spp, ray_to_mitsuba.parse_resolution(args.resolution), args.seed)
    except ray_to_mitsuba.SceneError as e:
        sys.exit(str(e))
    start = time.perf_counter()
    loaded = mi.load_dict(d)
    # Seeds far apart, so that no two references' sub-renders share one.
    subs = [np.array(mi.render(loaded, seed=args.seed * 1000 + k), dtype=np.float64) for k in range(args.splits)]
    estimates.write(args.out, *estimates.combine(subs))
    print(f"{args.out}: Mitsuba {mi.__version__} {args.variant}, {args.splits} x {spp} spp, "
          f"{time.perf_counter() - start:.1f} s")


if __name__ == "__main__":
    main()
