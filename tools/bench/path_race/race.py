#!/usr/bin/env python3
"""Races clrt's path tracer (`--mode path`) against a peer on the same scenes: Blender Cycles
(PyPI bpy 4.5) or Mitsuba 3 (PyPI mitsuba, its LLVM or scalar variant): noise at equal samples
per pixel, wall-clock time, and time to equal quality.

Per scene:
 (a) a converged reference of each renderer (--ref-spp samples, cached under
     BUILD/tools/bench/path_race/references, keyed by a hash of the scene, its meshes, the
     renderer and the settings); their image means must agree to within --tolerance (1%) in
     every channel, or the scene is not the same in both and the race stops (exit 1);
 (b) at each --spp, --seeds (at least 2) renders with seeds 1, 2, ... of each renderer: its
     noise, the per-pixel RMS difference between renders of different seeds over the square
     root of 2, and clrt's noise / the peer's; the RMSE against each reference is reported too;
 (c) the wall-clock time of each whole command (clrt: `clrt ... -o out.exr`; the peer: its
     render call, and its whole python process), clrt and the peer alternated after one
     untimed warm-up of each at that sample count, median of --runs;
 (d) efficiency 1 / (noise^2 time), and clrt's speed-up at equal quality, the ratio of
     efficiencies (against the peer's render call and against its whole process).
Prints a Markdown table and writes a JSON record (--json; default
BUILD/tools/bench/path_race/race-PEER.json). README.md beside this file says why each step is so.

Usage (from the repository root, after install_cycles.sh or install_mitsuba.sh BUILD):
    python3 tools/bench/path_race/race.py [--peer cycles|mitsuba-llvm|mitsuba-scalar]
        [--spp 16,64] [--seeds 3] [--runs 3] [--resolution 128x128] [--ref-spp 2048]
        [--clrt PATH] [--venv PATH] [SCENE...]
SCENE is a .ray path or a name: cornell1, knot, knob4, units_point, units_area (default:
cornell1 knot).
Run by any python3, it restarts itself with the peer's venv python (which reads the EXRs).
Exit status: 0 done, 1 the references disagree or a render failed, 2 a usage error, 77 the
peer is not installed (no venv, or no LLVM 16 or newer for Mitsuba's LLVM variant).
"""
import argparse
import hashlib
import json
import os
import pathlib
import platform
import shutil
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
REPO = HERE.parents[2]
sys.path.insert(0, str(HERE.parent))  # tools/bench: clrt_run
sys.path.insert(0, str(HERE))
import clrt_run  # noqa: E402
import metrics  # noqa: E402
import peers  # noqa: E402

DEFAULT_SCENES = ["cornell1", "knot"]
KNOT_OBJ = "knot-100k-flat.obj"
# The material knob's lobe subsets that every peer's converter maps to a native BSDF of
# Mitsuba's LLVM variant: Lambertian, mirror, glass, and the black absorber.
KNOB_SUBSETS = ("d", "m", "t", "none")
REFERENCE_SEED = 1000003  # far from the race's seeds 1, 2, ...


