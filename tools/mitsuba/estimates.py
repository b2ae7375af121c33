#!/usr/bin/env python3
"""estimates.py OUT.exr SUB.exr... : a pixel estimate and its noise from independent sub-renders.

Both renderers render a scene as K sub-renders with different seeds; each pixel's mean over them
is the image, and their spread estimates that mean's variance (the sample variance over K,
divided by K), which the per-pixel Z-test of compare.py needs. Within a sub-render the samples
need not be independent (clrt stratifies them): only the sub-renders must be. An estimate is
one EXR: the mean as R, G, B and its variance as var.R, var.G, var.B, with the count of
sub-renders in the channel `splits`. Run with the python of the venv tools/mitsuba/install.sh
makes (EXR goes through Mitsuba).
"""
import sys

import numpy as np

CHANNELS = ["R", "G", "B", "var.R", "var.G", "var.B", "splits"]


def combine(images):
    """Mean, variance of the mean and count of K >= 2 sub-renders, each H x W x 3."""
    stack = np.stack([np.asarray(i, dtype=np.float64) for i in images])
    k = stack.shape[0]
    if k < 2:
        raise ValueError("a variance needs two sub-renders or more")
    return stack.mean(axis=0), stack.var(axis=0, ddof=1) / k, k


def read_rgb(path):
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    bitmap = mi.Bitmap(path).convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.Float32, False)
    return np.array(bitmap, dtype=np.float64)


def write(path, mean, variance, splits):
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    planes = np.concatenate([mean, variance, np.full(mean.shape[:2] + (1,), float(splits))], axis=2)
    mi.Bitmap(planes.astype(np.float32), mi.Bitmap.PixelFormat.MultiChannel, CHANNELS).write(path)


def read(path):
    """(mean, variance of the mean, sub-render count) of an estimate written by write()."""
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    bitmap = mi.Bitmap(path)
    names = [bitmap.struct_()[i].name for i in range(bitmap.channel_count())]
    if sorted(names) != sorted(CHANNELS):
        raise ValueError(f"{path} is not an estimate (channels {', '.join(names)})")
    data = np.array(bitmap, dtype=np.float64).reshape(bitmap.height(), bitmap.width(), -1)
    planes = {name: data[..., i] for i, name in enumerate(names)}
    mean = np.stack([planes[c] for c in CHANNELS[:3]], axis=2)
    variance = np.stack([planes[c] for c in CHANNELS[3:6]], axis=2)
    return mean, variance, int(planes["splits"].flat[0])


def main():
    if len(sys.argv) < 4:
        sys.exit("usage: estimates.py OUT.exr SUB.exr SUB.exr...")
    write(sys.argv[1], *combine([read_rgb(p) for p in sys.argv[2:]]))


if __name__ == "__main__":
    main()
