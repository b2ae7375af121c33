"""What every benchmark script does with a process: runs clrt (or POV-Ray, or mpirun) and tells
its wall time, CPU time, peak resident memory and, for clrt's --stats=json, the statistics.

The scripts in the folders beside this file import it with
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
"""

import argparse
import dataclasses
import json
import os
import pathlib
import subprocess
import tempfile
import time

REPO = pathlib.Path(__file__).resolve().parents[2]
BUILD = REPO / "build"
CLRT = BUILD / "clrt"
CLRT_IMG = BUILD / "tools" / "img" / "clrt-img"


class RunFailed(RuntimeError):
    """A process exited with a status other than 0, or printed no statistics."""


@dataclasses.dataclass
class Run:
    command: list
    wall: float  # seconds from the start to the exit
    cpu: float  # user and system seconds, the process's and those of the children it waited for
    peak_mib: float  # the largest resident set of the process or of one of those children
    stdout: str
    stderr: str

    @property
    def stats(self):
        """The statistics clrt printed for --stats=json."""
        return parse_stats(self.stdout)


def parse_stats(text):
    """The first JSON object in `text`: what clrt (or clrt-mpi) prints for --stats=json, whatever
    came before it."""
    start = text.find("{")
    if start < 0:
        raise RunFailed(f"no statistics in the output:\n{text[-2000:]}")
    return json.JSONDecoder().raw_decode(text, start)[0]


def run(command, env=None):
    """Runs `command` (program and arguments; paths are fine) to its end and measures it.

    The output goes to files rather than pipes so that nothing has to drain them while the
    process runs. wait4 gives this process's own peak memory and CPU time, where
    getrusage(RUSAGE_CHILDREN) would give the largest peak of every child so far."""
    command = [str(word) for word in command]
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        started = time.perf_counter()
        process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=out, stderr=err,
                                   env=env)
        _, status, usage = os.wait4(process.pid, 0)
        wall = time.perf_counter() - started
        # Popen did not reap the process itself, and must not try to.
        process.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        stdout = out.read().decode(errors="replace")
        stderr = err.read().decode(errors="replace")
    if process.returncode != 0:
        raise RunFailed(f"{' '.join(command)} exited with {process.returncode}:\n"
                        f"{(stderr or stdout)[-2000:]}")
    return Run(command, wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0, stdout,
               stderr)


def run_clrt(arguments, clrt=CLRT, stats=False, env=None):
    """One clrt command: `arguments` follow the program's name; with `stats`, --stats=json too,
    whose statistics the result's `stats` holds."""
    return run([clrt, *arguments, *(["--stats=json"] if stats else [])], env)


def pocl_threads(threads, env=None):
    """`env` (default: this process's environment) with PoCL's CPU device limited to `threads`
    worker threads: PoCL 3 (Debian 12) reads POCL_MAX_PTHREAD_COUNT, PoCL 4 and later
    POCL_CPU_MAX_CU_COUNT."""
    return {**(os.environ if env is None else env), "POCL_MAX_PTHREAD_COUNT": str(threads),
            "POCL_CPU_MAX_CU_COUNT": str(threads)}


def versions_parser(doc, runs, runs_help):
    """The command line of a script that runs one or more clrt binaries in turn: --clrt
    (repeatable; the binaries, default build/clrt) and --runs (default `runs`), described by the
    first paragraph of `doc`. The parsed arguments' `binaries` are the ones to run."""
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    parser.add_argument("--clrt", action="append", type=pathlib.Path, dest="binaries", metavar="BIN",
                        help="a clrt binary (repeatable; default build/clrt)")
    parser.add_argument("--runs", type=int, default=runs, help=runs_help)
    parser.set_defaults(binaries=None)
    return parser


def binaries_of(args):
    """The binaries --clrt named, or build/clrt."""
    return args.binaries or [CLRT]