def default_build():
    return pathlib.Path(os.environ.get("CLRT_BUILD", REPO / "build"))


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scenes", nargs="*", help="scene names or .ray paths (default: cornell1 knot)")
    p.add_argument("--build", type=pathlib.Path, default=default_build(), help="the build tree (default: build)")
    p.add_argument("--clrt", type=pathlib.Path, help="clrt binary (default: $CLRT or BUILD/clrt)")
    p.add_argument("--peer", choices=sorted(peers.PEERS), default="cycles", help="the renderer raced (default: cycles)")
    p.add_argument("--mitsuba-sampler", choices=peers.MITSUBA_SAMPLERS,
                   help=f"Mitsuba's sampler (default: its own default, {peers.MITSUBA_SAMPLERS[0]})")
    p.add_argument("--venv", type=pathlib.Path,
                   help="the peer's venv (default: BUILD/cycles-venv, or BUILD/mitsuba-venv for Mitsuba)")
    p.add_argument("--spp", default="16,64", help="samples per pixel of the raced renders, comma-separated")
    p.add_argument("--seeds", type=int, default=3, help="independent renders per renderer and spp, between which the noise is measured")
    p.add_argument("--runs", type=int, default=3, help="timed runs per renderer and spp (median)")
    p.add_argument("--resolution", default="128x128", help="WxH")
    p.add_argument("--ref-spp", type=int, default=2048, help="samples per pixel of the references")
    p.add_argument("--threads", type=int, default=2, help="CPU threads of each renderer")
    p.add_argument("--device", help="clrt's --device for the raced renders (default: clrt's own, PoCL's CPU "
                                    "device); the references are the same bytes on every implementation")
    p.add_argument("--tolerance", type=float, default=0.01, help="largest relative difference of the references' means")
    p.add_argument("--json", type=pathlib.Path, help="where to write the record")
    p.add_argument("--keep", type=pathlib.Path, help="keep every image in this folder")
    args = p.parse_args(argv)
    args.clrt = args.clrt or pathlib.Path(os.environ.get("CLRT", args.build / "clrt"))
    try:
        args.spp = [int(s) for s in args.spp.split(",")]
        w, _, h = args.resolution.lower().partition("x")
        args.size = (int(w), int(h))
    except ValueError:
        p.error("--spp takes numbers separated by commas, --resolution WxH")
    if min(args.spp) < 1 or min(args.size) < 1 or args.runs < 1 or args.ref_spp < 1:
        p.error("counts and sizes must be positive")
    if args.seeds < 2:
        p.error("--seeds must be 2 or more: the noise is measured between renders of different seeds")
    args.scenes = args.scenes or DEFAULT_SCENES
    if args.mitsuba_sampler and not args.peer.startswith("mitsuba"):
        p.error("--mitsuba-sampler is for the Mitsuba peers")
    args.peer = peers.PEERS[args.peer](args.build, args.clrt, args.threads, args.venv, args.mitsuba_sampler)
    return args


def restart_in_venv(peer):
    """The peer's modules read its EXRs (and numpy does the sums): run under its venv's python."""
    try:
        for module in peer.modules:
            __import__(module)
        return
    except ImportError:
        pass
    why = peer.missing()
    if why:
        print(f"race.py: {peer.label}: {why}; skipped", file=sys.stderr)
        sys.exit(77)
    if os.environ.get("PATH_RACE_RESTARTED"):
        sys.exit(f"race.py: {peer.python} cannot import {' and '.join(peer.modules)}")
    os.environ["PATH_RACE_RESTARTED"] = "1"
    os.execv(str(peer.python), [str(peer.python), str(pathlib.Path(__file__).resolve()), *sys.argv[1:]])


# ---------------------------------------------------------------------------------------------
# scenes


def flatten_obj(source, target):
    """Writes `source` (an OBJ with a normal at every corner) without its normals: flat faces."""
    faces = 0
    with open(source, encoding="utf-8") as f, open(target, "w", encoding="utf-8") as out:
        out.write(f"# {pathlib.Path(source).name} of clrt-make-scenes --scale 0.1 without its vertex normals "
                  "(flat shading), for tools/bench/path_race\n")
        for line in f:
            if line.startswith("v "):
                out.write(line)
            elif line.startswith("f "):
                out.write("f " + " ".join(w.split("/")[0] for w in line.split()[1:]) + "\n")
                faces += 1
    return faces


def make_scenes(build, arguments):
    """Runs clrt-make-scenes ARGUMENTS... into a new temporary folder, which it returns."""
    maker = build / "tools" / "make_scenes" / "clrt-make-scenes"
    if not maker.exists():
        sys.exit(f"race.py: {maker} is missing (cmake --build {build}); it makes the race's large scenes")
    folder = tempfile.TemporaryDirectory()
    subprocess.run([str(maker), *arguments, folder.name], check=True, stdout=subprocess.DEVNULL)
    return folder


