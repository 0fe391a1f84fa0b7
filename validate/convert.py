"""A scene file of this project as a Mitsuba 3 scene (the dict API), convention for convention.

| ours (docs/SCENE_FORMAT.md)            | Mitsuba 3                                              |
|----------------------------------------|--------------------------------------------------------|
| `screen` camera                        | `spec_screen` (spec_sensor.py): exact pixel centres    |
| `look_at` camera                       | `perspective`, fov_axis y, to_world look_at (same rays)|
| jitter uniform in the pixel cell       | `independent` sampler + `box` filter (own pixel only)  |
| `max_depth` = bounces                  | `path`, max_depth + 1 (Mitsuba counts path segments)   |
| no Russian roulette                    | rr_depth beyond max_depth                              |
| `sky`: lerp by (y+1)/2                 | `envmap`, rows at theta = pi j/(H-1) from +y           |
| `solid`                                | `constant`                                             |
| lambertian                             | `twosided` `diffuse` (ours scatters from either side)  |
| mirror                                 | `twosided` `conductor`, material none, reflectance     |
| dielectric index n (relative), tint A  | `dielectric` int_ior n, ext_ior 1, both tints A; exact |
|                                        | Fresnel (ours is run with fresnel = "exact")           |
| plane (infinite)                       | a mesh of rings around the eye, out to 1e6 (plane_mesh)|
| triangles, meshes                      | one in-memory mesh per material, face normals          |
| point light, intensity I               | `point`, intensity I (both: A/pi I cos/d^2)            |
| emissive, radiance L, albedo A         | `area` emitter L (front face only) on a twosided       |
|                                        | `diffuse` A; `max_depth` as is (see mitsuba_depth)     |
| a lit background (envmap, light = true)| `max_depth` as is: every light then counts on at most  |
|                                        | max_depth segments in ours (scene_depth)               |
| Mitsuba's materials, textures          | convert_materials.py (its own table)                   |
| envmap, directional, spot, thin lens,  | convert_more.py (its own table)                        |
| plane/triangle uv, mesh vn/vt, instance|                                                        |

Each mapping is tested in validate/tests/ (test_camera, test_depth_and_light, test_envmap,
test_scene_files, test_textures, test_lights_lens) and by the comparison itself (compare.py).
"""

from __future__ import annotations

import mitsuba as mi
import numpy as np

import convert_materials
import convert_more
import meshio
import spec_sensor
from scene_model import MITSUBA_MATERIALS, Scene

# An infinite plane becomes a square reaching this many scene units from the eye in each
# direction (plane_mesh). A camera ray then misses where ours would hit beyond ~1e6 units:
# within a hair of the horizon (|dy| < h/1e6), far below the noise of any comparison here.
PLANE_HALF_SIZE = 1.0e6
PLANE_INNER_HALF_SIZE = 0.25
# Envmap rows for the sky: rows sit at theta = pi j/(H-1) and Mitsuba interpolates linearly
# in theta, while the sky is linear in cos(theta): the largest error is
# (pi/(H-1))^2/8 * 1/2 * |zenith - horizon|, 6e-7 of the difference at H = 1025.
SKY_ROWS = 1025
SKY_COLUMNS = 4  # the sky has no azimuthal dependence


def rgb(v) -> dict:
    return {"type": "rgb", "value": [float(x) for x in v]}


def mitsuba_depth(max_depth: int, surface_emitters: bool = False) -> int:
    """Our `max_depth` counts bounces: a path may reflect `max_depth` times, so it has at
    most `max_depth + 1` segments, the last one reaching the sky or a point light. Mitsuba's
    `max_depth` counts segments ("1: only directly visible emitters, 2: direct
    illumination"). An emissive surface, though, is a hit, and the spec blacks out every
    hit after `max_depth` bounces: its light counts on at most `max_depth` segments, which
    is Mitsuba's `max_depth` unchanged. Both proved by test_depth_and_light.py."""
    return max_depth if surface_emitters else max_depth + 1


