"""The XML scenes of the cross-check (validate/xml/): between them they hold every plugin,
structure and transform the importer reads (README.md's list), each loads in Mitsuba, and
each is read by this renderer without a warning (a warning is a known difference)."""

import subprocess
import xml.etree.ElementTree as ET

import mitsuba as mi
import pytest

import foreign_check
import ours
import xml_check

PLUGINS = {
    ("shape", k) for k in ("obj", "ply", "sphere", "disk", "rectangle", "cube", "shapegroup",
                           "instance")
} | {
    ("bsdf", k) for k in ("diffuse", "conductor", "roughconductor", "dielectric",
                          "roughdielectric", "thindielectric", "plastic", "roughplastic",
                          "twosided", "normalmap")
} | {("texture", "bitmap"), ("texture", "checkerboard")} | {
    ("emitter", k) for k in ("area", "point", "constant", "envmap", "directional", "spot")
} | {("sensor", "perspective"), ("sensor", "thinlens"), ("film", "hdrfilm"),
     ("sampler", "independent"), ("integrator", "path"), ("rfilter", "box")}
STRUCTURE = {"default", "include", "path", "ref", "lookat", "translate", "rotate", "scale",
             "matrix"}
FOV_AXES = {"x", "smaller", "diagonal"}


def _elements():
    for path in sorted(xml_check.XML.glob("*.xml")):
        yield from ET.parse(path).getroot().iter()


def test_the_scenes_hold_every_plugin_the_importer_reads():
    found = {(e.tag, e.get("type")) for e in _elements() if e.get("type")}
    assert PLUGINS - found == set()
    assert STRUCTURE - {e.tag for e in _elements()} == set()
    axes = {e.get("value") for e in _elements() if e.get("name") == "fov_axis"}
    # A sensor without fov_axis has Mitsuba's default, x.
    assert FOV_AXES - (axes | {"x"}) == set()
    assert any(e.get("value", "").startswith("$") for e in _elements())


@pytest.mark.parametrize("name", sorted(xml_check.SCENES))
def test_each_loads_in_mitsuba_and_imports_without_a_warning(name):
    path = xml_check.XML / f"{name}.xml"
    scene = mi.load_file(str(path), width="8", height="8", spp="1")
    assert list(scene.sensors()[0].film().size()) == [8, 8]
    out = subprocess.run([str(ours.BINARY), "check", str(path)], capture_output=True, text=True,
                         check=True).stdout
    assert "differs from Mitsuba" not in out, out


@pytest.mark.parametrize("name", sorted(foreign_check.SCENES))
def test_each_foreign_scene_loads_in_both(name):
    """The scenes from elsewhere (validate/foreign/) load in Mitsuba at a tiny size, and
    this renderer reads them (`check`: no error)."""
    rel, sizes = foreign_check.SCENES[name]
    path = foreign_check.FOREIGN / rel
    tiny = {k: "8" if k != "spp" else "1" for k in sizes["quick"]}
    scene = mi.load_file(str(path), **tiny)
    assert min(scene.sensors()[0].film().size()) == 8
    args = [str(ours.BINARY), "check", str(path)]
    for k, v in tiny.items():
        args += ["-D", f"{k}={v}"]
    subprocess.run(args, capture_output=True, text=True, check=True)