def race_folder(build):
    folder = build / "tools" / "bench" / "path_race" / "scenes"
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def knob_lines(text):
    """A knob-lobes scene of clrt-make-scenes: its lines before the spheres' material, that
    material's line, and the sphere lines."""
    lines = text.splitlines()
    first_sphere = next(i for i, line in enumerate(lines) if line.startswith("sphere "))
    return lines[:first_sphere - 1], lines[first_sphere - 1], lines[first_sphere:]


def prepare_knob(build):
    """The material knob (clrt-make-scenes --family knob: 576 spheres on a floor under one area
    light) with its spheres spread evenly and at random (a fixed seed) over the lobe subsets
    KNOB_SUBSETS, the materials of its knob-lobes-*.ray scenes; the area light takes 1 shadow
    ray, as the peers take one light sample a vertex; and the sky is black: Mitsuba's emitters
    are opaque, and under the knob's grey-blue sky they hid 1.6-3% of the light that clrt and
    Cycles see through the light."""
    import random
    scene = race_folder(build) / "knob4.ray"
    with make_scenes(build, ["--family", "knob"]) as tmp:
        parts = {s: knob_lines((pathlib.Path(tmp) / f"knob-lobes-{s}.ray").read_text(encoding="utf-8"))
                 for s in KNOB_SUBSETS}
    head, _, spheres = parts["d"]
    subsets = [KNOB_SUBSETS[i % len(KNOB_SUBSETS)] for i in range(len(spheres))]
    random.Random(4).shuffle(subsets)
    out = [f"# knob4.ray, written by tools/bench/path_race/race.py from clrt-make-scenes --family knob: "
           f"{len(spheres)} spheres, each Lambertian, mirror, glass or black ({', '.join(KNOB_SUBSETS)})"]
    for line in head:
        if line.startswith("#"):
            continue
        if line.startswith("background "):
            line = "background 0 0 0"
        elif line.startswith("light ") and " area " in line:
            line = " ".join(line.split()[:-1] + ["1"])
        out.append(line)
    for subset, sphere in zip(subsets, spheres):
        out += [parts[subset][1], sphere]
    scene.write_text("\n".join(out) + "\n", encoding="utf-8")
    return scene


def prepare_knot(build):
    """The mesh scene: knot.ray copied next to the flat knot OBJ in the build tree, which
    clrt-make-scenes makes (its knot-1m.obj at --scale 0.1 has 100,014 triangles)."""
    folder = race_folder(build)
    obj = folder / KNOT_OBJ
    if not obj.exists():
        with make_scenes(build, ["--scale", "0.1"]) as tmp:
            part = obj.with_suffix(".part")
            faces = flatten_obj(pathlib.Path(tmp) / "knot-1m.obj", part)
            part.rename(obj)
        print(f"race.py: wrote {obj} ({faces} triangles)", file=sys.stderr)
    scene = folder / "knot.ray"
    shutil.copyfile(HERE / "scenes" / "knot.ray", scene)
    return scene


# A scene name's file, or the function that writes it into the build tree.
SCENES = {"cornell1": HERE / "scenes" / "cornell1.ray", "knot": prepare_knot, "knob4": prepare_knob,
          "units_point": HERE / "scenes" / "units_point.ray",
          "units_area": HERE / "scenes" / "units_area.ray"}


def resolve_scene(name, build):
    if name in SCENES:
        scene = SCENES[name]
        return scene(build) if callable(scene) else scene
    path = pathlib.Path(name)
    if not path.exists():
        sys.exit(f"race.py: no scene {name} (names: {', '.join(SCENES)})")
    return path


def scene_digest(clrt, path):
    """The scene as clrt reads it, its meshes included (hash of `clrt --dump-scene`)."""
    dump = subprocess.run([str(clrt), "--dump-scene", "-", str(path)], stdout=subprocess.PIPE, check=True)
    return hashlib.sha256(dump.stdout).hexdigest()


