"""The statistics: p-values, the false-rejection rate under the null, and power."""

import math

import numpy as np
import pytest

import stats


@pytest.mark.parametrize("t,nu,p", [
    (2.228139, 10, 0.05), (12.7062, 1, 0.05), (1.959964, 1e7, 0.05), (3.169273, 10, 0.01),
    (0.0, 5, 1.0), (4.604095, 4, 0.01), (6.868827, 5, 0.001),
])
def test_student_t_tail_matches_tables(t, nu, p):
    assert math.isclose(stats.t_two_sided(t, nu), p, rel_tol=2e-5)


def _images(rng, kind: str, shape=(32, 64, 3)):
    if kind == "normal":  # unequal variances, some pixels noise-free
        sig = rng.uniform(0.001, 0.1, size=shape) * (rng.random(shape) < 0.9)
        return [rng.normal(0.5, sig) for _ in range(4)]
    # skewed: the mean of 256 rare Bernoulli draws, like a pixel that rarely sees the sky
    p = rng.choice([0.0, 0.003, 0.01, 0.05, 0.3], size=shape)
    return [rng.binomial(256, p) / 256 for _ in range(4)]


@pytest.mark.parametrize("kind", ["normal", "skewed"])
def test_under_the_null_p_values_are_not_too_small(kind):
    """300 comparisons of images with equal means: the Bonferroni-adjusted smallest p-value
    falls below 0.1 in at most ~10 % of them (a correct test), and a comparison fails (at
    1e-3) at most once (expected 0.3; 2 or more has probability 3.6 %). Fixed seed."""
    rng = np.random.default_rng(2024 if kind == "normal" else 7)
    adjusted = []
    for _ in range(300):
        v = stats.compare(*_images(rng, kind))
        adjusted.append(v.p_min * v.tests)
    adjusted = np.array(adjusted)
    assert np.mean(adjusted < 0.1) <= 0.13
    assert np.sum(adjusted < stats.ALPHA) <= 1


def test_a_small_shift_in_one_block_is_rejected():
    rng = np.random.default_rng(3)
    o1, o2, m1, m2 = (rng.normal(0.5, 0.02, size=(32, 64, 3)) for _ in range(4))
    assert stats.compare(o1, o2, m1, m2).passed
    # Each image has noise 0.02 per pixel, so D = O - M has 0.02 and a block's sum of 64
    # has 0.16: a shift of 0.02 in one 8x8 block adds 1.28, 8 sigma.
    o1[8:16, 8:16] += 0.02
    o2[8:16, 8:16] += 0.02
    v = stats.compare(o1, o2, m1, m2)
    assert not v.passed and v.block_t_max > 5


def test_a_one_percent_scale_of_the_whole_image_is_rejected():
    rng = np.random.default_rng(4)
    # Noise 0.02 per pixel: the image sum of D has 0.02 * sqrt(2048) = 0.9; 1 % of 0.5 on
    # 2048 pixels adds 10.2, 11 sigma.
    o1, o2, m1, m2 = (rng.normal(0.5, 0.02, size=(32, 64, 3)) for _ in range(4))
    v = stats.compare(o1 * 1.01, o2 * 1.01, m1, m2)
    assert not v.passed and min(v.z_channel) > 7


def test_identical_deterministic_images_pass_and_differing_ones_fail():
    a = np.full((16, 16, 3), 0.72)
    assert stats.compare(a, a, a, a).passed
    assert not stats.compare(a, a, a * (1 + 1e-4), a * (1 + 1e-4)).passed
