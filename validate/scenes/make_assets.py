"""The comparison scenes' own small assets, made reproducibly (numpy only):

    python validate/scenes/make_assets.py

- assets/env.hdr: a 128 x 64 lat-long map (flat Radiance RGBE) with colour that varies with
  azimuth (so a turn of one column, 2.8 degrees, changes what a mirror sees) and two
  bright 2 x 2 texel lamps (so it also moves shadows).
- assets/env_soft.hdr: the same colours at 64 x 32 without the lamps, for glass under an
  environment (validate/xml/outdoor.xml): a lamp seen only through glass, found by chance,
  gives a pixel too heavy-tailed for two seeds' variance at a few hundred spp.
- assets/ball.obj: a coarse UV sphere (16 x 8) with vt and vn: smooth shading differs
  visibly from its facets, and its texture coordinates are the sphere's own (u with the
  azimuth, v = 0 at the top as the OBJ file counts it from the bottom).
- assets/panel.obj: the square of Mitsuba's `rectangle` ([-1, 1]^2 at z = 0, facing +z)
  with texture coordinates over the whole square (u = (x + 1)/2, v = (y + 1)/2 after the
  flip of an OBJ's v both renderers make), for a textured wall: the importer's
  `rectangle` gives each of its two triangles its own uv.
- assets/gem.ply: a twelve-sided bipyramid, binary little-endian PLY with vertex normals
  (the corners' directions from the centre: shaded smooth over sharp facets) and u, v, as
  Mitsuba's PLY loader and ours both read it (validate/xml/room.xml).
"""

from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent / "assets"


def write_hdr(path: Path, img: np.ndarray) -> None:
    """Flat (not run-length encoded) RGBE scanlines, top row first."""
    h, w, _ = img.shape
    m = img.max(axis=2)
    e = np.where(m > 1e-32, np.floor(np.log2(np.maximum(m, 1e-32))) + 1, 0)
    scale = np.where(m > 1e-32, 256.0 / np.exp2(e), 0)
    rgb = np.clip(np.floor(img * scale[..., None]), 0, 255)
    rgbe = np.concatenate([rgb, np.where(m > 1e-32, e + 128, 0)[..., None]], axis=2)
    head = f"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {h} +X {w}\n".encode()
    path.write_bytes(head + rgbe.astype(np.uint8).tobytes())


def env_map(w: int = 128, h: int = 64, lamps: bool = True) -> np.ndarray:
    phi = 2 * np.pi * (np.arange(w) + 0.5) / w
    theta = np.pi * (np.arange(h) + 0.5) / h
    up = np.cos(theta)[:, None]  # +1 at the top row
    img = np.empty((h, w, 3))
    img[..., 0] = 0.35 + 0.25 * np.sin(3 * phi)[None, :] + 0.1 * up
    img[..., 1] = 0.40 + 0.20 * np.cos(2 * phi + 1)[None, :] * (0.5 + 0.5 * up)
    img[..., 2] = 0.55 + 0.35 * up + 0.1 * np.sin(5 * phi)[None, :]
    img = np.maximum(img, 0.02)
    if lamps:
        img[20:22, 30:32] = [30.0, 26.0, 20.0]  # a warm lamp, 55 degrees up
        img[26:28, 90:92] = [8.0, 12.0, 20.0]  # a cool one, 20 degrees up
    return img


def ball_obj(nu: int = 16, nv: int = 8) -> str:
    lines = ["# a coarse UV sphere with texture coordinates and normals (make_assets.py)"]
    for j in range(nv + 1):
        th = np.pi * j / nv
        for i in range(nu + 1):
            ph = 2 * np.pi * i / nu
            p = (np.sin(th) * np.cos(ph), np.cos(th), -np.sin(th) * np.sin(ph))
            lines.append("v %.9f %.9f %.9f" % p)
            lines.append("vn %.9f %.9f %.9f" % p)
            lines.append("vt %.9f %.9f" % (i / nu, 1 - j / nv))
    idx = lambda i, j: j * (nu + 1) + i + 1  # noqa: E731
    for j in range(nv):
        for i in range(nu):
            a, b, c, d = idx(i, j), idx(i, j + 1), idx(i + 1, j + 1), idx(i + 1, j)
            for tri in ((a, b, c), (a, c, d)):  # the poles' zero-area halves are dropped
                lines.append("f " + " ".join(f"{k}/{k}/{k}" for k in tri))
    return "\n".join(lines) + "\n"


def panel_obj() -> str:
    return ("# the square [-1, 1]^2 at z = 0 with uv over it (make_assets.py)\n"
            "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
            "vt 0 1\nvt 1 1\nvt 1 0\nvt 0 0\nvn 0 0 1\n"
            "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n")


def gem_ply(n: int = 12) -> bytes:
    ring = [(np.cos(2 * np.pi * i / n), 0.0, -np.sin(2 * np.pi * i / n)) for i in range(n)]
    points = np.array(ring + [(0.0, 0.8, 0.0), (0.0, -1.2, 0.0)])
    normals = points / np.linalg.norm(points, axis=1)[:, None]
    uv = [(i / n, 0.5) for i in range(n)] + [(0.5, 1.0), (0.5, 0.0)]
    faces = []
    for i in range(n):
        for apex in (n, n + 1):
            a, b, c = i, (i + 1) % n, apex
            e1, e2 = points[b] - points[a], points[c] - points[a]
            if np.dot(np.cross(e1, e2), points[a] + points[b] + points[c]) < 0:
                a, b = b, a  # wound outward
            faces.append((a, b, c))
    head = (f"ply\nformat binary_little_endian 1.0\ncomment validate/scenes/make_assets.py\n"
            f"element vertex {len(points)}\n"
            + "".join(f"property float {k}\n" for k in ("x", "y", "z", "nx", "ny", "nz", "u", "v"))
            + f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    body = b"".join(np.array([*p, *nrm, *t], "<f4").tobytes()
                    for p, nrm, t in zip(points, normals, uv))
    body += b"".join(np.array([3], "u1").tobytes() + np.array(f, "<i4").tobytes() for f in faces)
    return head.encode() + body


if __name__ == "__main__":
    HERE.mkdir(exist_ok=True)
    write_hdr(HERE / "env.hdr", env_map())
    write_hdr(HERE / "env_soft.hdr", env_map(64, 32, lamps=False))
    (HERE / "ball.obj").write_text(ball_obj())
    (HERE / "panel.obj").write_text(panel_obj())
    (HERE / "gem.ply").write_bytes(gem_ply())
    print("wrote", *(HERE / f for f in ("env.hdr", "env_soft.hdr", "ball.obj", "panel.obj",
                                        "gem.ply")))