# ---------------------------------------------------------------------------------------------
# renders


class Renderers:
    """clrt and its peer, each a fresh process per render."""

    def __init__(self, args):
        self.args, self.peer = args, args.peer
        self.env = clrt_run.pocl_threads(args.threads)

    def clrt(self, scene, spp, seed, out, size, reference=False):
        command = [self.args.clrt, scene, "--mode", "path", "--spp", spp, "--seed", seed,
                   "--resolution", f"{size[0]}x{size[1]}", "--threads", self.args.threads,
                   "--exr-pixel", "float", "-o", out, "-q"]
        if self.args.device and not reference:
            command += ["--device", self.args.device]
        run = clrt_run.run(command, self.env)
        return {"process_s": run.wall, "cpu_s": run.cpu, "peak_mib": run.peak_mib}

    def render(self, name, *arguments, **options):
        return (self.clrt if name == "clrt" else self.peer.render)(*arguments, **options)


def reference(renderers, name, scene, args):
    """The renderer's converged image, rendered once per scene and settings."""
    folder = args.build / "tools" / "bench" / "path_race" / "references"
    folder.mkdir(parents=True, exist_ok=True)
    h = hashlib.sha256()
    h.update(scene_digest(args.clrt, scene).encode())
    h.update(f"{args.size} {args.ref_spp} {REFERENCE_SEED} {args.threads}".encode())
    if name == "clrt":
        h.update(pathlib.Path(args.clrt).read_bytes())
    else:
        for source in args.peer.reference_sources():
            h.update(source.read_bytes())
        h.update(args.peer.version().encode())
    name_in_file = "clrt" if name == "clrt" else args.peer.name
    path = folder / f"{scene.stem}-{args.size[0]}x{args.size[1]}-{name_in_file}-{h.hexdigest()[:16]}.exr"
    if not path.exists():
        print(f"race.py: rendering {name}'s reference of {scene.name} ({args.ref_spp} spp)...", file=sys.stderr)
        part = path.with_name(path.stem + ".part.exr")
        started = time.perf_counter()
        renderers.render(name, scene, args.ref_spp, REFERENCE_SEED, part, args.size, reference=True)
        part.rename(path)
        print(f"race.py:   {time.perf_counter() - started:.1f} s", file=sys.stderr)
    return path, args.peer.read_image(path)


def flat(image):
    return image.ravel().tolist()


