#!/usr/bin/env python3
"""compare.py CLRT.exr MITSUBA.exr [--mean-tolerance 0.01] [--pixel-alpha 0.002] [--pixel-pass 0.99]
    [--discovery-level 0.05] [--sigmas 4] [--block 8] [--scale F]

Tells whether two Monte Carlo estimates of one image (estimates.py: each pixel's mean over
independent sub-renders, and that mean's variance) agree: exit 0 when they do, 1 when they
differ, 2 when they cannot be compared. Four checks, on the difference D = A - B
(docs/path-tracing.md, "Checked against Mitsuba 3"):

- the mean of each channel over the image: |mean A - mean B| <= tolerance x mean B;
- per pixel and channel, Welch's t = D / sqrt(var A + var B), with the Welch-Satterthwaite
  degrees of freedom; a pixel's p-value is the smallest of its channels' two-sided p-values
  times 3 (Bonferroni over the channels). At least the fraction pixel-pass of the noisy pixels
  must have p >= pixel-alpha, and every pixel without noise must agree to float rounding;
- the share of noisy pixels with p < discovery-level: without bias at most the level itself (the
  channel correction is conservative); more than sigmas binomial standard deviations above it
  says that a bias too small to fail single pixels is spread over many;
- per block of b x b pixels and channel, Z = sum(D) / sqrt(sum(D^2)): the mean of Z^2 over the
  noisy blocks, about 1 (at most) without bias, may lie at most sigmas of its standard
  deviations, sqrt(2 / blocks), above 1.

Run it with the python of the venv tools/mitsuba/install.sh makes (it reads EXR with Mitsuba).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import estimates  # noqa: E402
import student_t  # noqa: E402

# Pixels without noise (the sky seen directly) still differ by float rounding, always the same
# way; a difference this small, relative to the pixel, counts as no difference.
ROUNDING = 1e-4


def rounding_floor(a, b):
    return (ROUNDING * np.maximum(np.abs(a), np.abs(b))) ** 2


def pixel_p_values(a, b):
    """Each pixel's p-value (Welch's t per channel, Bonferroni over the channels) and whether
    it has any noise. A pixel without noise gets p 1 when A and B agree to rounding, else 0."""
    (mean_a, var_a, k_a), (mean_b, var_b, k_b) = a, b
    diff, var = mean_a - mean_b, var_a + var_b
    floor = rounding_floor(mean_a, mean_b)
    # Welch-Satterthwaite: the sum of two variance estimates of k - 1 degrees of freedom each.
    spread = var_a ** 2 / (k_a - 1) + var_b ** 2 / (k_b - 1)
    nu = np.divide(var ** 2, spread, out=np.full_like(var, 1e6), where=spread > 0)
    t = diff / np.sqrt(var + floor + 1e-300)
    p = np.where(var > 0, student_t.two_sided_p(t, np.maximum(nu, 1.0)), (diff ** 2 <= floor).astype(float))
    channels = p.shape[2]
    return np.minimum(1.0, channels * p.min(axis=2)), (var > 0).any(axis=2)


def block_z(a, b, size):
    """Z of each size x size block and channel, and whether the block has any noise at all."""
    h, w = (a.shape[0] // size) * size, (a.shape[1] // size) * size

    def blocks(image):
        return image[:h, :w].reshape(h // size, size, w // size, size, -1)

    diff = blocks(a - b)
    floor = rounding_floor(blocks(a), blocks(b))
    s, q = diff.sum(axis=(1, 3)), (diff ** 2 + floor).sum(axis=(1, 3))
    noisy = (diff ** 2 > floor).any(axis=(1, 3))
    # A block where both images agree exactly (black sky on both sides) has nothing to test.
    return np.divide(s, np.sqrt(q), out=np.zeros_like(s), where=q > 0), noisy


def verdict(good):
    return "ok  " if good else "FAIL"


def check_means(a, b, tolerance):
    (mean_a, var_a, _), (mean_b, var_b, _) = a, b
    pixels = mean_a.shape[0] * mean_a.shape[1]
    ok = True
    for c, name in enumerate("RGB"):
        ma, mb = mean_a[..., c].mean(), mean_b[..., c].mean()
        stderr = np.sqrt((var_a[..., c] + var_b[..., c]).sum()) / pixels
        norm = abs(mb) if mb != 0 else 1.0
        relative = (ma - mb) / norm
        good = abs(relative) <= tolerance
        ok &= good
        print(f"{verdict(good)} {name}: mean {ma:.6g} vs {mb:.6g}, relative difference {relative:+.4%} "
              f"(noise {stderr / norm:.4%}, tolerance {tolerance:.2%}), Z {(ma - mb) / stderr if stderr > 0 else 0:+.2f}")
        if stderr / norm > tolerance / 3:
            print("     note: the noise is too large to resolve the tolerance; render more samples")
    return ok


def check_pixels(a, b, args):
    p, noisy = pixel_p_values(a, b)
    quiet_bad = np.count_nonzero(~noisy & (p < 1))
    n = np.count_nonzero(noisy)
    passing = np.mean(p[noisy] >= args.pixel_alpha) if n else 1.0
    good = passing >= args.pixel_pass and quiet_bad == 0
    worst = np.unravel_index(np.argmin(np.where(noisy, p, 1.0)), p.shape)
    print(f"{verdict(good)} pixels: {passing:.2%} of the {n} noisy pixels have p >= {args.pixel_alpha:g} "
          f"(need {args.pixel_pass:.2%}); smallest p {p[worst]:.2g} at x {worst[1]}, y {worst[0]}; "
          f"{quiet_bad} of {p.size - n} pixels without noise differ")
    share = np.mean(p[noisy] < args.discovery_level) if n else 0.0
    limit = args.discovery_level + args.sigmas * np.sqrt(args.discovery_level * (1 - args.discovery_level) / max(n, 1))
    enough = share <= limit
    print(f"{verdict(enough)} discoveries: {share:.2%} of the noisy pixels have p < {args.discovery_level:g} "
          f"(at most {limit:.2%})")
    return good and enough


def check_blocks(a, b, args):
    # Z^2 averages to about 1 over blocks when both renders are unbiased (less where a block's
    # samples are skewed), with a spread of about sqrt(2 / blocks); biases too small to push one
    # block far, but spread over many, raise it.
    z, noisy = block_z(a[0], b[0], args.block)
    count = np.count_nonzero(noisy)
    mean_z2 = np.mean(z[noisy] ** 2) if count else 0.0
    z2_max = 1.0 + args.sigmas * np.sqrt(2.0 / max(count, 1))
    good = mean_z2 <= z2_max
    print(f"{verdict(good)} mean Z^2 over the {count} noisy {args.block}x{args.block} blocks "
          f"x channel: {mean_z2:.3f} (at most {z2_max:.3f})")
    return good


def unusable(message):
    print(f"compare.py: error: {message}", file=sys.stderr)
    return 2


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("a", help="the estimate under test (clrt)")
    parser.add_argument("b", help="the reference estimate (Mitsuba)")
    parser.add_argument("--mean-tolerance", type=float, default=0.01,
                        help="largest relative difference of a channel's mean (default 0.01)")
    parser.add_argument("--pixel-alpha", type=float, default=0.002,
                        help="the p-value below which a pixel fails (default 0.002)")
    parser.add_argument("--pixel-pass", type=float, default=0.99,
                        help="smallest fraction of the noisy pixels that must pass (default 0.99)")
    parser.add_argument("--discovery-level", type=float, default=0.05,
                        help="the p-value counted as a discovery (default 0.05)")
    parser.add_argument("--sigmas", type=float, default=4.0,
                        help="how many standard deviations the discoveries and the mean Z^2 of the blocks "
                             "may lie above their expectations without bias (default 4)")
    parser.add_argument("--block", type=int, default=8, help="block side in pixels (default 8)")
    parser.add_argument("--scale", type=float, default=1.0,
                        help="multiply the reference by this first: with 1.03, a pass says that an error "
                             "of 3%% would go unseen at these sample counts")
    args = parser.parse_args()

    try:
        a, (mean_b, var_b, k_b) = estimates.read(args.a), estimates.read(args.b)
    except (RuntimeError, ValueError) as e:
        return unusable(e)
    b = (args.scale * mean_b, args.scale ** 2 * var_b, k_b)
    if a[0].shape != b[0].shape:
        return unusable(f"{args.a} is {a[0].shape[1]}x{a[0].shape[0]}, {args.b} is {b[0].shape[1]}x{b[0].shape[0]}")
    if a[0].shape[0] < args.block or a[0].shape[1] < args.block:
        return unusable(f"the images are smaller than one {args.block}x{args.block} block")
    for name, (mean, var, _) in ((args.a, a), (args.b, b)):
        bad = np.count_nonzero(~np.isfinite(mean) | ~np.isfinite(var))
        if bad:
            print(f"FAIL {name}: {bad} values are NaN or infinite")
            return 1
    ok = check_means(a, b, args.mean_tolerance)
    ok &= check_pixels(a, b, args)
    ok &= check_blocks(a, b, args)
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
