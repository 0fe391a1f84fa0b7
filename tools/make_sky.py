#!/usr/bin/env python3
"""Writes scenes/textures/sky.hdr, the environment scene's light: a 512 x 256
equirectangular Radiance HDR map in Mitsuba 3's envmap layout (row 0 straight up, the left
edge looking down -z, u turning toward +x), standard library only.

- The sky: a blue zenith brightening to a pale horizon, radiance 0.25-1.2, with a
  Rayleigh-like glow around the sun.
- The sun: a disk of 1.5 degrees radius (the real sun's 0.27 would be a texel or two),
  30 degrees above the horizon, 120 degrees round from -z toward +x (to the right of and
  a little behind a camera looking down -z), of radiance 4000: most of the light.
- The ground: a dim warm grey (0.08-0.12) below the horizon.

The file is written flat (no run-length encoding), each pixel as RGBE: a shared exponent
e with R = r * 2^(e-136) and so on."""
import math, struct, sys
from pathlib import Path

W, H = 512, 256
SUN_ELEVATION, SUN_AZIMUTH, SUN_RADIUS = math.radians(30), math.radians(120), math.radians(1.5)

def direction(u, v):
    # Mitsuba's envmap: theta from +y, phi from -z toward +x.
    theta, phi = math.pi * v, 2 * math.pi * u
    return (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))

def direction_of(elevation, azimuth):
    return direction(azimuth / (2 * math.pi), (math.pi / 2 - elevation) / math.pi)

SUN = direction_of(SUN_ELEVATION, SUN_AZIMUTH)

def radiance(d):
    cos_sun = sum(a * b for a, b in zip(d, SUN))
    if cos_sun > math.cos(SUN_RADIUS):
        return (4000.0, 3800.0, 3400.0)
    y = d[1]
    if y < 0:
        g = 0.08 + 0.04 * math.exp(8 * y)
        return (g * 1.1, g, g * 0.85)
    t = y ** 0.4
    horizon, zenith = (1.2, 1.15, 1.05), (0.25, 0.45, 0.9)
    sky = [h * (1 - t) + z * t for h, z in zip(horizon, zenith)]
    glow = 0.6 * math.exp(12 * (cos_sun - 1))
    return tuple(c + glow * w for c, w in zip(sky, (1.0, 0.85, 0.6)))

def rgbe(rgb):
    m = max(rgb)
    if m < 1e-32:
        return b"\0\0\0\0"
    mantissa, e = math.frexp(m)
    scale = mantissa * 256 / m
    return bytes([min(255, int(c * scale)) for c in rgb] + [e + 128])

out = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).parent.parent / "scenes/textures/sky.hdr")
rows = []
for j in range(H):
    for i in range(W):
        rows.append(rgbe(radiance(direction((i + 0.5) / W, (j + 0.5) / H))))
header = f"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {H} +X {W}\n".encode()
out.write_bytes(header + b"".join(rows))
print(out, out.stat().st_size, "bytes")
