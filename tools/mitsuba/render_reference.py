#!/usr/bin/env python3
"""render_reference.py SCENE.ray OUT.exr [--spp N] [--seed S] [--resolution WxH]

Renders a clrt `.ray` scene with Mitsuba 3 (converted by ray_to_mitsuba.py) into a 32-bit float
EXR, the reference that `clrt --mode path` is compared with (compare.py). Run it with the
python of the venv tools/mitsuba/install.sh makes.
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ray_to_mitsuba  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene")
    parser.add_argument("out", help="an .exr file")
    parser.add_argument("--spp", type=int, help="samples per pixel (default: the scene's `samples`)")
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
    try:
        scene = ray_to_mitsuba.RayScene(args.scene)
        d = ray_to_mitsuba.to_mitsuba(scene, args.spp, ray_to_mitsuba.parse_resolution(args.resolution), args.seed)
    except ray_to_mitsuba.SceneError as e:
        sys.exit(str(e))
    start = time.perf_counter()
    image = mi.render(mi.load_dict(d), seed=args.seed)
    mi.Bitmap(image).write(args.out)
    print(f"{args.out}: Mitsuba {mi.__version__} {args.variant}, {d['sensor']['sampler']['sample_count']} spp, "
          f"{time.perf_counter() - start:.1f} s")


if __name__ == "__main__":
    main()
