"""Two-sided tail probabilities of Student's t distribution, with numpy alone (the Mitsuba venv
has no scipy): P(|T| > t) for nu degrees of freedom is the regularised incomplete beta function
I_x(nu / 2, 1 / 2) at x = nu / (nu + t^2), evaluated by its continued fraction."""
import math

import numpy as np

_lgamma = np.vectorize(math.lgamma, otypes=[float])
TINY = 1e-300


def _continued_fraction(a, b, x, terms=300):
    """The continued fraction of I_x(a, b) (modified Lentz), which converges fast for
    x < (a + 1) / (a + b + 2)."""
    c = np.ones_like(x)
    d = 1.0 - (a + b) * x / (a + 1.0)
    d = 1.0 / np.where(np.abs(d) < TINY, TINY, d)
    h = d.copy()
    for m in range(1, terms + 1):
        for numerator in (m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m)),
                          -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1))):
            d = 1.0 + numerator * d
            d = 1.0 / np.where(np.abs(d) < TINY, TINY, d)
            c = 1.0 + numerator / np.where(np.abs(c) < TINY, TINY, c)
            h = h * d * c
    return h


def incomplete_beta(a, b, x):
    """The regularised incomplete beta function I_x(a, b), elementwise, for x in [0, 1]."""
    a, b, x = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (a, b, x)))
    inner = np.clip(x, TINY, 1.0 - 1e-16)
    log_front = _lgamma(a + b) - _lgamma(a) - _lgamma(b) + a * np.log(inner) + b * np.log1p(-inner)
    direct = x < (a + 1.0) / (a + b + 2.0)
    # Where the fraction converges slowly, I_x(a, b) = 1 - I_{1-x}(b, a).
    aa, bb, xx = np.where(direct, a, b), np.where(direct, b, a), np.where(direct, inner, 1.0 - inner)
    value = np.exp(log_front) * _continued_fraction(aa, bb, xx) / aa
    result = np.where(direct, value, 1.0 - value)
    return np.where(x <= 0, 0.0, np.where(x >= 1, 1.0, result))


def two_sided_p(t, nu):
    """P(|T| >= |t|) for T with nu degrees of freedom (nu > 0, not necessarily whole)."""
    t, nu = np.broadcast_arrays(np.asarray(t, dtype=float), np.asarray(nu, dtype=float))
    return incomplete_beta(nu / 2.0, 0.5, nu / (nu + t * t))
