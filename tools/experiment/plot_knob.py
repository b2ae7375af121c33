#!/usr/bin/python3
"""The material knob's plot and table: python3 plot_knob.py RUNS.csv OUT.png

RUNS.csv is the runs.csv of a clrt-experiment run over the knob scenes of clrt-make-scenes
--family knob (knob-01.ray ... knob-16.ray) or --family texture-knob (texture-knob-1.ray ...
texture-knob-8.ray), with the integrators wavefront and megakernel and
the variants queue and by-class. Draws, per device, Mrays/s and Msamples/s against the number of
materials (medians over repeats, bars from the slowest to the fastest run) and prints a Markdown
table of the medians with the point from which the wavefront stays ahead of the megakernel. The
megakernel ignores the shading order, so its two variants are pooled as repeats of one.
"""
import csv
import os
import re
import statistics
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LINES = [("wavefront queue", "wavefront, queue order"),
         ("wavefront by-class", "wavefront, by class"),
         ("megakernel", "megakernel")]
MEASURES = [("mrays_per_s", "Mrays/s"), ("msamples_per_s", "Msamples/s")]


def line_of(variant):
    return "megakernel" if variant.startswith("megakernel") else variant


def read_runs(path):
    """{(device, line, k, measure): [values]}, the devices in their order of appearance."""
    values = defaultdict(list)
    devices = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            match = re.match(r"(?:texture-)?knob-(\d+)\.ray$", os.path.basename(row["scene"]))
            if not match or row["exit_code"] != "0" or row["flagged"] == "true":
                continue
            if row["device"] not in devices:
                devices.append(row["device"])
            for measure, _ in MEASURES:
                values[(row["device"], line_of(row["variant"]), int(match.group(1)), measure)].append(
                    float(row[measure]))
    return values, devices


def median(values, key):
    return statistics.median(values[key]) if values.get(key) else None


def overtakes_at(values, device, measure, ks):
    """The smallest k from which the wavefront's median beats the megakernel's at every k."""
    ahead = [median(values, (device, "wavefront queue", k, measure)) >
             median(values, (device, "megakernel", k, measure)) for k in ks]
    for i in range(len(ks)):
        if all(ahead[i:]):
            return ks[i]
    return None


def plot(values, devices, ks, out):
    fig, axes = plt.subplots(len(MEASURES), len(devices), figsize=(5.5 * len(devices), 7),
                             squeeze=False)
    for col, device in enumerate(devices):
        for row, (measure, unit) in enumerate(MEASURES):
            ax = axes[row][col]
            for line, name in LINES:
                keys = [(device, line, k, measure) for k in ks if values.get((device, line, k, measure))]
                xs = [key[2] for key in keys]
                mids = [statistics.median(values[key]) for key in keys]
                low = [m - min(values[key]) for m, key in zip(mids, keys)]
                high = [max(values[key]) - m for m, key in zip(mids, keys)]
                ax.errorbar(xs, mids, yerr=[low, high], marker="o", capsize=2, label=name)
            ax.set_xticks(ks)
            ax.set_xlabel("materials in the scene (lobe subsets, cheapest first)")
            ax.set_ylabel(unit)
            ax.set_ylim(bottom=0)
            ax.set_title(device, fontsize="small")
            ax.legend(fontsize="small")
    fig.suptitle("The material knob: path mode, medians with the slowest and fastest run")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def table(values, devices, ks):
    head = ["k"] + [f"{device}: {name}" for device in devices for _, name in LINES]
    print("| " + " | ".join(head) + " |")
    print("|" + "---:|" * len(head))
    for k in ks:
        cells = [str(k)]
        for device in devices:
            for line, _ in LINES:
                m = median(values, (device, line, k, "mrays_per_s"))
                cells.append("" if m is None else f"{m:.2f}")
        print("| " + " | ".join(cells) + " |")
    for device in devices:
        k = overtakes_at(values, device, "mrays_per_s", ks)
        print(f"\n{device}: the wavefront (queue order) is ahead of the megakernel "
              + (f"from k = {k} on" if k is not None else "at no k to the end"))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    values, devices = read_runs(sys.argv[1])
    ks = sorted({key[2] for key in values})
    if not ks:
        sys.exit("plot_knob.py: no successful run of a knob scene")
    plot(values, devices, ks, sys.argv[2])
    table(values, devices, ks)


if __name__ == "__main__":
    main()
