"""The converter's newer mappings: lights, the environment map, the thin lens, surface
coordinates and mesh attributes, instances.

| ours (docs/SCENE_FORMAT.md)                 | Mitsuba 3                                          |
|---------------------------------------------|----------------------------------------------------|
| envmap file, scale, rotate [x, y, z] deg    | envmap filename, scale, to_world = Rz Ry Rx        |
|                                             | (test_lights_lens.py: the left edge looks down -z) |
| solid / sky with light = true               | constant / envmap as without it (Mitsuba always    |
|                                             | samples its emitters; the flag is our estimator's) |
| directional: direction, irradiance E        | directional, same keys                             |
| spot: position, direction, I, cutoff, beam  | spot, to_world look_at(p, p + dir), intensity I,   |
|                                             | cutoff_angle, beam_width (test: I s(theta)/d^2)    |
| look_at with aperture A, focus_distance f   | thinlens, aperture_radius A, focus_distance f      |
|                                             | (default |at - from|; test: rays meet on z = f)    |
| plane uv: lengths along orthonormal_basis(n)| texcoords of the ring mesh, the same linear map    |
| triangle uv: (0,0) a, (1,0) b, (0,1) c      | per-vertex texcoords                               |
| mesh vn, vt, face_normals, flip_tex_coords  | vertex_normals, vertex_texcoords (meshio.py)       |
| [meshes.NAME] + instance (S, R, T)          | each placement as its own placed mesh, face        |
|                                             | normals (instances keep no vn or vt)               |
"""

from __future__ import annotations

import numpy as np
import mitsuba as mi


def rgb(v) -> dict:
    return {"type": "rgb", "value": [float(x) for x in v]}


def rotation(rotate_deg) -> mi.ScalarTransform4f:
    """Rotations about x, then y, then z: the matrix Rz Ry Rx (Mitsuba's chain applies the
    last factor first)."""
    rx, ry, rz = (float(a) for a in rotate_deg)
    return (mi.ScalarTransform4f().rotate([0, 0, 1], rz).rotate([0, 1, 0], ry)
            .rotate([1, 0, 0], rx))


def envmap(bg: dict) -> dict:
    return {"type": "envmap", "filename": bg["file"], "scale": float(bg["scale"]),
            "to_world": rotation(bg["rotate"])}


def light(l: dict) -> dict:
    kind = l.get("type", "point")
    if kind == "point":
        return {"type": "point", "position": [float(x) for x in l["position"]],
                "intensity": rgb(l["intensity"])}
    if kind == "directional":
        return {"type": "directional", "direction": [float(x) for x in l["direction"]],
                "irradiance": rgb(l["irradiance"])}
    if kind == "spot":
        p = np.asarray(l["position"], float)
        d = np.asarray(l["direction"], float)
        d = d / np.linalg.norm(d)
        # Any up not along the axis: the falloff is symmetric about it.
        up = [0.0, 1.0, 0.0] if abs(d[1]) < 0.9 else [1.0, 0.0, 0.0]
        return {"type": "spot", "intensity": rgb(l["intensity"]),
                "cutoff_angle": float(l["cutoff_angle"]), "beam_width": float(l["beam_width"]),
                "to_world": mi.ScalarTransform4f().look_at(origin=p.tolist(),
                                                          target=(p + d).tolist(), up=up)}
    raise ValueError(f"unknown light type {kind!r}")


def lens(cam: dict) -> dict:
    """The thin lens' keys for a look_at camera with aperture > 0 ({} for a pinhole)."""
    a = float(cam.get("aperture", 0.0))
    if a <= 0.0:
        return {}
    dist = np.linalg.norm(np.subtract(cam["at"], cam["from"]))
    return {"type": "thinlens", "aperture_radius": a,
            "focus_distance": float(cam.get("focus_distance", dist))}


def orthonormal_basis(n) -> tuple[np.ndarray, np.ndarray]:
    """src/sampling.rs orthonormal_basis (Duff et al.): the plane's (s, t) for its uv."""
    x, y, z = n
    s = 1.0 if z >= 0.0 else -1.0
    a = -1.0 / (s + z)
    c = x * y * a
    return (np.array([1.0 + s * x * x * a, s * c, -s * x]), np.array([c, s + y * y * a, -y]))


def plane_uv(verts: np.ndarray, point, normal) -> np.ndarray:
    n = np.asarray(normal, float)
    n = n / np.linalg.norm(n)
    s, t = orthonormal_basis(n)
    d = verts - np.asarray(point, float)
    return np.stack([d @ s, d @ t], axis=1)


def barycentric_uv(verts: np.ndarray, tris: np.ndarray):
    """Each triangle with its own three vertices at uv (0,0), (1,0), (0,1): a triangle's
    and a mesh without vt's coordinates."""
    v = verts[tris.ravel()]
    uv = np.tile([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], (len(tris), 1))
    return v, np.arange(3 * len(tris)).reshape(-1, 3), uv


def reads_uv(m: dict, scene) -> bool:
    """Whether material `m` looks anything up by uv (a texture, a normal map): only then
    are coordinates worth giving Mitsuba."""
    if m.get("type") == "normal_map":
        return True
    for v in m.values():
        if isinstance(v, str) and v in scene.textures:
            return True
        if isinstance(v, dict) and (v.get("type") in ("checkerboard", "image")
                                    or reads_uv(v, scene)):
            return True
    return False


def instance_object(o: dict, scene) -> dict:
    """An instance as the mesh object it equals (docs: to rounding)."""
    return {"type": "mesh", "file": scene.meshes[o["mesh"]]["file"], "scale": o["scale"],
            "rotate": o["rotate"], "translate": o["translate"], "face_normals": True}
