"""OBJ and PLY meshes read the way src/mesh/ reads them, placed the way
src/scene_file/transform.rs places them.

Mitsuba has its own OBJ and PLY loaders, but they accept triangles and quads only and place
vertices in float32. Reading the file here keeps our conventions exactly: every polygon is a
fan around its first vertex, all OBJ objects form one mesh, faces without area are dropped,
and the placement `p -> T + Rz Ry Rx (S * p)` is computed in float64 before the positions are
handed to Mitsuba.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

_PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}


def _read_obj(path: Path) -> tuple[np.ndarray, list[list[int]]]:
    verts, faces = [], []
    for line in path.read_text(errors="replace").splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            verts.append([float(x) for x in parts[1:4]])
        elif parts[0] == "f":
            face = []
            for token in parts[1:]:
                i = int(token.split("/")[0])
                # OBJ indices are 1-based; negative ones count back from the latest vertex.
                face.append(i - 1 if i > 0 else len(verts) + i)
            faces.append(face)
    return np.array(verts, dtype=np.float64).reshape(-1, 3), faces


def _read_ply(path: Path) -> tuple[np.ndarray, list[list[int]]]:
    data = path.read_bytes()
    end = data.index(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii", "replace").splitlines()
    fmt, elements = None, []
    for line in header:
        p = line.split()
        if not p:
            continue
        if p[0] == "format":
            fmt = p[1]
        elif p[0] == "element":
            elements.append({"name": p[1], "count": int(p[2]), "props": []})
        elif p[0] == "property":
            if p[1] == "list":
                elements[-1]["props"].append((p[4], "list", _PLY_TYPES[p[2]], _PLY_TYPES[p[3]]))
            else:
                elements[-1]["props"].append((p[2], _PLY_TYPES[p[1]], None, None))
    body = data[end:]
    verts, faces = None, []
    if fmt == "ascii":
        tokens = iter(body.split())
        for el in elements:
            rows = []
            for _ in range(el["count"]):
                row = {}
                for name, kind, _, _ in el["props"]:
                    if kind == "list":
                        n = int(next(tokens))
                        row[name] = [int(next(tokens)) for _ in range(n)]
                    else:
                        row[name] = float(next(tokens))
                rows.append(row)
            el["rows"] = rows
    else:
        order = "<" if fmt == "binary_little_endian" else ">"
        pos = 0
        for el in elements:
            rows = []
            scalar_only = all(kind != "list" for _, kind, _, _ in el["props"])
            if scalar_only:  # one vectorised read for the vertex block
                dt = np.dtype([(n, order + k) for n, k, _, _ in el["props"]])
                arr = np.frombuffer(body, dtype=dt, count=el["count"], offset=pos)
                pos += dt.itemsize * el["count"]
                el["array"] = arr
                continue
            for _ in range(el["count"]):
                row = {}
                for name, kind, count_t, item_t in el["props"]:
                    if kind == "list":
                        ct = np.dtype(order + count_t)
                        n = int(np.frombuffer(body, ct, 1, pos)[0])
                        pos += ct.itemsize
                        it = np.dtype(order + item_t)
                        row[name] = np.frombuffer(body, it, n, pos).astype(np.int64).tolist()
                        pos += it.itemsize * n
                    else:
                        t = np.dtype(order + kind)
                        row[name] = float(np.frombuffer(body, t, 1, pos)[0])
                        pos += t.itemsize
                rows.append(row)
            el["rows"] = rows
    for el in elements:
        if el["name"] == "vertex":
            if "array" in el:
                a = el["array"]
                verts = np.stack([a["x"], a["y"], a["z"]], axis=1).astype(np.float64)
            else:
                verts = np.array([[r["x"], r["y"], r["z"]] for r in el["rows"]], np.float64)
        elif el["name"] == "face":
            key = "vertex_indices" if any(p[0] == "vertex_indices" for p in el["props"]) \
                else "vertex_index"
            faces = [r[key] for r in el["rows"]]
    return verts.reshape(-1, 3), faces


def place(verts: np.ndarray, scale, rotate_deg, translate) -> np.ndarray:
    """`T + Rz Ry Rx (S * p)`, rotations by the right-hand rule, in float64, in the same
    order of operations as src/scene_file/transform.rs (so the same roundings)."""
    x, y, z = (verts[:, i] * scale[i] for i in range(3))
    s, c = math.sin(math.radians(rotate_deg[0])), math.cos(math.radians(rotate_deg[0]))
    y, z = y * c - z * s, y * s + z * c
    s, c = math.sin(math.radians(rotate_deg[1])), math.cos(math.radians(rotate_deg[1]))
    z, x = z * c - x * s, z * s + x * c
    s, c = math.sin(math.radians(rotate_deg[2])), math.cos(math.radians(rotate_deg[2]))
    x, y = x * c - y * s, x * s + y * c
    return np.stack([x + translate[0], y + translate[1], z + translate[2]], axis=1)


def triangles(verts: np.ndarray, faces: list[list[int]]) -> np.ndarray:
    """Fans around each face's first vertex, without the triangles that have no area:
    an (n, 3) array of vertex indices."""
    tris = [(f[0], f[k], f[k + 1]) for f in faces for k in range(1, len(f) - 1)]
    t = np.array(tris, dtype=np.int64).reshape(-1, 3)
    a, b, c = verts[t[:, 0]], verts[t[:, 1]], verts[t[:, 2]]
    area = np.cross(b - a, c - a)
    keep = np.any(area != 0.0, axis=1)
    return t[keep]


def load_placed(obj: dict) -> tuple[np.ndarray, np.ndarray]:
    """A scene file's mesh object as (placed float64 vertices, triangle indices)."""
    path = Path(obj["file"])
    ext = path.suffix.lower()
    if ext == ".obj":
        verts, faces = _read_obj(path)
    elif ext == ".ply":
        verts, faces = _read_ply(path)
    else:
        raise ValueError(f"{path}: not an .obj or .ply file")
    placed = place(verts, obj["scale"], obj["rotate"], obj["translate"])
    return placed, triangles(placed, faces)


