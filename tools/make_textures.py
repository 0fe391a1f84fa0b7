#!/usr/bin/env python3
"""Writes the materials scene's two textures into scenes/textures/ (standard library only):

- uv_grid.png: a 256 x 256 8-bit sRGB test image, 8 x 8 cells whose hue runs with u (left
  to right) and whose brightness runs with v (top to bottom), with dark grid lines, so a
  render shows where u and v run;
- bumps.png: a 256 x 256 tangent-space normal map (n = 2 rgb - 1) of 8 x 8 round bumps,
  each a spherical cap, flat between them."""
import colorsys, struct, sys, zlib
from pathlib import Path

W = H = 256
CELL = W // 8

def pixel(x, y):
    if x % CELL in (0, CELL - 1) or y % CELL in (0, CELL - 1):
        return (20, 20, 24)
    i, j = x // CELL, y // CELL
    r, g, b = colorsys.hsv_to_rgb(i / 8, 0.65, 0.95 - 0.08 * j)
    return tuple(round(255 * c) for c in (r, g, b))

def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

def bump(x, y):
    # The cap's slope at the pixel centre: a sphere of radius R over a disk of radius r.
    cx, cy = (x % CELL) + 0.5 - CELL / 2, (y % CELL) + 0.5 - CELL / 2
    r, R = CELL * 0.4, CELL * 0.6
    if cx * cx + cy * cy >= r * r:
        n = (0.0, 0.0, 1.0)
    else:
        # v runs down the image, so the cap's y slope enters with its sign turned.
        nz = (R * R - cx * cx - cy * cy) ** 0.5
        n = (cx / R, -cy / R, nz / R)
    return tuple(round(255 * (c + 1) / 2) for c in n)

def write(path, f):
    rows = b"".join(b"\0" + bytes(c for x in range(W) for c in f(x, y)) for y in range(H))
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0))
           + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
    path.write_bytes(png)
    print(path, len(png), "bytes")

folder = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).parent.parent / "scenes/textures")
write(folder / "uv_grid.png", pixel)
write(folder / "bumps.png", bump)
