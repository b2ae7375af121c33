#!/usr/bin/env python3
"""Plots clrt-bench bvh --suite output: Mrays/s against scene size, log scale, and (with a
third argument) the single meshes' build rate and SAH cost against their size.

Usage: clrt-bench bvh --suite > suite.md; python3 plot_scaling.py suite.md scaling.png [build.png]
Needs matplotlib (Debian: python3-matplotlib); a documentation tool, not part of the build.
"""
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLUMNS = ["closest camera", "closest random", "any camera", "any random"]


def read_rows(path):
    """Yields (scene name, {column: value}) for every table row of the benchmark output."""
    header = None
    for line in open(path):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("| scene"):
            header = cells
        elif header and line.startswith("| ") and not line.startswith("|---"):
            yield cells[0], dict(zip(header, cells))


def leading_number(cell):
    """A cell's first number: "21.3 (10.7)" (Mrays/s elapsed, per CPU-second) gives 21.3."""
    return float(cell.split()[0])


def series(rows, pattern, size_key, columns=COLUMNS):
    points = []
    for name, row in rows:
        if re.search(pattern, name):
            points.append((float(row[size_key]), {c: leading_number(row[c]) for c in columns}))
    return sorted(points)


MESHES = r"^mesh \S+ tris$"


def plot_build(rows, target):
    """Build rate and SAH cost of the single meshes: a faster build that made a worse tree would
    show as a rising cost (and as falling Mrays/s in the other figure)."""
    points = series(rows, MESHES, "triangles", ["build Mtris/s", "SAH cost"])
    sizes = [p[0] for p in points]
    fig, rate = plt.subplots(figsize=(6, 4))
    rate.plot(sizes, [p[1]["build Mtris/s"] for p in points], marker="o", color="tab:blue")
    rate.set_xscale("log")
    rate.set_xlabel("one mesh: triangles")
    rate.set_ylabel("BVH build, M triangles/s (2 cores)", color="tab:blue")
    rate.set_ylim(bottom=0)
    rate.grid(True, which="both", alpha=0.3)
    cost = rate.twinx()
    cost.plot(sizes, [p[1]["SAH cost"] for p in points], marker="s", color="tab:red")
    cost.set_ylabel("SAH cost of the tree (packet tests)", color="tab:red")
    cost.set_ylim(bottom=0)
    fig.suptitle("clrt BVH build: rate and tree quality against mesh size")
    fig.tight_layout()
    fig.savefig(target, dpi=90)


def main(source, target, build_target=None):
    rows = list(read_rows(source))
    if build_target:
        plot_build(rows, build_target)
    panels = [
        ("one mesh: triangles", series(rows, MESHES, "triangles")),
        ("instances of a 1k-triangle mesh", series(rows, r"x 1k-tri mesh$", "instances")),
        ("canonical shapes: instances", series(rows, r"shapes$", "instances")),
    ]
    panels = [p for p in panels if p[1]]
    fig, axes = plt.subplots(1, len(panels), figsize=(5 * len(panels), 4), squeeze=False)
    for ax, (title, points) in zip(axes[0], panels):
        sizes = [p[0] for p in points]
        for column in COLUMNS:
            ax.plot(sizes, [p[1][column] for p in points], marker="o", label=column)
        ax.set_xscale("log")
        ax.set_xlabel(title)
        ax.set_ylabel("Mrays/s (PoCL, 2 cores)")
        ax.set_ylim(bottom=0)
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].legend()
    fig.suptitle("clrt BVH traversal: throughput against scene size")
    fig.tight_layout()
    fig.savefig(target, dpi=90)


if __name__ == "__main__":
    main(*sys.argv[1:4])
