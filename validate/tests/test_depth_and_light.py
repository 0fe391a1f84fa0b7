"""max_depth: ours counts bounces, Mitsuba's path integrator counts path segments, so
Mitsuba's is ours + 1. Proved on paths whose bounce count is known exactly: a chain of n
mirrors that sends the camera ray to the sky after exactly n reflections, and a point light
seen in one diffuse bounce. Also the point light's intensity convention (A/pi I cos/d^2)."""

import math

import numpy as np
import pytest

import convert

ALBEDO = 0.8


def _chain(n: int):
    """Square mirrors at P_1..P_n: the ray goes -z, then alternately +x and -z, and the
    n-th mirror sends it straight up. Each mirror's normal bisects in and out."""
    dirs = [np.array([0.0, 0.0, -1.0])]
    for k in range(1, n):
        dirs.append(np.array([1.0, 0.0, 0.0]) if k % 2 else np.array([0.0, 0.0, -1.0]))
    dirs.append(np.array([0.0, 1.0, 0.0]))
    p = np.array([0.0, 0.0, -2.0])
    tris = []
    for k in range(1, n + 1):
        normal = dirs[k] - dirs[k - 1]
        normal /= np.linalg.norm(normal)
        t1 = np.cross(normal, [0.3, 0.5, 0.7])
        t1 /= np.linalg.norm(t1)
        t2 = np.cross(normal, t1)
        c = [p + 0.3 * (a * t1 + b * t2) for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        tris += [(c[0], c[1], c[2]), (c[0], c[2], c[3])]
        p = p + 1.5 * dirs[k]
    return tris


def _l(v) -> list:
    return [float(x) for x in v]


def _chain_scene(scene_from, n: int, extra=(), background=1, materials=""):
    """The mirrors of `_chain(n)` (and `extra` (triangle, material) pairs) seen along -z
    through a narrow look-at camera, over a solid background of grey `background`."""
    objs = "".join(
        f'[[objects]]\ntype = "triangle"\na = {_l(a)}\nb = {_l(b)}\nc = {_l(c)}\n'
        f'material = "{m}"\n'
        for (a, b, c), m in [*((t, "mirror") for t in _chain(n)), *extra])
    return scene_from(f"""
[camera]
type = "look_at"
from = [0, 0, 0]
at = [0, 0, -1]
vfov = 0.01
aspect = 2
[background]
type = "solid"
color = [{background}, {background}, {background}]
[materials.mirror]
type = "mirror"
albedo = [{ALBEDO}, {ALBEDO}, {ALBEDO}]
{materials}
{objs}""", name=f"chain{n}")


def _first_lit(render, depths) -> int:
    for d in depths:
        if render(d) > 0:
            return d
    raise AssertionError("never lit")


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_a_path_of_n_bounces_needs_depth_n_here_and_n_plus_1_in_mitsuba(
        n, scene_from, render_ours):
    scene = _chain_scene(scene_from, n)
    want = ALBEDO ** n

    def ours(d):
        img = render_ours(scene, 4, spp=1, max_depth=d)
        assert np.allclose(img, want if d >= n else 0.0, rtol=1e-7), (d, img[0, 0])  # f32 file
        return img.mean()

    def mits(d):
        img = convert.render(scene, seed=0, width=4, spp=4, max_depth=d,
                             depth_map=lambda x: x)  # d is given to Mitsuba as is
        assert np.allclose(img, want if d >= n + 1 else 0.0, rtol=1e-6), (d, img[0, 0])
        return img.mean()

    assert _first_lit(ours, range(0, 8)) == n
    assert _first_lit(mits, range(0, 8)) == n + 1
    assert convert.mitsuba_depth(n) == n + 1


@pytest.mark.parametrize("n", [0, 1, 3])
def test_an_emitter_after_n_bounces_needs_depth_n_plus_1_in_both(n, scene_from, render_ours):
    """The chain of n mirrors sends the ray up into an emissive square facing down, over a
    black background: the spec blacks out a hit after max_depth bounces, emitter or not,
    so both need max_depth n + 1, and the converter passes max_depth on unchanged."""
    tris = _chain(n)
    # The last mirror's centre: the mean of its two triangles' six corners.
    top = np.array([0.0, 0.0, -2.0]) if n == 0 else np.concatenate(tris[-2:]).mean(axis=0)
    up = np.array([0.0, 0.0, -1.0]) if n == 0 else np.array([0.0, 1.0, 0.0])
    centre = top + 1.5 * up
    t1 = np.cross(up, [0.3, 0.5, 0.7])
    t1 /= np.linalg.norm(t1)
    t2 = np.cross(t1, up)  # (t1, t2) counter-clockwise seen from below: faces -up
    c = [centre + 0.4 * (a * t1 + b * t2) for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    lamp = [((c[0], c[1], c[2]), "lamp"), ((c[0], c[2], c[3]), "lamp")]
    scene = _chain_scene(scene_from, n, extra=lamp, background=0, materials="""
[materials.lamp]
type = "emissive"
radiance = [2, 3, 4]""")
    want = ALBEDO ** n * np.array([2.0, 3.0, 4.0])
    assert convert.surface_emitters(scene) and convert.scene_depth(scene, 5) == 5

    def ours(d):
        img = render_ours(scene, 4, spp=1, max_depth=d)
        assert np.allclose(img, want if d >= n + 1 else 0.0, rtol=1e-6), (d, img[0, 0])
        return img.mean()

    def mits(d):
        img = convert.render(scene, seed=0, width=4, spp=4, max_depth=d)  # as is
        assert np.allclose(img, want if d >= n + 1 else 0.0, rtol=1e-6), (d, img[0, 0])
        return img.mean()

    assert _first_lit(ours, range(0, 6)) == n + 1
    assert _first_lit(mits, range(0, 6)) == n + 1


def test_emitters_beside_point_lights_are_refused(scene_from):
    scene = scene_from(LIT.format(x=0.0).replace('type = "lambertian"', 'type = "emissive"\n'
                                                 'radiance = [1, 1, 1]'))
    with pytest.raises(ValueError, match="two ways"):
        convert.scene_depth(scene, 3)


LIT = """
[camera]
type = "look_at"
from = [0, 0, 0]
at = [{x}, -1, -3]
vfov = 0.0001
aspect = 1
[background]
type = "solid"
color = [0, 0, 0]
[materials.matte]
type = "lambertian"
albedo = [0.9, 0.5, 0.2]
[[objects]]
type = "plane"
point = [0, -1, 0]
normal = [0, 1, 0]
material = "matte"
[[lights]]
position = [0, 1, -3]
intensity = [10, 20, 30]
"""


@pytest.mark.parametrize("x", [0.0, 1.5])
def test_point_light_direct_light_and_its_depth(x, scene_from, render_ours):
    """At (x, -1, -3) under a light at (0, 1, -3): A/pi * I * cos / d^2, with one bounce
    here (depth 1) and two segments in Mitsuba (depth 2); one less gives black."""
    scene = scene_from(LIT.format(x=x))
    d2 = x * x + 4.0
    cos = 2.0 / math.sqrt(d2)
    want = np.array([0.9, 0.5, 0.2]) / math.pi * np.array([10, 20, 30]) * cos / d2
    assert np.allclose(render_ours(scene, 1, max_depth=1)[0, 0], want, rtol=1e-6)
    assert np.all(render_ours(scene, 1, max_depth=0) == 0.0)
    mits = convert.render(scene, seed=0, width=1, spp=4, max_depth=1)  # mapped to 2
    assert np.allclose(mits[0, 0], want, rtol=5e-6)
    black = convert.render(scene, seed=0, width=1, spp=4, max_depth=0)  # mapped to 1
    assert np.all(black == 0.0)