def race_scene(renderers, label, scene, args, workdir):
    peer = args.peer
    record = {"scene": label, "path": str(scene)}
    refs = {}
    for name in ("clrt", "peer"):
        path, image = reference(renderers, name, scene, args)
        refs[name] = image
        record[f"{name}_reference"] = {"path": str(path), "spp": args.ref_spp,
                                       "mean_rgb": image.mean(axis=(0, 1)).tolist()}
    differences = metrics.relative_differences(record["clrt_reference"]["mean_rgb"],
                                               record["peer_reference"]["mean_rgb"])
    record["reference_mean_difference_rgb"] = differences
    record["references_agree"] = metrics.means_agree(record["clrt_reference"]["mean_rgb"],
                                                     record["peer_reference"]["mean_rgb"], args.tolerance)
    print(f"race.py: {label}: clrt's reference mean differs from {peer.label}'s by "
          f"{', '.join(f'{100 * d:+.2f}%' for d in differences)} (R, G, B)", file=sys.stderr)
    if not record["references_agree"]:
        return record

    record["spp"] = []
    for spp in args.spp:
        # Warm-up, untimed, at the sample count timed: the scene files and meshes into the page
        # cache, clrt's kernels into its program cache, the peer's libraries into memory, and
        # the kernels Mitsuba's LLVM variant compiles for these settings into Dr.Jit's cache.
        for name in ("clrt", "peer"):
            renderers.render(name, scene, spp, 1, workdir / "warm.exr", args.size)
        runs = {"clrt": [], "peer": []}
        errors = {"clrt": [], "peer": [], "clrt_vs_peer_ref": [], "peer_vs_clrt_ref": []}
        images = {"clrt": [], "peer": []}
        for i in range(max(args.seeds, args.runs)):
            seed = i + 1
            for name in ("clrt", "peer"):  # alternated, so that load falls on both alike
                out = workdir / f"{scene.stem}-{name}-{spp}-{seed}.exr"
                runs[name].append(renderers.render(name, scene, spp, seed, out, args.size))
                if i < args.seeds:
                    image = flat(peer.read_image(out))
                    images[name].append(image)
                    other = "peer" if name == "clrt" else "clrt"
                    errors[name].append(metrics.rmse(image, flat(refs[name])))
                    errors[f"{name}_vs_{other}_ref"].append(metrics.rmse(image, flat(refs[other])))
                if args.keep:
                    args.keep.mkdir(parents=True, exist_ok=True)
                    shutil.copyfile(out, args.keep / out.name)
                out.unlink()
        row = {"spp": spp, "seeds": args.seeds, "runs": args.runs, "times": runs, "rmse_per_seed": errors}
        # The noise, from the seeds' renders among themselves: against a reference it would
        # hold the reference's own noise too, which for a peer whose reference sampler is
        # noisier than its raced one was a third of its error at 64 spp.
        row["clrt_rmse"] = metrics.noise_rmse(images["clrt"])
        row["peer_rmse"] = metrics.noise_rmse(images["peer"])
        row["clrt_rmse_vs_own_ref"] = metrics.pooled_rmse(errors["clrt"])
        row["peer_rmse_vs_own_ref"] = metrics.pooled_rmse(errors["peer"])
        row["clrt_rmse_vs_peer_ref"] = metrics.pooled_rmse(errors["clrt_vs_peer_ref"])
        row["peer_rmse_vs_clrt_ref"] = metrics.pooled_rmse(errors["peer_vs_clrt_ref"])
        row["rmse_ratio"] = row["clrt_rmse"] / row["peer_rmse"]
        row["clrt_s"] = metrics.median(r["process_s"] for r in runs["clrt"][:args.runs])
        for time_of in ("render", "process"):
            seconds = metrics.median(r[f"{time_of}_s"] for r in runs["peer"][:args.runs])
            row[f"peer_{time_of}_s"] = seconds
            row[f"peer_efficiency_{time_of}"] = metrics.efficiency(row["peer_rmse"], seconds)
            row[f"speedup_vs_{time_of}"] = metrics.speedup(row["clrt_rmse"], row["clrt_s"], row["peer_rmse"], seconds)
        row["clrt_efficiency"] = metrics.efficiency(row["clrt_rmse"], row["clrt_s"])
        record["spp"].append(row)
        print(f"race.py: {label} {spp} spp: noise clrt {row['clrt_rmse']:.4g}, {peer.label} {row['peer_rmse']:.4g}; "
              f"time clrt {row['clrt_s']:.2f} s, {peer.label} {row['peer_render_s']:.2f} s "
              f"({row['peer_process_s']:.2f} s process)", file=sys.stderr)
    return record


# ---------------------------------------------------------------------------------------------
# the record


