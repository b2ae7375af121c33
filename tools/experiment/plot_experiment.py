#!/usr/bin/python3
"""Plots of a clrt-experiment run: python3 plot_experiment.py RESULTS.json OUT_DIR

Every plot shows medians over the repeats with their spread (min-max) as error bars, its axes
start at 0, and its title names the resolution, samples per pixel and devices.

mrays.png      Mrays/s per scene, one bar per device and variant; bars of short renders (their
               Mrays/s measure start-up as much as tracing) are hatched and faded
kernels.png    each kernel's share of the device's busy time, per device and variant (all scenes)
wavefront.png  Mrays/s against the wavefront size, when the experiment swept it
local-size.png Mrays/s against the local size, when the experiment swept it
"""
import json
import os
import sys
import textwrap
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
from matplotlib.transforms import offset_copy  # noqa: E402


def label(entry):
    return f"{entry['device_spec']} {entry['variant']}"


def scene_name(entry):
    return os.path.basename(entry["scene"])


def spread_bars(entries, key):
    """Matplotlib's yerr: how far below and above each median its repeats went."""
    low = [s[key] - s["spread"][key][0] for s in entries]
    high = [s["spread"][key][1] - s[key] for s in entries]
    return [low, high]


def titled(ax, what, title):
    """The plot's subject over the experiment's title, wrapped so that neither is cut off."""
    ax.set_title(f"{what}\n" + textwrap.fill(title, 70), fontsize="medium")


def colour(n):
    """A colour of its own for each of the first 20 series; past 20 they repeat, hatched."""
    colours = plt.get_cmap("tab20").colors
    return colours[n % len(colours)]


def legend_beside(ax, handles=None):
    """The legend right of the axes, never over the data, and right of the last x tick label too,
    which overhangs the axes' edge by half its width. The overhang is in points, so the legend
    stays clear of it however the layout later sizes the axes."""
    fig = ax.figure
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    right = max([t.get_window_extent(renderer).x1 for t in ax.get_xticklabels() if t.get_text()]
                + [ax.bbox.x1])
    overhang = (right - ax.bbox.x1) * 72.0 / fig.dpi
    anchor = offset_copy(ax.transAxes, fig=fig, x=overhang + 6, y=0, units="points")
    kwargs = {"handles": handles} if handles else {}
    ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.0, 1.0),
              bbox_transform=anchor, **kwargs)


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110, bbox_inches="tight")
    plt.close(fig)


def mrays_figure(summary, title):
    scenes = list(dict.fromkeys(scene_name(s) for s in summary))
    configs = list(dict.fromkeys(label(s) for s in summary))
    entry = {(scene_name(s), label(s)): s for s in summary}
    width = 0.8 / len(configs)
    fig, ax = plt.subplots(figsize=(min(16, max(6, 0.35 * len(scenes) * len(configs))), 5))
    for k, config in enumerate(configs):
        present = [i for i, sc in enumerate(scenes) if (sc, config) in entry]
        bars = [entry[(scenes[i], config)] for i in present]
        drawn = ax.bar([i + k * width for i in present], [s["mrays_per_second"] for s in bars],
                       width, yerr=spread_bars(bars, "mrays_per_second"), capsize=3, label=config,
                       color=colour(k), hatch="//" if k >= 20 else None)
        for bar, s in zip(drawn, bars):
            if s.get("short", 0) > 0:
                bar.set_hatch("xx")
                bar.set_alpha(0.45)
    ax.set_xticks([i + 0.4 - width / 2 for i in range(len(scenes))])
    ax.set_xticklabels(scenes, rotation=45, ha="right", fontsize="small")
    ax.set_ylim(bottom=0)
    ax.set_ylabel("Mrays/s (all ray kinds, render time)")
    titled(ax, "Throughput per scene, device and variant", title)
    # Swatches of their own: a series' first bar may be a short one, hatched and faded.
    handles = [Patch(facecolor=colour(k), hatch="//" if k >= 20 else None, label=config)
               for k, config in enumerate(configs)]
    if any(s.get("short", 0) > 0 for s in summary):
        handles.append(Patch(facecolor="lightgrey", hatch="xx", alpha=0.45,
                             label="short render: start-up as much as tracing"))
    legend_beside(ax, handles)
    return fig


def kernels_figure(summary, title):
    seconds = defaultdict(lambda: defaultdict(float))
    for s in summary:
        for kernel, t in s["kernels"].items():
            seconds[label(s)][kernel] += t
    configs = list(seconds)
    kernels = sorted({k for c in configs for k in seconds[c]},
                     key=lambda k: -sum(seconds[c][k] for c in configs))
    fig, ax = plt.subplots(figsize=(9, 2.2 + 0.5 * len(configs)))
    left = [0.0] * len(configs)
    for n, kernel in enumerate(kernels):
        shares = []
        for c in configs:
            total = sum(seconds[c].values()) or 1.0
            shares.append(100.0 * seconds[c][kernel] / total)
        ax.barh(configs, shares, left=left, label=kernel, color=colour(n),
                hatch="//" if n >= 20 else None)
        left = [a + b for a, b in zip(left, shares)]
    ax.set_xlim(0, 100)
    ax.set_xlabel("% of the device's busy time (medians, summed over scenes)")
    titled(ax, "Where the device time goes", title)
    legend_beside(ax)
    return fig


def plot_sweep(summary, out, key, axis_label, what, title, name):
    """Mrays/s against one setting, when the experiment swept it: only the lines (scene, device,
    integrator) that ran at two values of it or more. Devices whose defaults merely differ (PoCL's
    local size against Intel's) swept nothing, and draw nothing."""
    lines = defaultdict(list)
    for s in summary:
        if s.get(key):
            line = f"{scene_name(s)}, {s['device_spec']}, {s.get('integrator', '')}"
            lines[line].append((s[key], s))
    lines = {line: points for line, points in lines.items() if len({p[0] for p in points}) > 1}
    if not lines:
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for n, (line, points) in enumerate(lines.items()):
        points.sort(key=lambda p: p[0])
        ax.errorbar([p[0] for p in points], [p[1]["mrays_per_second"] for p in points],
                    yerr=spread_bars([p[1] for p in points], "mrays_per_second"), marker="o",
                    capsize=3, label=line, color=colour(n), linestyle="-" if n < 20 else "--")
    # A power-of-two axis cannot reach 0; it starts at half the smallest size swept.
    ax.set_xscale("log", base=2)
    ax.set_xlim(left=min(p[0] for points in lines.values() for p in points) / 2)
    ax.set_ylim(bottom=0)
    ax.set_xlabel(axis_label)
    ax.set_ylabel("Mrays/s")
    titled(ax, what, title)
    legend_beside(ax)
    save(fig, out, name)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        results = json.load(f)
    summary = [s for s in results["summary"] if s["runs"] > s["failed"]]
    if not summary:
        sys.exit("plot_experiment.py: no successful run to plot")
    title = results["title"]
    save(mrays_figure(summary, title), sys.argv[2], "mrays.png")
    save(kernels_figure(summary, title), sys.argv[2], "kernels.png")
    plot_sweep(summary, sys.argv[2], "wavefront", "wavefront (rays per queue)",
               "Wavefront size sweep", title, "wavefront.png")
    plot_sweep(summary, sys.argv[2], "local_size", "local size (work-items per work-group)",
               "Local size sweep", title, "local-size.png")


if __name__ == "__main__":
    main()
