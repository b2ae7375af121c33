#!/usr/bin/env python3
"""ray_to_mitsuba_render.py SCENE -o OUT.exr [--variant V] [--clrt CLRT] [--spp N]
    [--resolution WxH] [--seed S] [--threads T] [--sampler NAME]

Renders one clrt scene with Mitsuba 3, for the race (race.py --peer mitsuba-llvm or
mitsuba-scalar). The scene is the one clrt reads (`clrt --dump-scene`), carried over by
tools/mitsuba/ray_to_mitsuba.py, the converter that `path_matches_mitsuba` checks clrt against;
here it runs with Mitsuba's own Russian roulette (its `path` integrator's default, from the
fifth vertex on) rather than none, as a user of Mitsuba renders, so that the race meets Mitsuba
at its defaults, as it meets Cycles. The converter maps Lambertian materials to Mitsuba's
native `diffuse` BSDF; scenes that need its Python plugins (Phong, mixed lobes) are refused by
the LLVM variant, and race.py's scenes need none.

Run with the Mitsuba venv's python (tools/mitsuba/install.sh); the LLVM variant needs LLVM 16
or newer, found through DRJIT_LIBLLVM_PATH (race.py sets it). Prints one JSON line: `build_s`
(the scene's dictionary, meshes included, from the dump the converter read: what a Mitsuba
user's scene file holds), `load_s` (mi.load_dict: the plugins and the BVH), `render_s`
(mi.render and its evaluation: for the LLVM variant, tracing and compiling the kernels, or
finding them in Dr.Jit's kernel cache, and running them), `write_s` (the EXR) and the settings
used. Reading the dump (`clrt --dump-scene` and the converter's parse) is in none of them.
"""
import argparse
import json
import pathlib
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "mitsuba"))
import ray_to_mitsuba as rtm  # noqa: E402
from peers import MITSUBA_SAMPLERS  # noqa: E402

VARIANTS = ("llvm_ad_rgb", "scalar_rgb")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", help="a .ray or .nff file")
    parser.add_argument("-o", "--output", required=True, help="the EXR to write")
    parser.add_argument("--variant", choices=VARIANTS, default="llvm_ad_rgb")
    parser.add_argument("--clrt", default=rtm.DEFAULT_CLRT, help="the clrt that reads the scene (default: build/clrt)")
    parser.add_argument("--spp", type=int, help="samples per pixel (default: the scene's `samples`)")
    parser.add_argument("--resolution", help="WxH (default: the scene's)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--sampler", choices=MITSUBA_SAMPLERS, default=MITSUBA_SAMPLERS[0])
    args = parser.parse_args()

    import drjit as dr
    import mitsuba as mi
    mi.set_variant(args.variant)
    dr.set_thread_count(args.threads)
    try:
        scene = rtm.read_scene(args.clrt, args.scene)
        started = time.perf_counter()
        description = rtm.to_mitsuba(scene, args.spp, rtm.parse_resolution(args.resolution), args.seed,
                                     russian_roulette=True, sampler=args.sampler)
        built_at = time.perf_counter()
        loaded = mi.load_dict(description)
        loaded_at = time.perf_counter()
        image = mi.render(loaded, seed=args.seed)
        dr.eval(image)
        dr.sync_thread()
        rendered_at = time.perf_counter()
    except rtm.SceneError as e:
        print(f"ray_to_mitsuba_render: {e}", file=sys.stderr)
        sys.exit(2)
    mi.Bitmap(image).write(str(args.output))
    written_at = time.perf_counter()
    sensor = loaded.sensors()[0]
    print(json.dumps({"build_s": built_at - started, "load_s": loaded_at - built_at, "render_s": rendered_at - loaded_at,
                      "write_s": written_at - rendered_at, "mitsuba": mi.__version__, "variant": args.variant, "sampler": args.sampler,
                      "spp": sensor.sampler().sample_count(), "seed": args.seed, "threads": dr.thread_count(),
                      "resolution": list(sensor.film().crop_size())}))


def read_exr(path):
    """The RGB planes of an EXR (H x W x 3 float64, top row first), through Mitsuba's reader."""
    import mitsuba as mi
    import numpy as np
    if not mi.variant():
        mi.set_variant("scalar_rgb")
    pixels = np.array(mi.Bitmap(str(path)), dtype=np.float64)
    return pixels[..., :3]


if __name__ == "__main__":
    main()
