"""Difference images: what a person looks at when a comparison passes or fails.

One PNG per comparison, four panels side by side, each pixel enlarged to a square:
ours | Mitsuba (both sRGB-encoded) | the per-pixel difference in units of its noise
(blue below, red above, +-4 sigma saturates; noise looks like grey static, a real
difference like a shape) | the block statistics (grey |t| up to the rejection threshold,
yellow to red beyond it).
"""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import numpy as np

import stats


def write_png(path: Path, rgb8: np.ndarray) -> None:
    """A minimal 8-bit RGB PNG writer (no dependency beyond zlib)."""
    h, w, _ = rgb8.shape
    raw = b"".join(b"\x00" + rgb8[y].astype(np.uint8).tobytes() for y in range(h))

    def chunk(tag: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + tag + data + \
            struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) \
        + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    path.write_bytes(png)


def srgb8(linear: np.ndarray) -> np.ndarray:
    x = np.clip(linear, 0.0, 1.0)
    s = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
    return np.round(s * 255).astype(np.uint8)


def _diverging(z: np.ndarray) -> np.ndarray:
    """-4..4 -> blue .. grey .. red, per channel averaged to one value per pixel."""
    t = np.clip(z / 4.0, -1.0, 1.0)
    grey = 0.5
    r = np.where(t > 0, grey + (1 - grey) * t, grey * (1 + t))
    b = np.where(t < 0, grey - (1 - grey) * t, grey * (1 - t))
    g = grey * (1 - np.abs(t))
    return np.round(np.stack([r, g, b], -1) * 255).astype(np.uint8)


def _heat(t_abs: np.ndarray, t_star: float) -> np.ndarray:
    under = np.clip(t_abs / t_star, 0, 1) * 0.6
    over = np.clip((t_abs - t_star) / (2 * t_star), 0, 1)
    r = np.where(t_abs < t_star, under, 1.0)
    g = np.where(t_abs < t_star, under, 0.9 * (1 - over))
    b = np.where(t_abs < t_star, under, 0.0)
    return np.round(np.stack([r, g, b], -1) * 255).astype(np.uint8)


def comparison_png(path: Path, o1, o2, m1, m2, block_t: np.ndarray, block: int,
                   t_star: float, scale: int = 4) -> None:
    O, M = (o1 + o2) / 2, (m1 + m2) / 2
    v = ((o1 - o2) ** 2 + (m1 - m2) ** 2) / 4
    h, w, _ = O.shape
    # Each pixel's difference over the typical noise of its block (a single pixel's
    # two-seed variance has one degree of freedom: too noisy to divide by), with the
    # tests' float32 allowance (stats.REL_FLOOR): a pixel both compute exactly is grey.
    sigma = np.zeros_like(v)
    size = np.maximum(np.abs(O), np.abs(M))
    for j in range(0, h, block):
        for i in range(0, w, block):
            sl = (slice(j, j + block), slice(i, i + block))
            sigma[sl] = np.sqrt(v[sl].mean((0, 1)) + (stats.REL_FLOOR * size[sl]) ** 2 + 1e-30)
    z = ((O - M) / sigma).mean(-1) * np.sqrt(3)  # channels averaged, kept in sigma units
    bt = np.abs(block_t).max(-1)
    bt_full = np.kron(bt, np.ones((block, block)))[:h, :w]
    gap = np.full((h, 1, 3), 255, np.uint8)
    panels = [srgb8(O), gap, srgb8(M), gap, _diverging(z), gap, _heat(bt_full, t_star)]
    img = np.concatenate(panels, axis=1)
    img = np.kron(img, np.ones((scale, scale, 1), np.uint8))
    path.parent.mkdir(parents=True, exist_ok=True)
    write_png(path, img)
