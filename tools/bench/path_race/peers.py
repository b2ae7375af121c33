"""The renderers clrt's path tracer races (race.py --peer): how each is installed, found, run
once per render as a fresh process, and how its EXRs are read back. Plain Python: importing
this needs neither bpy nor Mitsuba, only running a peer's render does."""
import glob
import json
import os
import pathlib
import re
import sys

HERE = pathlib.Path(__file__).resolve().parent
REPO = HERE.parents[2]
sys.path.insert(0, str(HERE.parent))  # tools/bench: clrt_run
import clrt_run  # noqa: E402

# Dr.Jit's LLVM back end aborts with Debian 12's LLVM 14 and 15.
OLDEST_LLVM = 16

# Mitsuba's samplers, its own default first.
MITSUBA_SAMPLERS = ("independent", "stratified", "multijitter", "orthogonal", "ldsampler")


def llvm_library(environ=None):
    """The LLVM shared library for Dr.Jit: $DRJIT_LIBLLVM_PATH when it names a file, else the
    newest libLLVM-N.so of version OLDEST_LLVM or later in the system's library folders (Debian
    12's `libllvm19` puts /usr/lib/x86_64-linux-gnu/libLLVM-19.so there); None if there is none."""
    environ = os.environ if environ is None else environ
    named = environ.get("DRJIT_LIBLLVM_PATH")
    if named:
        return named if os.path.isfile(named) else None
    found = []
    for pattern in ("/usr/lib/*/libLLVM-*.so", "/usr/lib/libLLVM-*.so", "/usr/lib/llvm-*/lib/libLLVM-*.so"):
        for path in glob.glob(pattern):
            m = re.search(r"libLLVM-(\d+)", os.path.basename(path))
            if m and int(m.group(1)) >= OLDEST_LLVM:
                found.append((int(m.group(1)), path))
    return max(found)[1] if found else None


def report_of(run, script, spp):
    """The JSON line a render script printed last (after whatever a log line left unfinished on
    it), which must say it took `spp` samples per pixel: Mitsuba's orthogonal sampler, for one,
    rounds the count to a prime's square."""
    lines = [line[line.index("{"):] for line in run.stdout.splitlines() if line.rstrip().endswith("}") and "{" in line]
    if not lines:
        raise clrt_run.RunFailed(f"{script} printed no report:\n{run.stdout[-2000:]}")
    report = json.loads(lines[-1])
    if report.get("spp", spp) != spp:
        raise clrt_run.RunFailed(f"{script} was asked for {spp} samples per pixel and took {report['spp']}")
    return report


class Peer:
    """One renderer raced by clrt. `name` is its --peer, `label` how tables call it."""
    name = label = venv_name = install = script = None
    modules = ()

    def __init__(self, build, clrt, threads, venv=None, sampler=None):
        self.venv = pathlib.Path(venv) if venv else pathlib.Path(build) / self.venv_name
        self.python = self.venv / "bin" / "python"
        self.clrt, self.threads = clrt, threads
        self.sampler = sampler

    def missing(self):
        """Why this peer cannot run here (race.py then exits 77), or None."""
        if not self.python.exists():
            return f"no venv at {self.venv} (bash {self.install} {self.venv.parent})"
        return None

    def environment(self):
        return dict(os.environ)

    def reference_sources(self):
        """The files whose change makes its cached references stale."""
        return [HERE / self.script, REPO / "tools" / "mitsuba" / "ray_to_mitsuba.py"]

    def settings(self):
        """What the record says of how the peer was run, besides its version."""
        return {}

    def command(self, scene, spp, seed, out, size, reference):
        return [self.python, HERE / self.script, scene, "-o", out, "--clrt", self.clrt, "--spp", spp,
                "--seed", seed, "--resolution", f"{size[0]}x{size[1]}", "--threads", self.threads]

    def render(self, scene, spp, seed, out, size, reference=False):
        """Renders one image into `out` (EXR), a converged `reference` or a raced render; the
        times of the process and of its render call."""
        run = clrt_run.run(self.command(scene, spp, seed, out, size, reference), self.environment())
        info = report_of(run, self.script, spp)
        return {"process_s": run.wall, "render_s": self.render_seconds(info), "build_s": self.build_seconds(info),
                "cpu_s": run.cpu, "peak_mib": run.peak_mib}


class Cycles(Peer):
    name, label, venv_name = "cycles", "Cycles", "cycles-venv"
    install = "tools/bench/path_race/install_cycles.sh"
    script = "ray_to_cycles.py"
    modules = ("bpy", "numpy")

    @staticmethod
    def render_seconds(info):
        # bpy.ops.render.render: sync, BVH, render and EXR write.
        return info["render_s"]

    @staticmethod
    def build_seconds(info):
        return info["build_s"]

    @staticmethod
    def version():
        import bpy
        return f"bpy {bpy.app.version_string}"

    @staticmethod
    def read_image(path):
        import ray_to_cycles
        return ray_to_cycles.read_exr(path)


class Mitsuba(Peer):
    venv_name = "mitsuba-venv"
    install = "tools/bench/path_race/install_mitsuba.sh"
    script = "ray_to_mitsuba_render.py"
    modules = ("mitsuba", "numpy")
    variant = None
    # Mitsuba's own default; race.py --mitsuba-sampler names another for the raced renders. The
    # references always take it: any sampler converges to the same image, and it takes any
    # sample count, where the stratified ones round theirs to a square or a prime's square.
    default_sampler = MITSUBA_SAMPLERS[0]

    def settings(self):
        return {"sampler": self.sampler or self.default_sampler, "reference_sampler": self.default_sampler}

    def command(self, scene, spp, seed, out, size, reference):
        sampler = self.default_sampler if reference else self.sampler or self.default_sampler
        return super().command(scene, spp, seed, out, size, reference) + ["--variant", self.variant,
                                                                          "--sampler", sampler]

    @staticmethod
    def render_seconds(info):
        # mi.load_dict (the BVH), mi.render and the EXR write: what Cycles' render call does.
        return info["load_s"] + info["render_s"] + info["write_s"]

    @staticmethod
    def build_seconds(info):
        # The scene's dictionary: as building the scene in bpy is for Cycles.
        return info["build_s"]

    def version(self):
        import mitsuba
        return f"mitsuba {mitsuba.__version__} {self.variant}"

    @staticmethod
    def read_image(path):
        import ray_to_mitsuba_render
        return ray_to_mitsuba_render.read_exr(path)


class MitsubaLlvm(Mitsuba):
    name, label, variant = "mitsuba-llvm", "Mitsuba LLVM", "llvm_ad_rgb"

    def missing(self):
        if llvm_library() is None:
            return (f"no LLVM {OLDEST_LLVM} or newer for Mitsuba's LLVM variant (apt-get install libllvm19, "
                    f"or DRJIT_LIBLLVM_PATH)")
        return super().missing()

    def environment(self):
        return {**os.environ, "DRJIT_LIBLLVM_PATH": llvm_library()}

    def version(self):
        return f"{super().version()} ({os.path.basename(llvm_library())})"


class MitsubaScalar(Mitsuba):
    name, label, variant = "mitsuba-scalar", "Mitsuba scalar", "scalar_rgb"


PEERS = {p.name: p for p in (Cycles, MitsubaLlvm, MitsubaScalar)}
