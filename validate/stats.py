"""The statistics of the comparison: two renderers, two seeds each, one verdict.

Model. Each renderer gives two independent images of the same scene at the same spp (seeds
fixed). For renderer X with seed images x1, x2, the estimate is X = (x1 + x2)/2, and
v_X = (x1 - x2)^2 / 4 is an unbiased estimate of Var(X) per pixel and channel (one degree
of freedom: at high spp each image is close to normal, and x1 + x2 is independent of
x1 - x2). The difference D = O - M of our image O and Mitsuba's M has mean zero when both
renderers compute the same integral, and variance v = v_O + v_M.

Tests. For a set of pixels P (the whole image, or one block of B x B pixels), per channel,

    t = sum_P D / sqrt(sum_P v + (REL_FLOOR * sum_P |value|)^2)

is close to Student's t with Satterthwaite's degrees of freedom
nu = (sum v)^2 / sum(v^2 / 3) (each v is a scaled chi-square with one degree of freedom,
whose square has mean 3 v^2), halved (NU_FACTOR, for the reason given there) and capped
at the number of variance terms. Each comparison (one
scene, one precision) runs 3 whole-image tests and 3 per block; it rejects when any
two-sided p-value falls below ALPHA / (number of its tests) (Bonferroni): the chance that
a correct converter fails a comparison is at most ALPHA. The seeds are fixed, so the verdict
is the same on every run.

RMSE. sqrt(mean D^2) against sqrt(mean v), the RMSE that noise alone would give: the ratio
is near 1 when the images differ by noise only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

ALPHA = 1e-3  # family-wise significance of one comparison
BLOCK = 8  # block side in pixels
# Float rounding is not physics. Mitsuba computes in float32 (and our PFM files hold
# float32), so a pixel both renderers compute exactly -- a mirror under a constant-blue sky,
# a solid background -- still differs by a few 1e-7 of its value, and that error is the same
# in every pixel of a block: it adds coherently. So each test's variance gets
# (REL_FLOOR * sum of |value|)^2, a systematic allowance of 1e-5 of the value: far below
# the noise anywhere else, and far below any mistake worth finding (the smallest one the
# power checks inject is 1e-2). Seen: four_mirrors' blue channel, 0.6 exactly here,
# 0.59999955 in Mitsuba (7.5e-7), over whole blocks.
REL_FLOOR = 1e-5
# Satterthwaite's nu computed from the estimated variances is itself noisy, and in null
# simulations of this very test (test_stats.py: normal pixels of unequal variance, and
# skewed binomial pixels) it made the smallest p-values about 1.6 times too frequent.
# Halving nu (heavier tails, larger p-values) brought them under the nominal rate.
NU_FACTOR = 0.5


def _betacf(a: float, b: float, x: float) -> float:
    """Continued fraction of the incomplete beta function (modified Lentz)."""
    tiny, c, d = 1e-300, 1.0, 1.0 - (a + b) * x / (a + 1.0)
    d = 1.0 / (d if abs(d) > tiny else tiny)
    h = d
    for m in range(1, 400):
        m2 = 2 * m
        for num in (m * (b - m) * x / ((a + m2 - 1) * (a + m2)),
                    -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1))):
            d = 1.0 + num * d
            d = 1.0 / (d if abs(d) > tiny else tiny)
            c = 1.0 + num / c
            c = c if abs(c) > tiny else tiny
            h *= d * c
        if abs(d * c - 1.0) < 1e-15:
            break
    return h


def betainc(a: float, b: float, x: float) -> float:
    """The regularised incomplete beta function I_x(a, b)."""
    if x <= 0.0:
        return 0.0
    if x >= 1.0:
        return 1.0
    lnbeta = math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b)
    front = math.exp(lnbeta + a * math.log(x) + b * math.log1p(-x))
    if x < (a + 1.0) / (a + b + 2.0):
        return front * _betacf(a, b, x) / a
    return 1.0 - front * _betacf(b, a, 1.0 - x) / b


def t_two_sided(t: float, nu: float) -> float:
    """P(|T| >= |t|) for Student's t with nu degrees of freedom (nu may be fractional)."""
    if not math.isfinite(t):
        return 0.0
    return betainc(nu / 2.0, 0.5, nu / (nu + t * t))


