"""The cameras and the pixel filter: the converted sensor shoots our rays, and each sample
counts for its own pixel only."""

import math

import mitsuba as mi
import numpy as np
import pytest

import convert
import spec_sensor


def _sensor(d: dict):
    spec_sensor.register()
    return mi.load_dict(d)


def _dir(sensor, u, v):
    ray, weight = sensor.sample_ray(0.0, 0.5, mi.Point2f(u, v), mi.Point2f(0.5, 0.5))
    return np.array(ray.o), np.array(ray.d), float(weight[0])


@pytest.mark.parametrize("nx,ny", [(64, 32), (800, 400), (6, 3)])
def test_screen_sensor_shoots_through_the_specs_pixel_centres(nx, ny):
    film = {"type": "hdrfilm", "width": nx, "height": ny}
    s = _sensor({"type": spec_sensor.NAME, "film": film, "eye_x": 0.25, "eye_y": -1.0,
                 "eye_z": 3.0})
    for i, j in [(0, 0), (nx - 1, 0), (0, ny - 1), (nx - 1, ny - 1), (nx // 3, ny // 2)]:
        for dx, dy in [(0.0, 0.0), (-0.5, -0.5), (0.49, 0.3)]:
            # Mitsuba's film position of our pixel coordinate (i + dx, j + dy).
            o, d, w = _dir(s, (i + 0.5 + dx) / nx, (j + 0.5 + dy) / ny)
            p = np.array([-2 + 4 * (i + dx) / (nx - 1), 1 - 2 * (j + dy) / (ny - 1), -1.0])
            assert np.allclose(d, p / np.linalg.norm(p), atol=2e-7), (i, j, dx, dy)
            assert np.allclose(o, [0.25, -1.0, 3.0]) and w == 1.0
    # The four corner pixels' centres are (+-2, +-1, -1), as the spec says.
    _, d, _ = _dir(s, 0.5 / nx, 0.5 / ny)
    assert np.allclose(d, np.array([-2, 1, -1]) / math.sqrt(6), atol=2e-7)


@pytest.mark.parametrize("frm,at,up,vfov,nx,ny", [
    ([13, 2, 3], [0, 0, 0], [0, 1, 0], 20.0, 400, 225),
    ([0.6, 1.3, 4.2], [0, 0.55, 0], [0, 1, 0], 30.0, 64, 32),
    ([-1, 5, 2], [1, 0, -3], [0.2, 0.1, 1], 75.0, 33, 50),
])
def test_perspective_sensor_is_our_look_at_camera(frm, at, up, vfov, nx, ny, scene_from):
    # src/camera/look_at.rs: D ~ -w + ((x+1/2)/nx - 1/2) h_w u + (1/2 - (y+1/2)/ny) h_h v.
    frm, at, up = (np.array(v, float) for v in (frm, at, up))
    w = (frm - at) / np.linalg.norm(frm - at)
    u = np.cross(up, w)
    u /= np.linalg.norm(u)
    v = np.cross(w, u)
    hh = 2 * math.tan(math.radians(vfov) / 2)
    hw = hh * nx / ny
    scene = scene_from(f"""
[camera]
type = "look_at"
from = {frm.tolist()}
at = {at.tolist()}
up = {up.tolist()}
vfov = {vfov}
aspect = {nx / ny!r}
""")
    assert scene.size(nx) == (nx, ny)
    s = mi.load_dict(convert.sensor(scene, nx, 1))
    for x, y in [(0, 0), (nx - 1, ny - 1), (nx / 2 - 0.5, ny / 2 - 0.5), (3.2, 7.9)]:
        o, d, _ = _dir(s, (x + 0.5) / nx, (y + 0.5) / ny)
        want = -w + ((x + 0.5) / nx - 0.5) * hw * u + (0.5 - (y + 0.5) / ny) * hh * v
        assert np.allclose(d, want / np.linalg.norm(want), atol=1e-6), (x, y)
        assert np.allclose(o, frm, atol=1e-6)


QUADRANT = """
[render]
width = {width}
[camera]
{camera}
[background]
type = "solid"
color = [1, 1, 1]
[materials.black]
type = "lambertian"
albedo = [0, 0, 0]
[[objects]]
type = "triangle"
a = {a}
b = {b}
c = {c}
material = "black"
[[objects]]
type = "triangle"
a = {a}
b = {c}
c = {d}
material = "black"
"""


def _quadrant(scene_from, camera: str, corner, right, down, width=16):
    """A black square whose one corner sits exactly on the image centre: it covers the
    top-left quarter of the view, so its edges fall exactly between two pixel columns and
    two pixel rows."""
    c0 = np.array(corner, float)
    big = 1e3
    pts = [c0, c0 - big * np.array(right), c0 - big * np.array(right) - big * np.array(down),
           c0 - big * np.array(down)]
    # The square spans "left" and "up" of the corner: minus right, minus down.
    a, b, c, d = ([float(x) for x in p] for p in pts)
    return scene_from(QUADRANT.format(width=width, camera=camera, a=a, b=b, c=c, d=d))


CASES = {
    "screen": ('type = "screen"\neye = [0.3, -0.2, 0.5]', [0.3, -0.2, -1.5], [1, 0, 0],
               [0, -1, 0]),
    "look_at": ('type = "look_at"\nfrom = [0, 0, 0]\nat = [0, 0, -1]\nvfov = 40\naspect = 2',
                [0, 0, -2], [1, 0, 0], [0, -1, 0]),
}


@pytest.mark.parametrize("case", CASES)
def test_an_edge_on_a_pixel_border_leaves_both_pixels_pure(case, scene_from, render_ours):
    """Box filter plus the pixel mapping: jittered samples never leave their cell, in ours
    and in Mitsuba, so the columns and rows beside the edge are exactly 0 or exactly 1."""
    scene = _quadrant(scene_from, *CASES[case])
    nx, ny = scene.size()
    want = np.ones((ny, nx))
    want[: ny // 2, : nx // 2] = 0.0
    ours_img = render_ours(scene, nx, spp=64)[..., 0]
    assert np.array_equal(ours_img, want)
    mits = convert.render(scene, seed=3, width=nx, spp=64, max_depth=2)[..., 0]
    assert np.allclose(mits, want, atol=1e-6)


def test_the_edge_test_sees_a_gaussian_filter_and_a_half_pixel_shift(scene_from):
    scene = _quadrant(scene_from, *CASES["screen"])
    nx, ny = scene.size()
    d = convert.to_mitsuba(scene, width=nx, spp=64, max_depth=2)
    d["sensor"]["film"]["rfilter"] = {"type": "gaussian"}
    spec_sensor.register()
    gauss = np.array(mi.render(mi.load_dict(d), seed=3))[..., 0]
    assert gauss[0, nx // 2] < 0.99  # the black side bleeds across the edge
    shifted = convert.render(scene, seed=3, width=nx, spp=64, max_depth=2, shift=0.5)[..., 0]
    assert 0.3 < shifted[0, nx // 2 - 1] < 0.7  # half the cell now lies across the edge


def test_a_crop_window_shoots_the_same_rays_as_the_whole_film():
    film = {"type": "hdrfilm", "width": 64, "height": 32}
    whole = _sensor({"type": spec_sensor.NAME, "film": film})
    crop = _sensor({"type": spec_sensor.NAME, "film": film | {
        "crop_offset_x": 40, "crop_offset_y": 8, "crop_width": 8, "crop_height": 4}})
    for u, v in [(0.0, 0.0), (0.5, 0.5), (0.99, 0.2)]:
        _, d_crop, _ = _dir(crop, u, v)
        _, d_whole, _ = _dir(whole, (40 + 8 * u) / 64, (8 + 4 * v) / 32)
        assert np.allclose(d_crop, d_whole, atol=2e-7)
