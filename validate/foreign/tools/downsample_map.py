"""Writes an environment map downsampled by a whole factor (each output texel the mean of
a factor x factor block of input texels), to keep a copy small enough to commit.

    validate/.venv/bin/python validate/foreign/tools/downsample_map.py IN.exr OUT.exr 8

Used for validate/foreign/infinite_mirrors/textures/museum.exr (README.md there lists it as
an edit).
"""

from __future__ import annotations

import sys

import mitsuba as mi
import numpy as np

mi.set_variant("scalar_rgb")


def main() -> None:
    src, dst, factor = sys.argv[1], sys.argv[2], int(sys.argv[3])
    img = np.array(mi.Bitmap(src), dtype=np.float64)[..., :3]
    h, w = img.shape[0] // factor, img.shape[1] // factor
    small = img[: h * factor, : w * factor].reshape(h, factor, w, factor, 3).mean(axis=(1, 3))
    mi.Bitmap(small.astype(np.float32), mi.Bitmap.PixelFormat.RGB).write(dst)
    print(f"{src}: {img.shape[1]}x{img.shape[0]} -> {dst}: {w}x{h}")


if __name__ == "__main__":
    main()
