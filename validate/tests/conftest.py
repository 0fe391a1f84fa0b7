"""Shared set-up: the validate/ modules on the path, Mitsuba's scalar_rgb variant, and
helpers that render tiny scenes with both renderers."""

import sys
from pathlib import Path

import mitsuba as mi
import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
mi.set_variant("scalar_rgb")

import ours  # noqa: E402
import scene_model  # noqa: E402


@pytest.fixture
def scene_from(tmp_path):
    """Writes TOML text to a file and loads it as a scene."""
    def make(text: str, name: str = "probe"):
        path = tmp_path / f"{name}.toml"
        path.write_text(text)
        return scene_model.load(path)
    return make


@pytest.fixture
def render_ours(tmp_path):
    """Our renderer on a scene: a float64 (h, w, 3) image."""
    def run(scene, width, spp=1, max_depth=10, seed=0, precision="f64"):
        img, _ = ours.render(scene, tmp_path / "ours", width=width, spp=spp,
                             max_depth=max_depth, seed=seed, precision=precision)
        return img
    return run