def cpu_model():
    try:
        for line in open("/proc/cpuinfo", encoding="utf-8"):
            if line.lower().startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def git_commit():
    try:
        head = subprocess.run(["git", "-C", str(REPO), "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(REPO), "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True).stdout.strip() != ""
        return head, dirty
    except (OSError, subprocess.CalledProcessError):
        return "unknown", None


def markdown(record):
    p = record["peer"]["label"]
    lines = [f"| scene | spp | noise clrt | noise {p} | clrt / {p} | clrt vs own ref | {p} vs own ref "
             f"| clrt vs {p}'s ref | {p} vs clrt's ref | clrt s | {p} render s | {p} process s "
             "| speed-up (render) | speed-up (process) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for scene in record["scenes"]:
        if not scene.get("references_agree"):
            d = ", ".join(f"{100 * x:+.2f}%" for x in scene["reference_mean_difference_rgb"])
            lines.append(f"| {scene['scene']} | references disagree: {d} |" + " |" * 12)
            continue
        for r in scene["spp"]:
            lines.append(
                f"| {scene['scene']} | {r['spp']} | {r['clrt_rmse']:.4g} | {r['peer_rmse']:.4g} | {r['rmse_ratio']:.2f} "
                f"| {r['clrt_rmse_vs_own_ref']:.4g} | {r['peer_rmse_vs_own_ref']:.4g} | {r['clrt_rmse_vs_peer_ref']:.4g} | {r['peer_rmse_vs_clrt_ref']:.4g} | {r['clrt_s']:.2f} "
                f"| {r['peer_render_s']:.2f} | {r['peer_process_s']:.2f} | {r['speedup_vs_render']:.2f} "
                f"| {r['speedup_vs_process']:.2f} |")
    means = ["", f"Reference means, clrt against {p} (R, G, B): " + "; ".join(
        f"{s['scene']} " + ", ".join(f"{100 * x:+.2f}%" for x in s["reference_mean_difference_rgb"])
        for s in record["scenes"])]
    return "\n".join(lines + means)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    restart_in_venv(args.peer)
    if not pathlib.Path(args.clrt).exists():
        sys.exit(f"race.py: no clrt at {args.clrt} (--clrt or $CLRT)")
    scenes = [(name, resolve_scene(name, args.build)) for name in args.scenes]
    head, dirty = git_commit()
    record = {
        "tool": "tools/bench/path_race/race.py",
        "peer": {"name": args.peer.name, "label": args.peer.label, "version": args.peer.version(),
                 **args.peer.settings()},
        "machine": {"cpu": cpu_model(), "cores": os.cpu_count(), "load_before": list(os.getloadavg())},
        "versions": {"clrt_commit": head, "clrt_tree_dirty": dirty,
                     "clrt": str(args.clrt), "python": platform.python_version()},
        "settings": {"resolution": list(args.size), "spp": args.spp, "seeds": args.seeds, "runs": args.runs,
                     "ref_spp": args.ref_spp, "threads": args.threads, "tolerance": args.tolerance,
                     "clrt_device": args.device or "default"},
        "scenes": [],
    }
    status = 0
    with tempfile.TemporaryDirectory(prefix="path_race-") as tmp:
        renderers = Renderers(args)
        try:
            for label, scene in scenes:
                result = race_scene(renderers, label, scene, args, pathlib.Path(tmp))
                record["scenes"].append(result)
                if not result["references_agree"]:
                    print(f"race.py: error: {label}: the two references' means differ by more than "
                          f"{100 * args.tolerance:g}%: the scenes are not matched; stopping", file=sys.stderr)
                    status = 1
                    break
        except clrt_run.RunFailed as e:
            print(f"race.py: error: a render failed: {e}", file=sys.stderr)
            record["error"] = str(e)
            status = 1
    record["machine"]["load_after"] = list(os.getloadavg())
    out = args.json or args.build / "tools" / "bench" / "path_race" / f"race-{args.peer.name}.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(record, indent=1) + "\n", encoding="utf-8")
    print(markdown(record))
    print(f"\nrecord: {out}; machine: {record['machine']['cpu']}, {record['machine']['cores']} cores, load "
          f"{record['machine']['load_before'][0]:.2f} before, {record['machine']['load_after'][0]:.2f} after; "
          f"{record['peer']['version']}{', sampler ' + record['peer']['sampler'] if 'sampler' in record['peer'] else ''}, clrt {head}{' (tree with uncommitted changes)' if dirty else ''}")
    return status


if __name__ == "__main__":
    sys.exit(main())