def scene_depth(scene: Scene, max_depth: int) -> int:
    """Mitsuba's `max_depth` for ours in `scene`. Where the background is a light (an
    envmap, or `light = true`), every light of ours counts on at most `max_depth` segments,
    point lights too (src/scene.rs set_background_sampled): Mitsuba's max_depth unchanged."""
    return mitsuba_depth(max_depth, surface_emitters(scene) or background_sampled(scene))


def background_sampled(scene: Scene) -> bool:
    bg = scene.background
    return bg["type"] == "envmap" or bool(bg.get("light", False))


def surface_emitters(scene: Scene) -> bool:
    """Whether an object of `scene` is emissive. Such a scene maps `max_depth` one way, the
    sky and point lights the other (mitsuba_depth), so it may have neither."""
    emits = any(scene.materials[o["material"]]["type"] == "emissive" for o in scene.objects)
    bg = scene.background
    lit_bg = bg["type"] != "solid" or any(c > 0 for c in bg["color"])
    if emits and not background_sampled(scene) and (scene.lights or lit_bg):
        raise ValueError(f"{scene.name}: emissive surfaces beside point lights or a lit "
                         "background count max_depth two ways; Mitsuba's one max_depth "
                         "cannot match both")
    return emits


def sky_bitmap(horizon, zenith, rows: int = SKY_ROWS, cols: int = SKY_COLUMNS) -> np.ndarray:
    """The sky as a lat-long image: row j at theta = pi j/(rows-1) from +y, where our sky
    is horizon*(1-s) + zenith*s with s = (cos(theta) + 1)/2 (src/background.rs)."""
    theta = np.pi * np.arange(rows) / (rows - 1)
    s = (np.cos(theta) + 1.0) * 0.5
    col = np.outer(1.0 - s, horizon) + np.outer(s, zenith)
    return np.repeat(col[:, None, :], cols, axis=1).astype(np.float32)


def bsdf(m: dict, scene: Scene | None = None) -> dict:
    textures = scene.textures if scene else {}
    if m["type"] in MITSUBA_MATERIALS:
        return convert_materials.mitsuba_bsdf(m, textures, scene.materials,
                                              lambda n: bsdf(n, scene))
    if m["type"] in ("lambertian", "emissive"):  # an emitter reflects as a matte surface
        albedo = convert_materials.texture(m["albedo"], textures)
        return {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": albedo}}
    if m["type"] == "mirror":
        return {"type": "twosided", "bsdf": {"type": "conductor", "material": "none",
                                             "specular_reflectance": rgb(m["albedo"])}}
    if m["type"] == "dielectric":
        # Our index is relative to the outside (1/n for the air inside a glass shell):
        # Mitsuba's eta is int_ior/ext_ior. Both interfaces keep their orientation.
        # The tint multiplies reflected and refracted rays alike, as ours does.
        return {"type": "dielectric", "int_ior": m["index"], "ext_ior": 1.0,
                "specular_reflectance": rgb(m["albedo"]),
                "specular_transmittance": rgb(m["albedo"])}
    raise ValueError(f"unknown material type {m['type']!r}")


def plane_mesh(point, normal, centre) -> tuple[np.ndarray, np.ndarray]:
    """An infinite plane as triangles that grow with the distance from `centre` (the eye,
    projected onto the plane): square rings, each twice the size of the one inside it,
    out to PLANE_HALF_SIZE. Mitsuba places a hit from barycentric coordinates in float32,
    so the position error is ~6e-8 times the size of the triangle hit: one huge rectangle
    put hits a few units from the camera 0.03 units off (found by the point-light test);
    here the error stays ~1e-7 times the distance, as it is for spheres. Each ring shares
    its 8 points (corners and edge midpoints) with the next: no T-junctions, no cracks.
    Wound counter-clockwise about `normal`, which is the front face for a dielectric."""
    n = np.asarray(normal, np.float64)
    n = n / np.linalg.norm(n)
    p0 = np.asarray(point, np.float64)
    c = np.asarray(centre, np.float64)
    c = c - np.dot(c - p0, n) * n  # onto the plane
    a = np.cross(n, [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0])
    a /= np.linalg.norm(a)
    b = np.cross(n, a)  # (a, b, n) right-handed: counter-clockwise in (a, b) faces n
    ring = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1)]
    verts, tris = [c], []
    half = PLANE_INNER_HALF_SIZE
    while True:
        base = len(verts)
        verts += [c + half * (i * a + j * b) for i, j in ring]
        for k in range(8):
            q0, q1 = base + k, base + (k + 1) % 8
            if base == 1:  # the innermost square: a fan around the centre
                tris.append((0, q0, q1))
            else:  # a quad between this ring and the one inside it
                p0_, p1_ = q0 - 8, q1 - 8
                tris += [(p0_, q0, q1), (p0_, q1, p1_)]
        if half >= PLANE_HALF_SIZE:
            break
        half *= 2.0
    return np.array(verts), np.array(tris, dtype=np.int64)


