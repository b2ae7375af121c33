#!/usr/bin/env python3
"""path_matches_mitsuba.py --clrt CLRT --venv VENV --cache DIR --work DIR SCENE.ray...

The CTest check path_matches_mitsuba: renders each scene with `clrt --mode path` and with
Mitsuba 3 (render_reference.py), each as independent sub-renders with their own seeds that
estimates.py turns into a mean and its per-pixel variance, and compares them (compare.py).
Each reference is rendered once and kept in DIR under a hash of everything that decides its
pixels. Then the same comparison against the reference scaled by 1.03 must fail, or the sample
counts are too low for the check to mean anything. Exit 0 when every scene matches, 1 when one does not, 77
(skipped) when the Mitsuba venv of tools/mitsuba/install.sh is absent.
"""
import argparse
import glob
import hashlib
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SKIPPED = 77
# The relative error the check must be able to see at the sample counts it uses.
DETECTABLE = 1.03


def run(command, **kwargs):
    return subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kwargs)


def reference(python, scene, args, mitsuba_version):
    """The cached Mitsuba render of `scene`, rendered first if no cache entry matches."""
    key = hashlib.sha256()
    # The scene as clrt reads it, its meshes included, is what the converter reads.
    dump = run([args.clrt, "--dump-scene", "-", scene])
    if dump.returncode != 0:
        raise RuntimeError(f"clrt cannot read {scene}: {dump.stdout.strip()}")
    key.update(dump.stdout.encode())
    # The images of the environment and of textures are named by the dump, not held in it.
    scene_read = json.loads(dump.stdout)
    images = [scene_read["environment"]] if scene_read["environment"] else []
    for image in images + [t for t in scene_read["textures"] if "file" in t]:
        with open(image["file"], "rb") as f:
            key.update(f.read())
    code = [os.path.join(HERE, f"{name}.py") for name in ("ray_to_mitsuba", "lobes", "render_reference", "estimates")]
    for path in code:
        with open(path, "rb") as f:
            key.update(f.read())
    key.update(f"{mitsuba_version} {args.reference_spp} {args.splits} {args.reference_seed}".encode())
    name = os.path.splitext(os.path.basename(scene))[0]
    out = os.path.join(args.cache, f"{name}-{key.hexdigest()[:16]}.exr")
    if not os.path.exists(out):
        # A hidden name, so that the clean-up of older references below cannot match it.
        partial = os.path.join(args.cache, f".{name}-{os.getpid()}.exr")
        done = run([python, os.path.join(HERE, "render_reference.py"), scene, partial, "--clrt", args.clrt,
                    "--spp", str(args.reference_spp), "--splits", str(args.splits),
                    "--seed", str(args.reference_seed)])
        print(done.stdout, end="")
        if done.returncode != 0:
            raise RuntimeError(f"the Mitsuba reference of {scene} failed")
        # Renamed into place whole, so a render cut short never poses as a reference; the
        # scene's older references can never match again.
        for old in glob.glob(os.path.join(args.cache, f"{glob.escape(name)}-*.exr")):
            os.remove(old)
        os.replace(partial, out)
    return out


def clrt_estimate(python, scene, name, args):
    """clrt's estimate of `scene` from `splits` sub-renders, or None (having said why)."""
    subs = []
    for k in range(1, args.splits + 1):
        subs.append(os.path.join(args.work, f"{name}-{k}.exr"))
        done = run([args.clrt, "--mode", "path", "--spp", str(args.spp // args.splits), "--seed", str(k),
                    "--exr-pixel", "float", "-q", "-o", subs[-1], scene])
        if done.returncode != 0:
            print(done.stdout, end="")
            print(f"FAIL clrt --mode path exited with {done.returncode}")
            return None
    out = os.path.join(args.work, f"{name}.exr")
    done = run([python, os.path.join(HERE, "estimates.py"), out] + subs)
    if done.returncode != 0:
        print(done.stdout, end="")
        print("FAIL estimates.py could not combine clrt's sub-renders")
        return None
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--clrt", required=True)
    parser.add_argument("--venv", required=True)
    parser.add_argument("--cache", required=True, help="folder of the Mitsuba references")
    parser.add_argument("--work", required=True, help="folder for clrt's renders")
    parser.add_argument("--spp", type=int, default=256, help="clrt's samples per pixel (default 256)")
    parser.add_argument("--reference-spp", type=int, default=512, help="Mitsuba's (default 512)")
    parser.add_argument("--splits", type=int, default=8,
                        help="independent sub-renders of each image, for its per-pixel variance (default 8)")
    parser.add_argument("--reference-seed", type=int, default=7)
    parser.add_argument("scenes", nargs="+")
    args = parser.parse_args()

    python = os.path.join(args.venv, "bin", "python")
    version = run([python, "-c", "import mitsuba; print(mitsuba.__version__)"]) if os.path.exists(python) else None
    if version is None or version.returncode != 0:
        print(f"skipped: no Mitsuba 3 in {args.venv} (tools/mitsuba/install.sh BUILD_DIR installs it)")
        return SKIPPED
    os.makedirs(args.cache, exist_ok=True)
    os.makedirs(args.work, exist_ok=True)

    failed = []
    for scene in args.scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        print(f"== {name}", flush=True)
        try:
            ref = reference(python, scene, args, version.stdout.strip())
        except RuntimeError as e:
            print(f"FAIL {e}")
            failed.append(name)
            continue
        start = time.perf_counter()
        image = clrt_estimate(python, scene, name, args)
        if image is None:
            failed.append(name)
            continue
        print(f"clrt --mode path, {args.splits} x {args.spp // args.splits} spp: {time.perf_counter() - start:.1f} s")
        compare = [python, os.path.join(HERE, "compare.py"), image, ref]
        same = run(compare)
        print(same.stdout, end="")
        wrong = run(compare + ["--scale", str(DETECTABLE)])
        if wrong.returncode != 1:
            print(f"FAIL the comparison passes against the reference times {DETECTABLE}: too few samples to tell")
        else:
            print(f"ok   against the reference times {DETECTABLE} the comparison fails, as it must")
        if same.returncode != 0 or wrong.returncode != 1:
            failed.append(name)
    if failed:
        print(f"{len(failed)} of {len(args.scenes)} scenes differ from Mitsuba: {' '.join(failed)}")
        return 1
    print(f"all {len(args.scenes)} scenes match Mitsuba")
    return 0


if __name__ == "__main__":
    sys.exit(main())
