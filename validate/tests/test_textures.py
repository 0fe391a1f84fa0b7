"""Textures as Mitsuba reads them (convert_materials.texture), against the conventions of
docs/SCENE_FORMAT.md: which checkerboard colour is where, in the colour and in the scalar
lookup; scale then offset; an image's v running down from its top row. Each lookup is
exact (no sampling), so each test is deterministic."""

import mitsuba as mi
import numpy as np
import pytest

import convert_materials as cm


def _ours_checker(c0, c1, u, v, scale=(1, 1), offset=(0, 0)):
    """SCENE_FORMAT.md: color0 where frac(u) > 1/2 and frac(v) > 1/2 agree."""
    u, v = scale[0] * u + offset[0], scale[1] * v + offset[1]
    return c0 if ((u - np.floor(u)) > 0.5) == ((v - np.floor(v)) > 0.5) else c1


def _si(u, v):
    si = mi.SurfaceInteraction3f()
    si.uv = mi.Point2f(u, v)
    return si


UVS = [(0.1, 0.1), (0.6, 0.1), (0.1, 0.7), (0.8, 0.9), (0.37, 0.52), (1.3, -0.2)]


@pytest.mark.parametrize("u,v", UVS)
def test_checkerboard_colour_lookup_is_ours(u, v):
    c0, c1 = [0.9, 0.5, 0.1], [0.1, 0.2, 0.7]
    t = {"type": "checkerboard", "color0": c0, "color1": c1, "scale": [3, 2], "offset": [0.25, 0]}
    tex = mi.load_dict(cm.texture(t, {}))
    got = np.array(tex.eval(_si(u, v)))
    want = _ours_checker(c0, c1, u, v, (3, 2), (0.25, 0))
    assert np.allclose(got, want, atol=1e-6)


@pytest.mark.parametrize("u,v", UVS)
def test_checkerboard_scalar_lookup_is_ours_after_the_swap(u, v):
    """An alpha texture: Mitsuba's eval_1 returns color1 where eval returns color0, so the
    converter swaps them; without the swap this test fails (checked below)."""
    t = {"type": "checkerboard", "color0": [0.05, 0.3, 0.3], "color1": [0.4, 0.1, 0.2],
         "scale": 2}
    want = _ours_checker(0.05, 0.4, u, v, (2, 2))  # ours reads the first channel
    swapped = mi.load_dict(cm.texture(t, {}, scalar=True))
    assert swapped.eval_1(_si(u, v)) == pytest.approx(want, abs=1e-6)
    plain = mi.load_dict(cm.texture(t, {}))
    assert plain.eval_1(_si(u, v)) != pytest.approx(want, abs=1e-3)


def test_image_v_runs_down_from_the_top_row(tmp_path):
    """Pixel (i, j) (row j from the top of the file) is seen at uv ((i+1/2)/W, (j+1/2)/H),
    with scale and offset applied to uv first."""
    h, w = 2, 4
    img = np.arange(h * w * 3, dtype=np.float32).reshape(h, w, 3) / (h * w * 3)
    path = tmp_path / "ramp.exr"
    mi.Bitmap(img).write(str(path))
    tex = mi.load_dict(cm.texture({"type": "image", "file": str(path)}, {}))
    for j in range(h):
        for i in range(w):
            got = np.array(tex.eval(_si((i + 0.5) / w, (j + 0.5) / h)))
            assert np.allclose(got, img[j, i], atol=1e-6), (i, j)
    shifted = mi.load_dict(cm.texture({"type": "image", "file": str(path), "scale": 0.5,
                                       "offset": [0.25, 0.5]}, {}))
    # 0.5 * u + 0.25 = 5/8 (pixel 2), 0.5 * v + 0.5 = 3/4 (row 1)
    got = np.array(shifted.eval(_si(0.75, 0.5)))
    assert np.allclose(got, img[1, 2], atol=1e-6)


def test_normal_map_turns_off_mitsubas_flip_and_shadowing():
    m = {"type": "normal_map", "normal_map": [0.5, 0.5, 1.0], "material": "base"}
    base = {"type": "plastic"}
    d = cm.mitsuba_bsdf(m, {}, {"base": base}, lambda n: {"type": "diffuse"})
    assert d["flip_invalid_normals"] is False and d["use_shadowing_function"] is False
    mi.load_dict(d)  # Mitsuba 3.9.1 knows both parameters