def emitter(m: dict) -> dict | None:
    """Mitsuba's `area` emitter gives off light from the front face only, as ours does
    unless `two_sided`: that has no one-object equivalent, so it is refused."""
    if m["type"] != "emissive":
        return None
    if m["two_sided"]:
        raise ValueError("a two-sided emitter has no Mitsuba equivalent (area is one-sided)")
    return {"type": "area", "radiance": rgb(m["radiance"])}


def _mesh(name: str, verts: np.ndarray, tris: np.ndarray, material: dict,
          scene: Scene | None = None, normals=None, uvs=None) -> mi.Mesh:
    """An in-memory Mitsuba mesh; face normals unless vertex `normals` are given."""
    props = mi.Properties()
    props["bsdf"] = mi.load_dict(bsdf(material, scene))
    if (e := emitter(material)) is not None:
        props["emitter"] = mi.load_dict(e)
    props["face_normals"] = normals is None
    mesh = mi.Mesh(name, len(verts), len(tris), props=props,
                   has_vertex_normals=normals is not None,
                   has_vertex_texcoords=uvs is not None)
    params = mi.traverse(mesh)
    params["vertex_positions"] = verts.astype(np.float32).ravel()
    params["faces"] = tris.astype(np.uint32).ravel()
    if normals is not None:
        params["vertex_normals"] = normals.astype(np.float32).ravel()
    if uvs is not None:
        params["vertex_texcoords"] = uvs.astype(np.float32).ravel()
    params.update()
    return mesh


def eye(scene: Scene) -> list[float]:
    cam = scene.camera
    return cam["eye"] if cam["type"] == "screen" else cam["from"]


def sensor(scene: Scene, width: int, spp: int, shift: float = 0.0) -> dict:
    nx, ny = scene.size(width)
    film = {"type": "hdrfilm", "width": nx, "height": ny, "pixel_format": "rgb",
            "component_format": "float32", "rfilter": {"type": "box"}}
    sampler = {"type": "independent", "sample_count": spp}
    cam = scene.camera
    if cam["type"] == "screen":
        ex, ey, ez = cam["eye"]
        return {"type": spec_sensor.NAME, "film": film, "sampler": sampler, "shift": shift,
                "eye_x": ex, "eye_y": ey, "eye_z": ez}
    if shift:
        raise ValueError("the shift injection is for the screen camera")
    # src/camera/look_at.rs: D ~ -w + ((x+1/2)/nx - 1/2) h_w u + (1/2 - (y+1/2)/ny) h_h v,
    # h_h = 2 tan(vfov/2), h_w = h_h nx/ny: Mitsuba's perspective sensor with its vertical
    # field of view over the film's edges, the same frame (look_at) and aspect nx/ny.
    # A thin lens (aperture > 0) is Mitsuba's thinlens with the same frame (convert_more.lens).
    return {"type": "perspective", "fov_axis": "y", "fov": cam["vfov"], "film": film,
            "sampler": sampler, "near_clip": 1e-6, "far_clip": 1e30,
            "to_world": mi.ScalarTransform4f().look_at(origin=cam["from"], target=cam["at"],
                                                      up=cam["up"])} | convert_more.lens(cam)


