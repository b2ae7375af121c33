"""Peak memory of the whole command on the memory targets' scenes, for one or more clrt
binaries run in turn (docs/performance.md#memory).

    python3 tools/bench/peak_memory/peak_memory.py [--clrt BIN ...] [--runs 3] [--scale 1]

It writes its scenes into a scratch folder, deterministic and no one's in particular:
  heightfield: a grid of 708x708 vertices without normals, 999,698 triangles (36 MB of OBJ),
               rendered at 3840x2160;
  spheres:     3,000,000 spheres of one material over a 40x5x40 box, rendered at 32x24
               (the memory is the scene's; the picture is a stamp);
  texture:     a sphere showing an 8192x8192 8-bit PPM texture (201 MB), and one showing a
               4096x4096 PFM (201 MB), rendered at 64x64;
  environment: a sphere under an 8192x4096 PFM environment (403 MB), rendered at 64x64;
and, when build/scenes-large/tri-1m.ray exists (clrt-make-scenes), the 1M-triangle knot with
vertex normals at 3840x2160. --scale multiplies the triangle and sphere counts (the tests use a
small one). It prints each run's peak resident memory (wait4's ru_maxrss) in KiB and MB.
"""

import math
import pathlib
import random
import struct
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import clrt_run  # noqa: E402


def write_heightfield(folder, side):
    """A side x side grid of vertices, two triangles a cell, no normals."""
    obj = folder / "heightfield.obj"
    with open(obj, "w") as out:
        for j in range(side):
            for i in range(side):
                x, z = i / (side - 1) * 20 - 10, j / (side - 1) * 20 - 10
                y = math.sin(x * 1.3) * math.cos(z * 0.7) + 0.3 * math.sin(3 * x + 2 * z)
                out.write(f"v {x:.5f} {y:.5f} {z:.5f}\n")
        for j in range(side - 1):
            for i in range(side - 1):
                a = j * side + i + 1
                out.write(f"f {a} {a + side} {a + 1}\nf {a + 1} {a + side} {a + side + 1}\n")
    scene = folder / "heightfield.ray"
    scene.write_text("eye 0 8 -14\nlookat 0 0 0\nfov 60\nbackground 0.5 0.6 0.8\n"
                     "light 1 1 1 directional -1 -2 1\n"
                     "material 0.6 0.5 0.4 0.1 0.8 0.2 20 0 0\nmesh heightfield.obj\n")
    return scene


def write_spheres(folder, count):
    """`count` small spheres at random (seeded) places."""
    scene = folder / "spheres.ray"
    rng = random.Random(1)
    with open(scene, "w") as out:
        out.write("eye 0 12 -20\nlookat 0 1.5 0\nfov 60\nbackground 0.05 0.06 0.1\n"
                  "light 0.8 0.8 0.75 point -12.5 25 -15\n"
                  "material 0.9 0.75 0.45 0.1 0.8 0.5 40 0.2 0\n")
        for _ in range(count):
            out.write(f"sphere {rng.uniform(-20, 20):.5g} {rng.uniform(0, 5):.5g} "
                      f"{rng.uniform(-20, 20):.5g} {rng.uniform(0.01, 0.05):.4g}\n")
    return scene


def write_image_scene(folder, name, width, height, floats, command):
    """A `width` x `height` PPM or PFM of a repeating pattern, and a scene using it by `command`
    ("texture color image" or "environment")."""
    image = folder / f"{name}.{'pfm' if floats else 'ppm'}"
    with open(image, "wb") as out:
        if floats:
            out.write(b"PF\n%d %d\n-1.0\n" % (width, height))
            row = struct.pack(f"<{3 * width}f", *[(x * 13 % 97) / 97 for x in range(3 * width)])
        else:
            out.write(b"P6\n%d %d\n255\n" % (width, height))
            row = bytes((x * 7 ^ x >> 3) & 255 for x in range(3 * width))
        for _ in range(height):
            out.write(row)
    scene = folder / f"{name}.ray"
    material = "light 1 1 1 ambient\nmaterial 1 1 1 1 0 0 1 0 0\n"
    if command == "environment":
        scene.write_text(f"eye 0 0 3\nlookat 0 0 0\nenvironment {image.name}\n{material}sphere\n")
    else:
        scene.write_text(f"eye 0 0 3\nlookat 0 0 0\n{material}texture color image {image.name}\nsphere\n")
    return scene


def main():
    parser = clrt_run.versions_parser(__doc__, 3, "runs of each binary on each scene (default 3)")
    parser.add_argument("--scale", type=float, default=1.0, help="multiplies the scenes' sizes")
    args = parser.parse_args()
    binaries = clrt_run.binaries_of(args)

    with tempfile.TemporaryDirectory(prefix="clrt-peak-memory-") as work:
        work = pathlib.Path(work)
        side = max(3, round(1 + 707 * math.sqrt(args.scale)))
        cases = [(f"height field, {2 * (side - 1) ** 2:,} triangles without normals",
                  write_heightfield(work, side), "3840x2160"),
                 (f"{round(3_000_000 * args.scale):,} spheres",
                  write_spheres(work, round(3_000_000 * args.scale)), "32x24")]
        side = max(8, round(8192 * math.sqrt(args.scale)))
        half = max(4, side // 2)
        cases += [(f"texture, {side}x{side} 8-bit", write_image_scene(work, "texture8", side, side, False,
                                                                       "texture"), "64x64"),
                  (f"texture, {half}x{half} float", write_image_scene(work, "texturef", half, half, True,
                                                                       "texture"), "64x64"),
                  (f"environment, {side}x{half} float", write_image_scene(work, "sky", side, half, True,
                                                                           "environment"), "64x64")]
        knot = clrt_run.BUILD / "scenes-large" / "tri-1m.ray"
        if knot.exists() and args.scale == 1.0:
            cases.append(("knot, 1M triangles with normals", knot, "3840x2160"))
        print("| scene | resolution | clrt | peak KiB | peak MB |")
        print("|---|---|---|---:|---:|")
        for label, scene, resolution in cases:
            for _ in range(args.runs):
                for binary in binaries:
                    run = clrt_run.run_clrt([scene, "-q", "--resolution", resolution,
                                             "-o", work / "out.png"], clrt=binary)
                    kib = round(run.peak_mib * 1024)
                    print(f"| {label} | {resolution} | {binary} | {kib:,} | {kib * 1.024 / 1000:.1f} |",
                          flush=True)


if __name__ == "__main__":
    main()
