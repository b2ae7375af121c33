"""The arithmetic of the race (race.py), in plain Python so that test_metrics.py runs without
bpy or numpy: error, efficiency and the medians of timed runs.

Monte Carlo noise falls as RMSE ~ 1/sqrt(spp) while time grows as spp, so RMSE^2 x time is,
for one renderer on one scene, about the same at any sample count: efficiency = 1 / (RMSE^2
time) (the "efficiency" of Veach's thesis, section 2.4, and of pbrt). Two renderers' ratio of
efficiencies is then how many times faster one reaches any given quality than the other.
"""
import math
import statistics


def mse(values, reference):
    """Mean squared difference of two equally long sequences of numbers (pixel channels)."""
    values, reference = list(values), list(reference)
    if len(values) != len(reference):
        raise ValueError(f"{len(values)} values against {len(reference)} reference values")
    if not values:
        raise ValueError("no values")
    return math.fsum((a - b) * (a - b) for a, b in zip(values, reference)) / len(values)


def rmse(values, reference):
    """Root mean squared difference, per pixel channel."""
    return math.sqrt(mse(values, reference))


def noise_rmse(renders):
    """The noise of one render, per pixel channel, from several independent renders of the same
    image (seeds): the difference of two has twice a render's variance, so the root of half
    their mean squared difference, over every pair. Unlike the error against a reference, it
    holds none of the reference's own noise."""
    renders = [list(r) for r in renders]
    if len(renders) < 2:
        raise ValueError("the noise needs two renders or more")
    pairs = [(a, b) for i, a in enumerate(renders) for b in renders[i + 1:]]
    return math.sqrt(math.fsum(mse(a, b) for a, b in pairs) / len(pairs) / 2)


def pooled_rmse(errors):
    """One RMSE for several independent renders (seeds): the root of their mean MSE."""
    errors = list(errors)
    if not errors:
        raise ValueError("no errors")
    return math.sqrt(math.fsum(e * e for e in errors) / len(errors))


def efficiency(error, seconds):
    """1 / (RMSE^2 x time): how much quality a second buys, independent of the sample count
    while RMSE falls as 1/sqrt(spp)."""
    if error <= 0 or seconds <= 0:
        raise ValueError(f"efficiency needs a positive error and time, got {error} and {seconds}")
    return 1.0 / (error * error * seconds)


def speedup(error_a, seconds_a, error_b, seconds_b):
    """How many times sooner A reaches B's quality (or any quality) than B does: the ratio of
    efficiencies. Above 1: A is faster at equal quality."""
    return efficiency(error_a, seconds_a) / efficiency(error_b, seconds_b)


def median(values):
    values = list(values)
    if not values:
        raise ValueError("no values")
    return statistics.median(values)


def relative_differences(means_a, means_b):
    """Per channel, (a - b) / b: how far A's image mean lies from B's."""
    out = []
    for a, b in zip(means_a, means_b):
        if b == 0:
            out.append(0.0 if a == 0 else math.inf)
        else:
            out.append((a - b) / b)
    return out


def means_agree(means_a, means_b, tolerance):
    """Whether every channel's image means differ by at most `tolerance` of B's."""
    return all(abs(d) <= tolerance for d in relative_differences(means_a, means_b))