def to_mitsuba(scene: Scene, width: int | None = None, spp: int = 64,
               max_depth: int | None = None, shift: float = 0.0,
               depth_map=None) -> dict:
    """The Mitsuba scene dict (call mi.load_dict on it). `width`, `spp`, `max_depth`
    override the file's (our meaning of max_depth); `shift` and `depth_map` exist for the
    power checks' deliberate mistakes."""
    width = scene.render["width"] if width is None else width
    depth = scene.render["max_depth"] if max_depth is None else max_depth
    md = depth_map(depth) if depth_map else scene_depth(scene, depth)
    out = {"type": "scene",
           "integrator": {"type": "path", "max_depth": md,
                          # Russian roulette never starts: every path runs to max_depth.
                          "rr_depth": md + 1, "hide_emitters": False},
           "sensor": sensor(scene, width, spp, shift)}
    bg = scene.background
    if bg["type"] == "sky":
        bmp = mi.Bitmap(sky_bitmap(bg["horizon"], bg["zenith"]))
        out["sky"] = {"type": "envmap", "bitmap": bmp, "scale": 1.0}
    elif bg["type"] == "envmap":
        out["sky"] = convert_more.envmap(bg)
    elif any(c > 0 for c in bg["color"]):
        out["sky"] = {"type": "constant", "radiance": rgb(bg["color"])}
    for k, light in enumerate(scene.lights):
        out[f"light_{k}"] = convert_more.light(light)
    tris: dict[str, list] = {}  # face-normal triangles, one Mitsuba mesh per material
    for k, o in enumerate(scene.objects):
        m = scene.materials[o["material"]]
        uv = convert_more.reads_uv(m, scene)  # only then are coordinates given
        if o["type"] == "sphere":
            out[f"object_{k}"] = {"type": "sphere", "center": [float(c) for c in o["center"]],
                                  "radius": float(o["radius"]), "bsdf": bsdf(m, scene)}
            if (e := emitter(m)) is not None:
                out[f"object_{k}"]["emitter"] = e
        elif o["type"] == "plane":
            v, t = plane_mesh(o["point"], o["normal"], eye(scene))
            uvs = convert_more.plane_uv(v, o["point"], o["normal"]) if uv else None
            out[f"object_{k}"] = _mesh(f"plane_{k}", v, t, m, scene, uvs=uvs)
        elif o["type"] in ("triangle", "mesh", "instance"):
            if o["type"] == "triangle":
                v, t, n, uvs = np.array([o["a"], o["b"], o["c"]], float), np.array([[0, 1, 2]]), None, None
            else:
                mo = convert_more.instance_object(o, scene) if o["type"] == "instance" else o
                v, t, n, uvs = meshio.load_placed_attrs(mo)
            if uv and uvs is None:  # a triangle's (and a mesh without vt's) barycentric uv
                n = None if n is None else n[t.ravel()]  # unshared with the vertices
                v, t, uvs = convert_more.barycentric_uv(v, t)
            if n is not None or uvs is not None:
                out[f"object_{k}"] = _mesh(f"mesh_{k}", v, t, m, scene, normals=n, uvs=uvs)
            else:
                tris.setdefault(o["material"], []).append((v, t))
        else:
            raise ValueError(f"unknown object type {o['type']!r}")
    for name, parts in tris.items():
        verts, faces, base = [], [], 0
        for v, t in parts:
            verts.append(v)
            faces.append(t + base)
            base += len(v)
        out[f"mesh_{len(out)}"] = _mesh(name, np.concatenate(verts), np.concatenate(faces),
                                        scene.materials[name], scene)
    return out


def load(scene: Scene, **kw) -> mi.Scene:
    """The converted scene, loaded (registers the sensor plugin for the current variant)."""
    spec_sensor.register()
    return mi.load_dict(to_mitsuba(scene, **kw))


def render(scene: Scene, seed: int, **kw) -> np.ndarray:
    """A float64 (height, width, 3) image of linear radiance."""
    mscene = load(scene, **kw)
    img = mi.render(mscene, seed=seed, spp=kw.get("spp", 64))
    return np.array(img, dtype=np.float64)[:, :, :3]
