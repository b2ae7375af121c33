#!/usr/bin/env python3
"""compare.py CLRT.exr MITSUBA.exr [--mean-tolerance 0.01] [--z-pass 0.99] [--z-max 3] [--block 4]
    [--z2-sigmas 4] [--scale F]

Tells whether two Monte Carlo renders of one scene estimate the same image: exit 0 when they do,
1 when they differ, 2 when the images cannot be compared. Three checks, all on the difference
image D = A - B (docs/path-tracing.md, "Checked against Mitsuba 3"):

- the mean of each channel over the image: |mean A - mean B| <= tolerance x mean B;
- per block of b x b pixels and channel, Z = sum(D) / sqrt(sum(D^2)). When both renders are
  unbiased, every D has expectation 0, whatever the image shows (edges, shadows), and sum(D^2)
  is an unbiased estimate of the variance of sum(D), because the pixels' samples are
  independent; so Z needs no second render and ignores fireflies (one huge D gives |Z| near 1).
  At least the fraction z-pass of the blocks must have |Z| <= z-max;
- the mean of Z^2 over blocks twice as wide, about 1 (at most) without bias: no more than
  z2-sigmas of its standard deviations above 1.

Run it with the python of the venv tools/mitsuba/install.sh makes (it reads EXR with Mitsuba).
"""
import argparse
import sys

import numpy as np


def read_exr(path):
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    try:
        bitmap = mi.Bitmap(path)
    except RuntimeError as e:
        sys.exit(f"compare.py: error: cannot read {path}: {e}")
    image = np.array(bitmap.convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.Float32, False), dtype=np.float64)
    return image.reshape(image.shape[0], image.shape[1], -1)


# Pixels without noise (the sky seen directly) still differ by float rounding, always the same
# way; a difference this small, relative to the pixel, counts as no difference.
ROUNDING = 1e-4


def block_z(a, b, size):
    """Z of each size x size block and channel, and whether the block has any noise at all."""
    h, w = (a.shape[0] // size) * size, (a.shape[1] // size) * size

    def blocks(image):
        return image[:h, :w].reshape(h // size, size, w // size, size, -1)

    diff = blocks(a - b)
    floor = (ROUNDING * np.maximum(np.abs(blocks(a)), np.abs(blocks(b)))) ** 2
    s, q = diff.sum(axis=(1, 3)), (diff ** 2 + floor).sum(axis=(1, 3))
    noisy = (diff ** 2 > floor).any(axis=(1, 3))
    # A block where both images agree exactly (black sky on both sides) has nothing to test.
    return np.divide(s, np.sqrt(q), out=np.zeros_like(s), where=q > 0), noisy


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("a", help="the image under test (clrt)")
    parser.add_argument("b", help="the reference (Mitsuba)")
    parser.add_argument("--mean-tolerance", type=float, default=0.01,
                        help="largest relative difference of a channel's mean (default 0.01)")
    parser.add_argument("--z-pass", type=float, default=0.99,
                        help="smallest fraction of blocks with |Z| <= z-max (default 0.99)")
    parser.add_argument("--z-max", type=float, default=3.0, help="the largest |Z| a block may have (default 3)")
    parser.add_argument("--block", type=int, default=4, help="block side in pixels (default 4)")
    parser.add_argument("--z2-sigmas", type=float, default=4.0,
                        help="how far the mean of Z^2 over blocks twice as wide may lie above 1, "
                             "in its standard deviations, sqrt(2 / blocks) (default 4)")
    parser.add_argument("--scale", type=float, default=1.0,
                        help="multiply the reference by this first: with 1.03, a pass says that an error "
                             "of 3%% would go unseen at these sample counts")
    args = parser.parse_args()

    a, b = read_exr(args.a), args.scale * read_exr(args.b)
    if a.shape != b.shape:
        sys.exit(f"compare.py: error: {args.a} is {a.shape[1]}x{a.shape[0]}x{a.shape[2]}, "
                 f"{args.b} is {b.shape[1]}x{b.shape[0]}x{b.shape[2]}")
    if a.shape[0] < args.block or a.shape[1] < args.block:
        sys.exit(f"compare.py: error: the images are smaller than one {args.block}x{args.block} block")
    ok = True
    for name, image in ((args.a, a), (args.b, b)):
        if not np.isfinite(image).all():
            print(f"FAIL {name}: {np.count_nonzero(~np.isfinite(image))} values are NaN or infinite")
            ok = False
    if not ok:
        return 1

    diff = a - b
    pixels = diff.shape[0] * diff.shape[1]
    names = "RGBA"[:diff.shape[2]] if diff.shape[2] <= 4 else [str(c) for c in range(diff.shape[2])]
    for c, name in enumerate(names):
        mean_a, mean_b = a[..., c].mean(), b[..., c].mean()
        d = diff[..., c]
        # The standard error of the mean difference, from the same unbiased variance estimate.
        stderr = np.sqrt((d ** 2).sum()) / pixels
        norm = abs(mean_b) if mean_b != 0 else 1.0
        relative = (mean_a - mean_b) / norm
        good = abs(relative) <= args.mean_tolerance
        ok &= good
        print(f"{'ok  ' if good else 'FAIL'} {name}: mean {mean_a:.6g} vs {mean_b:.6g}, "
              f"relative difference {relative:+.4%} (noise {stderr / norm:.4%}, tolerance {args.mean_tolerance:.2%}), "
              f"Z {(mean_a - mean_b) / stderr if stderr > 0 else 0:+.2f}")
        if stderr / norm > args.mean_tolerance / 3:
            print(f"     note: the noise is too large to resolve the tolerance; render more samples")

    z, _ = block_z(a, b, args.block)
    passing = np.mean(np.abs(z) <= args.z_max)
    good = passing >= args.z_pass
    ok &= good
    worst = np.unravel_index(np.argmax(np.abs(z)), z.shape)
    print(f"{'ok  ' if good else 'FAIL'} blocks: {passing:.2%} of {z.size} ({args.block}x{args.block} pixels x channel) "
          f"have |Z| <= {args.z_max:g} (need {args.z_pass:.2%}); largest |Z| {abs(z[worst]):.2f} "
          f"at pixels x {worst[1] * args.block}, y {worst[0] * args.block}, channel {names[worst[2]]}")

    # Z^2 averages to about 1 over blocks when both renders are unbiased (less where a block's
    # samples are skewed), with a spread of about sqrt(2 / blocks); biases too small to push one
    # block past z-max, but spread over many, raise it. Larger blocks see small biases better.
    size = 2 * args.block
    z, noisy = block_z(a, b, size)
    count = np.count_nonzero(noisy)
    mean_z2 = np.mean(z[noisy] ** 2) if count else 0.0
    z2_max = 1.0 + args.z2_sigmas * np.sqrt(2.0 / max(count, 1))
    good = mean_z2 <= z2_max
    ok &= good
    print(f"{'ok  ' if good else 'FAIL'} mean Z^2 over the {count} noisy {size}x{size} blocks "
          f"x channel: {mean_z2:.3f} (at most {z2_max:.3f})")
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