def normal_two_sided(z: float) -> float:
    return math.erfc(abs(z) / math.sqrt(2.0))


@dataclass
class Verdict:
    """One comparison's numbers (all per channel where it says so)."""

    mean_ours: list
    mean_mitsuba: list
    z_channel: list  # whole-image t statistic per channel
    p_channel: list
    block_t_max: float  # the largest |t| over blocks and channels
    block_p_min: float
    blocks: int
    tests: int
    threshold_p: float  # a test rejects below this p-value
    rmse: float
    rmse_noise: float
    block_t: np.ndarray  # (by, bx, 3) block statistics, for the difference images

    @property
    def rmse_ratio(self) -> float:
        return self.rmse / self.rmse_noise if self.rmse_noise > 0 else float("inf")

    @property
    def p_min(self) -> float:
        return min(min(self.p_channel), self.block_p_min)

    @property
    def passed(self) -> bool:
        return self.p_min >= self.threshold_p


def _t_and_nu(d_sum, v_sum, v2_sum, abs_sum, n_terms: int):
    """t and its degrees of freedom from the sums over a set of pixels (per channel)."""
    v_sum = v_sum + (REL_FLOOR * abs_sum) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(v_sum > 0, d_sum / np.sqrt(v_sum), np.where(d_sum == 0, 0.0, np.inf))
        nu = np.where(v2_sum > 0, v_sum**2 / (v2_sum / 3.0), n_terms)
    return t, np.clip(nu * NU_FACTOR, 1.0, n_terms)


def compare(o1, o2, m1, m2, block: int = BLOCK, alpha: float = ALPHA) -> Verdict:
    """Tests whether our images (o1, o2) and Mitsuba's (m1, m2) have the same mean."""
    O, M = (o1 + o2) / 2.0, (m1 + m2) / 2.0
    size = np.maximum(np.abs(O), np.abs(M))
    vo, vm = (o1 - o2) ** 2 / 4.0, (m1 - m2) ** 2 / 4.0
    v = vo + vm
    v2 = vo**2 + vm**2  # for Satterthwaite: each term's square
    D = O - M
    h, w, _ = D.shape
    n = h * w
    t_img, nu_img = _t_and_nu(D.sum((0, 1)), v.sum((0, 1)), v2.sum((0, 1)), size.sum((0, 1)),
                              2 * n)
    p_img = [t_two_sided(float(t), float(nu)) for t, nu in zip(t_img, nu_img)]

    by, bx = -(-h // block), -(-w // block)
    bt = np.zeros((by, bx, 3))
    p_blocks = []
    for j in range(by):
        for i in range(bx):
            sl = (slice(j * block, (j + 1) * block), slice(i * block, (i + 1) * block))
            cnt = D[sl].shape[0] * D[sl].shape[1]
            t, nu = _t_and_nu(D[sl].sum((0, 1)), v[sl].sum((0, 1)), v2[sl].sum((0, 1)),
                              size[sl].sum((0, 1)), 2 * cnt)
            bt[j, i] = t
            p_blocks += [t_two_sided(float(tc), float(nc)) for tc, nc in zip(t, nu)]
    tests = 3 + len(p_blocks)
    return Verdict(
        mean_ours=O.mean((0, 1)).tolist(), mean_mitsuba=M.mean((0, 1)).tolist(),
        z_channel=t_img.tolist(), p_channel=p_img,
        block_t_max=float(np.max(np.abs(bt))), block_p_min=float(min(p_blocks)),
        blocks=by * bx, tests=tests, threshold_p=alpha / tests,
        rmse=float(np.sqrt(np.mean(D**2))),
        rmse_noise=float(np.sqrt(np.mean(v + (REL_FLOOR * size) ** 2))),
        block_t=bt)
