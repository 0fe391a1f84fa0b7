"""The environment map's rotation, the spot light's falloff and the thin lens, each as
Mitsuba evaluates the converted dict, against the formula of docs/SCENE_FORMAT.md (and,
for the map, against our renderer too). Every probe is one exact ray or one exact
evaluation: deterministic."""

import math
import sys
from pathlib import Path

import mitsuba as mi
import numpy as np
import pytest

import convert_more

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "scenes"))
import make_assets  # noqa: E402


def _local(u, v):
    """SCENE_FORMAT.md: +y at the top row, the left edge looks down -z, u turns to +x."""
    th, ph = math.pi * v, 2 * math.pi * u
    return np.array([math.sin(th) * math.sin(ph), math.cos(th), -math.sin(th) * math.cos(ph)])


def _rot(rotate):
    """Rz Ry Rx, right-handed, degrees (our rotate)."""
    x, y, z = (math.radians(a) for a in rotate)
    rx = np.array([[1, 0, 0], [0, math.cos(x), -math.sin(x)], [0, math.sin(x), math.cos(x)]])
    ry = np.array([[math.cos(y), 0, math.sin(y)], [0, 1, 0], [-math.sin(y), 0, math.cos(y)]])
    rz = np.array([[math.cos(z), -math.sin(z), 0], [math.sin(z), math.cos(z), 0], [0, 0, 1]])
    return rz @ ry @ rx


def _meter(sky: dict, d) -> np.ndarray:
    scene = mi.load_dict({
        "type": "scene", "integrator": {"type": "path", "max_depth": 1}, "sky": sky,
        "sensor": {"type": "radiancemeter", "origin": [0, 0, 0],
                   "direction": [float(x) for x in d],
                   "film": {"type": "hdrfilm", "width": 1, "height": 1,
                            "rfilter": {"type": "box"}, "pixel_format": "rgb"},
                   "sampler": {"type": "independent", "sample_count": 1}}})
    return np.array(mi.render(scene, spp=1))[0, 0, :3]


# Where Mitsuba's envmap shows texel (i, j) exactly: columns at their centres, rows at
# theta = pi j/(H-1) (first row straight up, last straight down; found by scanning, and
# what test_envmap.py found for the sky). Our renderer must show it there too.
TEXEL = lambda i, j, w, h: ((i + 0.5) / w, j / (h - 1))  # noqa: E731


@pytest.mark.parametrize("rotate", [[0, 0, 0], [0, 90, 0], [10, 40, -5], [-30, 0, 60]])
def test_envmap_texel_centres_seen_where_our_docs_say(tmp_path, scene_from, render_ours, rotate):
    env = make_assets.env_map(16, 8)
    path = tmp_path / "env.hdr"
    make_assets.write_hdr(path, env)
    texels = np.array(mi.Bitmap(str(path)), dtype=np.float64)  # as stored (RGBE)
    bg = {"type": "envmap", "file": str(path), "scale": 1.0, "rotate": rotate}
    for i, j in [(0, 3), (5, 2), (11, 6), (15, 4)]:
        d = _rot(rotate) @ _local(*TEXEL(i, j, 16, 8))
        want = texels[j, i]
        assert np.allclose(_meter(convert_more.envmap(bg), d), want, rtol=1e-4), (i, j)
        up = [0, 1, 0] if abs(d[1]) < 0.9 else [1, 0, 0]
        s = scene_from(f"""
[camera]
type = "look_at"
from = [0, 0, 0]
at = {[float(x) for x in d]}
up = {up}
vfov = 1
aspect = 1
[background]
type = "envmap"
file = "{path}"
rotate = {[float(a) for a in rotate]}
""")
        ours = render_ours(s, width=1, spp=1, max_depth=1)[0, 0]  # a lit map: segments
        assert np.allclose(ours, want, rtol=1e-4), (i, j)


@pytest.mark.parametrize("theta", [0.0, 10.0, 17.9, 18.1, 24.0, 29.9, 30.1, 45.0])
def test_spot_falloff_is_linear_in_the_angle(theta):
    """I s(theta)/d^2: s = 1 inside the beam (18), (30 - theta)/(30 - 18) up to the
    cutoff (30), 0 beyond."""
    light = {"type": "spot", "position": [0.5, 2.0, -1.0], "direction": [0.3, -1.0, 0.2],
             "intensity": [10, 20, 30], "cutoff_angle": 30.0, "beam_width": 18.0}
    spot = mi.load_dict(convert_more.light(light))
    axis = np.array(light["direction"]) / np.linalg.norm(light["direction"])
    side = np.cross(axis, [1.0, 0.0, 0.0])
    side /= np.linalg.norm(side)
    t = math.radians(theta)
    p = np.array(light["position"]) + 2.5 * (math.cos(t) * axis + math.sin(t) * side)
    it = mi.Interaction3f()
    it.p = mi.Point3f(*p)
    _, value = spot.sample_direction(it, mi.Point2f(0.5, 0.5))
    s = 1.0 if theta <= 18 else max(0.0, (30 - theta) / 12)
    assert np.allclose(np.array(value), np.array([10, 20, 30]) * s / 2.5 ** 2, rtol=2e-4,
                       atol=1e-6)


@pytest.mark.parametrize("film", [(0.5, 0.5), (0.1, 0.8), (0.95, 0.05)])
def test_thin_lens_rays_meet_on_the_plane_of_focus(film):
    """Every lens sample's ray passes through the point where the pinhole ray of the same
    film position meets the plane at focus_distance along the view (not at that distance
    along the ray), and leaves from within aperture of the eye."""
    cam = {"from": [0.5, 1.0, 4.0], "at": [0.0, 0.2, -1.0], "up": [0, 1, 0], "vfov": 30.0,
           "aspect": 2.0, "aperture": 0.3, "focus_distance": 3.0}
    d = {"type": "perspective", "fov_axis": "y", "fov": cam["vfov"],
         "film": {"type": "hdrfilm", "width": 64, "height": 32}, "near_clip": 1e-6,
         "to_world": mi.ScalarTransform4f().look_at(origin=cam["from"], target=cam["at"],
                                                   up=cam["up"])} | convert_more.lens(cam)
    sensor = mi.load_dict(d)
    eye, fwd = np.array(cam["from"]), np.subtract(cam["at"], cam["from"])
    fwd /= np.linalg.norm(fwd)
    right = np.cross(fwd, cam["up"]); right /= np.linalg.norm(right)
    up = np.cross(right, fwd)
    h = 2 * math.tan(math.radians(cam["vfov"]) / 2)
    pin = fwd + (film[0] - 0.5) * h * cam["aspect"] * right + (0.5 - film[1]) * h * up
    focus = eye + pin * cam["focus_distance"] / pin.dot(fwd)
    radii = []
    for a in [(0.5, 0.5), (0.0, 0.3), (1.0, 0.5), (0.2, 0.9), (0.99, 0.01)]:
        ray, _ = sensor.sample_ray(0.0, 0.5, mi.Point2f(*film), mi.Point2f(*a))
        o, dd = np.array(ray.o), np.array(ray.d)
        t = (focus - o).dot(fwd) / dd.dot(fwd)
        assert np.allclose(o + t * dd, focus, atol=2e-5)
        radii.append(np.linalg.norm(o - eye))
    assert max(radii) <= 0.3 + 1e-6 and max(radii) > 0.29
