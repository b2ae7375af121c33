#!/usr/bin/env python3
"""render_reference.py SCENE OUT.exr [--clrt CLRT] [--spp N] [--splits K] [--seed S] [--resolution WxH]

Renders a clrt scene with Mitsuba 3 (converted by ray_to_mitsuba.py from clrt's own reading of
it, `clrt --dump-scene`) as K sub-renders of N / K samples per pixel, each with its own seed,
into an estimate (estimates.py: the mean and its variance, as a 32-bit float EXR), the
reference that `clrt --mode path` is compared with (compare.py). Run it with the python of the venv tools/mitsuba/install.sh makes.

A scene with moving objects (`endpose`) is clrt's average over the shutter of static images.
Sub-render k of K renders the static scene at its own time t_k = open + (k + u_k) / K (close -
open), u_k uniform from the sub-render's seed (jittered strata): each sub-render is then an
unbiased estimate of that average on its own, so their mean is too, and their spread holds the
variation over time besides the pixel noise.
"""
import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import estimates  # noqa: E402
import ray_to_mitsuba  # noqa: E402

# Sub-renders of a scene with moving objects, whatever --splits asks for (when it asks fewer).
# One time per sub-render leaves an error in the time average that neighbouring pixels share
# (those an edge sweeps over within one stratum of the shutter), which the block test of
# compare.py, a sum over neighbouring pixels, reads as a bias. On motion.ray, with reference
# seeds 1 to 6: 8 sub-renders failed it at 5 of the 6 (mean Z^2 1.28 to 3.5, limit 1.49), 32
# passed all with up to 1.32, 64 passed seeds 1 to 8 with 0.63 to 0.98. The samples per pixel
# are divided among them, so the render costs about the same.
MOVING_SPLITS = 64


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
    resolution = ray_to_mitsuba.parse_resolution(args.resolution)
    try:
        dump = ray_to_mitsuba.dump_scene(args.clrt, args.scene)
        scene = ray_to_mitsuba.DumpedScene(dump)
        splits = max(args.splits, MOVING_SPLITS) if scene.moving else args.splits
        spp = -(-(args.spp or scene.samples) // splits)
        start = time.perf_counter()
        loaded = None if scene.moving else mi.load_dict(ray_to_mitsuba.to_mitsuba(scene, spp, resolution, args.seed))
        subs = []
        for k in range(splits):
            # Seeds far apart, so that no two references' sub-renders share one.
            seed = args.seed * 1000 + k
            if scene.moving:
                opening, closing = scene.shutter
                t = opening + (k + np.random.default_rng(seed).random()) / splits * (closing - opening)
                loaded = mi.load_dict(ray_to_mitsuba.to_mitsuba(ray_to_mitsuba.DumpedScene(dump, t), spp,
                                                                resolution, args.seed))
            subs.append(np.array(mi.render(loaded, seed=seed), dtype=np.float64))
    except ray_to_mitsuba.SceneError as e:
        sys.exit(str(e))
    estimates.write(args.out, *estimates.combine(subs))
    shutter = f", each at its own time of the shutter {list(scene.shutter)}" if scene.moving else ""
    print(f"{args.out}: Mitsuba {mi.__version__} {args.variant}, {splits} x {spp} spp{shutter}, "
          f"{time.perf_counter() - start:.1f} s")


if __name__ == "__main__":
    main()
