"""The sky as Mitsuba's lat-long envmap: which row is seen in which direction.

A radiance meter looks along one exact ray, so each probe is deterministic."""

import math

import mitsuba as mi
import numpy as np
import pytest

import convert


def _seen(bitmap: np.ndarray, direction) -> np.ndarray:
    scene = mi.load_dict({
        "type": "scene", "integrator": {"type": "path", "max_depth": 1},
        "sky": {"type": "envmap", "bitmap": mi.Bitmap(bitmap.astype(np.float32))},
        "sensor": {"type": "radiancemeter", "origin": [0, 0, 0],
                   "direction": [float(x) for x in direction],
                   "film": {"type": "hdrfilm", "width": 1, "height": 1,
                            "rfilter": {"type": "box"}, "pixel_format": "rgb"},
                   "sampler": {"type": "independent", "sample_count": 1}}})
    return np.array(mi.render(scene, spp=1))[0, 0, :3]


def _direction(theta: float, phi: float) -> list:
    """theta from +y (the zenith), phi about it."""
    return [math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)]


H = 9
ROWS = np.repeat(np.arange(H, dtype=np.float64)[:, None, None], 4, axis=1).repeat(3, axis=2)


@pytest.mark.parametrize("j", range(H))
@pytest.mark.parametrize("phi", [0.3, 2.0, 4.5])
def test_row_j_is_seen_at_theta_pi_j_over_h_minus_1(j, phi):
    # Row 0 is straight up, row H-1 straight down, rows evenly spaced in theta.
    assert np.allclose(_seen(ROWS, _direction(math.pi * j / (H - 1), phi)), j, atol=1e-4)


@pytest.mark.parametrize("j", range(H - 1))
def test_between_rows_it_interpolates_linearly_in_theta(j):
    v = _seen(ROWS, _direction(math.pi * (j + 0.25) / (H - 1), 1.0))
    assert np.allclose(v, j + 0.25, atol=1e-4)


def test_half_texel_centres_would_be_the_wrong_convention():
    # Were rows at theta = pi (j + 1/2)/H, row j would be seen there: it is not (except
    # the middle row, where the two conventions meet).
    for j in (j for j in range(H) if 2 * j != H - 1):
        v = _seen(ROWS, _direction(math.pi * (j + 0.5) / H, 1.0))
        assert abs(v[0] - j) > 0.05


def test_the_converted_sky_is_our_gradient_in_every_direction():
    # src/background.rs: horizon (1 - s) + zenith s, s = (y + 1)/2.
    horizon, zenith = np.array([0.9, 0.3, 0.05]), np.array([0.1, 0.5, 2.0])
    bmp = convert.sky_bitmap(horizon, zenith)
    rng = np.random.default_rng(19)
    dirs = rng.normal(size=(40, 3))
    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
    dirs = np.vstack([dirs, [[0, 1, 0], [0, -1, 0], [1, 0, 0], [0, 0, -1]]])
    for d in dirs:
        s = (d[1] + 1) / 2
        want = horizon * (1 - s) + zenith * s
        # The interpolation bound of convert.SKY_ROWS (6e-7 of |zenith - horizon| < 2)
        # plus float32 rounding.
        assert np.allclose(_seen(bmp, d), want, rtol=1e-6, atol=2e-6), d
