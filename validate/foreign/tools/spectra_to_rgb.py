"""Writes a Mitsuba scene with each `<spectrum name=... value="λ:v, ...">` (a reflectance
sampled at wavelengths) replaced by the `<rgb>` Mitsuba's scalar_rgb variant itself reads it
as: the value of the texture Mitsuba's own loader makes of it. This renderer reads RGB only;
both renderers then read the same colour.

    validate/.venv/bin/python validate/foreign/tools/spectra_to_rgb.py IN.xml OUT.xml

Used for validate/foreign/twosided_cbox/ (README.md there lists it as an edit).
"""

from __future__ import annotations

import re
import sys

import mitsuba as mi

mi.set_variant("scalar_rgb")

SPECTRUM = re.compile(r'<spectrum name="(\w+)" value="([^"]*:[^"]*)"\s*/>')
COMMENT = re.compile(r"<!--.*?-->", re.S)


def rgb_of(value: str) -> list[float]:
    """What Mitsuba's loader makes of the sampled spectrum `value` as a reflectance."""
    bsdf = mi.load_string('<bsdf version="3.0.0" type="diffuse">'
                          f'<spectrum name="reflectance" value="{value}"/></bsdf>')
    return list(mi.traverse(bsdf)["reflectance.value"])


def main() -> None:
    src, dst = sys.argv[1], sys.argv[2]
    text = open(src).read()

    def swap(m: re.Match) -> str:
        r, g, b = rgb_of(m.group(2))
        return f'<rgb name="{m.group(1)}" value="{r:.9g}, {g:.9g}, {b:.9g}"/>'

    # Only outside comments: a spectrum commented out stays as it is.
    parts = COMMENT.split(text)
    comments = COMMENT.findall(text)
    out = [SPECTRUM.sub(swap, p) for p in parts]
    merged = "".join(o + c for o, c in zip(out, comments + [""]))
    open(dst, "w").write(merged)


if __name__ == "__main__":
    main()
