#!/usr/bin/env python3
"""Plots clrt-bench bvh --suite output: Mrays/s against scene size, log scale.

Usage: clrt-bench bvh --suite > suite.md; python3 plot_scaling.py suite.md scaling.png
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


def mrays(cell):
    return float(cell.split()[0])


def series(rows, pattern, size_key):
    points = []
    for name, row in rows:
        if re.search(pattern, name):
            points.append((float(row[size_key]), {c: mrays(row[c]) for c in COLUMNS}))
    return sorted(points)


def main(source, target):
    rows = list(read_rows(source))
    panels = [
        ("one mesh: triangles", series(rows, r"^mesh \S+ tris$", "triangles")),
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
    main(sys.argv[1], sys.argv[2])