def _read_obj_attrs(path: Path):
    """An OBJ file with its vt and vn: each distinct v/vt/vn a face names becomes one vertex
    (as src/mesh/ reads it). Returns positions, faces, normals or None, uvs or None."""
    pos, tex, nor, keys, faces = [], [], [], {}, []
    for line in path.read_text(errors="replace").splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] in ("v", "vn"):
            (pos if parts[0] == "v" else nor).append([float(x) for x in parts[1:4]])
        elif parts[0] == "vt":
            tex.append([float(x) for x in parts[1:3]])
        elif parts[0] == "f":
            face = []
            for token in parts[1:]:
                idx = (token.split("/") + ["", ""])[:3]
                lists = (pos, tex, nor)
                key = tuple(None if not i else (int(i) - 1 if int(i) > 0 else len(l) + int(i))
                            for i, l in zip(idx, lists))
                face.append(keys.setdefault(key, len(keys)))
            faces.append(face)
    order = sorted(keys, key=keys.get)
    v = np.array([pos[k[0]] for k in order], dtype=np.float64).reshape(-1, 3)
    uv = np.array([tex[k[1]] for k in order]) if tex and all(k[1] is not None for k in order) else None
    n = np.array([nor[k[2]] for k in order]) if nor and all(k[2] is not None for k in order) else None
    return v, faces, n, uv


def load_placed_attrs(obj: dict):
    """A mesh object with its vertex normals and texture coordinates, as our renderer
    uses them: (vertices, triangles, normals or None, uvs or None). Normals are placed by
    R S^-1 and normalised; `face_normals` drops them; `flip_tex_coords` (default: true
    for .obj) maps v to 1 - v. Only OBJ files carry attributes here (a PLY's are not read)."""
    path = Path(obj["file"])
    if path.suffix.lower() != ".obj":
        # Not converted yet: refuse rather than render a smooth or textured PLY faceted.
        head = path.read_bytes()[:4096].split(b"end_header")[0].decode("ascii", "replace")
        props = {line.split()[-1] for line in head.splitlines() if line.startswith("property")}
        if not obj.get("face_normals", False) and {"nx", "ny", "nz"} <= props:
            raise ValueError(f"{path}: a PLY file's vertex normals are not converted yet")
        if props & {"u", "s", "texture_u"}:
            raise ValueError(f"{path}: a PLY file's texture coordinates are not converted yet")
        v, t = load_placed(obj)
        return v, t, None, None
    verts, faces, normals, uvs = _read_obj_attrs(path)
    placed = place(verts, obj["scale"], obj["rotate"], obj["translate"])
    tris = triangles(placed, faces)
    if normals is not None and not obj.get("face_normals", False):
        normals = place(normals, [1.0 / s for s in obj["scale"]], obj["rotate"], [0, 0, 0])
        length = np.linalg.norm(normals, axis=1, keepdims=True)
        normals = np.where(length > 0, normals / np.where(length > 0, length, 1), 0.0)
    else:
        normals = None
    if uvs is not None and obj.get("flip_tex_coords", True):
        uvs = np.stack([uvs[:, 0], 1.0 - uvs[:, 1]], axis=1)
    return placed, tris, normals, uvs


if __name__ == "__main__":  # a quick look: python meshio.py FILE
    file = Path(sys.argv[1])
    v, f = _read_ply(file) if file.suffix.lower() == ".ply" else _read_obj(file)
    print(len(v), "vertices", len(f), "faces")
