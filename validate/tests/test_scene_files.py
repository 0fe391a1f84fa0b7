"""Reading and writing scene files, meshes placed as ours places them, and the plane."""

import struct
import subprocess

import numpy as np
import pytest

import convert
import meshio
import ours
import scene_model

ROOT = ours.ROOT
SCENES = sorted((ROOT / "scenes").glob("*.toml")) + \
    sorted((ROOT / "validate/scenes").glob("*.toml"))
MESHES = ROOT / "tests/data/meshes"


@pytest.mark.parametrize("path", [p for p in SCENES if not scene_model.missing_files(p)],
                         ids=lambda p: p.stem)
def test_a_written_scene_renders_the_same_bits(path, tmp_path):
    scene = scene_model.load(path)
    copy = tmp_path / f"{path.stem}.toml"
    scene_model.write_toml(scene, copy)
    again = scene_model.load(copy)
    for key in ("render", "camera", "background", "materials", "objects", "lights",
                "textures", "meshes"):
        assert getattr(again, key) == getattr(scene, key), key
    outs = []
    for src in (path, copy):
        out = tmp_path / f"{src.parent.name}-{src.stem}.pfm"
        subprocess.run([str(ours.BINARY), "render", str(src), "--width", "24", "--spp", "2",
                        "--out", str(out), "--quiet"], check=True, stdout=subprocess.DEVNULL)
        outs.append(out.read_bytes())
    assert outs[0] == outs[1]


def test_an_almost_empty_file_gets_the_formats_defaults(tmp_path):
    path = tmp_path / "empty.toml"
    path.write_text('[[objects]]\ntype = "sphere"\ncenter = [0, 0, -1]\nradius = 0.5\n'
                    'material = "m"\n[materials.m]\ntype = "dielectric"\nindex = 1.5\n')
    s = scene_model.load(path)
    assert s.render == {"width": 800, "spp": 1, "max_depth": 10, "seed": 0, "precision": "f64"}
    assert s.camera == {"type": "screen", "eye": [0.0, 0.0, 0.0]}
    assert s.background == {"type": "sky", "horizon": [1.0, 1.0, 1.0],
                            "zenith": [0.5, 0.7, 1.0]}
    assert s.materials["m"] == {"type": "dielectric", "index": 1.5, "albedo": [1.0] * 3,
                                "fresnel": "schlick"}
    assert s.size() == (800, 400)


def test_placement_matches_the_rust_tests():
    # src/scene_file/transform.rs scale_then_x_then_y_then_z_then_translate.
    p = meshio.place(np.array([[1.0, 0, 0], [0, 1.0, 0]]), [2, 3, 4], [90, 90, 90], [10, 20, 30])
    assert np.allclose(p, [[10, 20, 28], [10, 23, 30]], atol=1e-12)


def test_a_placed_mesh_has_the_bounds_raytrace_check_reports(tmp_path):
    obj = {"type": "mesh", "file": str(MESHES / "icosahedron.ply"), "scale": [2.0, 3.0, 4.0],
           "rotate": [30.0, 45.0, 60.0], "translate": [1.0, 2.0, 3.0], "material": "m"}
    verts, tris = meshio.load_placed(obj)
    assert len(tris) == 20
    scene = tmp_path / "m.toml"
    scene.write_text(scene_model.to_toml(scene_model.Scene(
        scene, {}, {"type": "screen"}, {"type": "sky"},
        {"m": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]}}, [obj])))
    out = subprocess.run([str(ours.BINARY), "check", str(scene)], check=True,
                         capture_output=True, text=True).stdout
    line = next(l for l in out.splitlines() if "bounds" in l)
    nums = [float(x) for x in line.split(":")[1].replace("(", " ").replace(")", " ")
            .replace(",", " ").replace("to", " ").split()]
    used = verts[np.unique(tris)]
    assert np.allclose(nums, [*used.min(0), *used.max(0)], atol=1e-4)


def _ply(verts, faces, fmt: str) -> bytes:
    head = (f"ply\nformat {fmt} 1.0\nelement vertex {len(verts)}\nproperty float x\n"
            f"property float y\nproperty float z\nproperty uchar red\nelement face {len(faces)}\n"
            "property list uchar int vertex_indices\nend_header\n").encode()
    if fmt == "ascii":
        body = "".join(f"{x} {y} {z} 7\n" for x, y, z in verts)
        body += "".join(f"{len(f)} {' '.join(map(str, f))}\n" for f in faces)
        return head + body.encode()
    e = "<" if fmt == "binary_little_endian" else ">"
    body = b"".join(struct.pack(e + "fffB", *v, 7) for v in verts)
    body += b"".join(struct.pack(e + "B" + "i" * len(f), len(f), *f) for f in faces)
    return head + body


def test_ply_and_obj_polygons_become_the_same_fans(tmp_path):
    verts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0, 1), (2, 2, 1), (0, 0, 0)]
    faces = [[0, 1, 2, 3], [1, 4, 5, 2, 0], [0, 1, 6]]  # a quad, a pentagon, a degenerate
    obj = tmp_path / "m.obj"
    obj.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in verts)
                   + "f 1/1 2/2 3/3 4/4\nf -6 -3 -2 -5 -7\nf 1 2 7\n")
    want = np.array([[0, 1, 2], [0, 2, 3], [1, 4, 5], [1, 5, 2], [1, 2, 0]])
    common = {"scale": [1.0] * 3, "rotate": [0.0] * 3, "translate": [0.0] * 3}
    for fmt in ("ascii", "binary_little_endian", "binary_big_endian"):
        ply = tmp_path / f"m-{fmt}.ply"
        ply.write_bytes(_ply(verts, faces, fmt))
        v, t = meshio.load_placed({"file": str(ply), **common})
        assert np.array_equal(t, want) and np.allclose(v, verts), fmt
    v, t = meshio.load_placed({"file": str(obj), **common})
    assert np.array_equal(t, want) and np.allclose(v, verts)


@pytest.mark.parametrize("normal", [[0, 1, 0], [0.3, -2, 0.5], [1, 0, 0]])
def test_the_plane_mesh_tiles_the_plane_facing_its_normal(normal):
    point, centre = np.array([0.5, -0.8, 2.0]), np.array([0.1, 3.0, -1.0])
    v, t = convert.plane_mesh(point, normal, centre)
    n = np.array(normal, float) / np.linalg.norm(normal)
    assert np.allclose((v - point) @ n, 0, atol=1e-9)  # every vertex on the plane
    cross = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    assert np.all(cross @ n > 0)  # wound counter-clockwise about the normal
    u1 = np.cross(n, [0.6, 0.0, 0.8])
    u1 /= np.linalg.norm(u1)
    u2 = np.cross(n, u1)
    rel = v - v[0]  # v[0] is the eye's foot, the centre of the rings
    side = 2 * np.max(np.hypot(rel @ u1, rel @ u2)) / np.sqrt(2)  # corners at (+-h, +-h)
    area = 0.5 * np.linalg.norm(cross, axis=1).sum()
    assert np.isclose(area, side ** 2, rtol=1e-9)  # no gap, no overlap
    # No triangle is larger than a few times its distance from the eye's foot.
    dist = np.linalg.norm(v[t].mean(1) - v[0], axis=1)
    size = np.linalg.norm(v[t[:, 1]] - v[t[:, 0]], axis=1)
    assert np.all(size <= 2.5 * np.maximum(dist, convert.PLANE_INNER_HALF_SIZE))
    assert side >= 2 * convert.PLANE_HALF_SIZE


def test_dielectric_keeps_the_relative_index_and_tints_both_ways():
    b = convert.bsdf({"type": "dielectric", "index": 1 / 1.5, "albedo": [0.9, 0.8, 0.7]})
    assert b["int_ior"] / b["ext_ior"] == 1 / 1.5  # Mitsuba's eta = int/ext: ours
    assert b["specular_reflectance"]["value"] == b["specular_transmittance"]["value"] \
        == [0.9, 0.8, 0.7]
