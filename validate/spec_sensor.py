"""The specification's camera as a Mitsuba 3 sensor plugin (`spec_screen`).

src/camera/screen.rs: the eye at `eye`, looking down -z; the screen in the plane z = -1,
4 wide and 2 high *between the outermost pixel centres*, so pixel (i, j) (row j from the
top) is centred at (-2 + 4i/(nx-1), 1 - 2j/(ny-1), -1) and its pixels are 4/(nx-1) by
2/(ny-1): not square, which Mitsuba's `perspective` sensor cannot express (its field of view
spans the film edges and its pixels are square).

Mitsuba hands a sensor the film position of a sample as `sample2` in [0, 1)^2, already
divided by the film size, with pixel (i, j) covering [i, i+1) x [j, j+1) before the
division. Our pixel coordinates put pixel i's centre at i, so x = sample2.x * nx - 1/2:
with Mitsuba's box filter (radius 1/2, each sample counts for its own pixel only) and its
uniform position within the pixel, this is exactly our jitter `x = i + delta`,
delta uniform in [-1/2, 1/2) (src/render/reference.rs camera_ray, src/sampling.rs
pixel_jitter).

A crop window (the film's crop_offset and crop_size) renders part of the same image.
`shift` (in pixels, default 0) moves every ray by that much in x and y: it exists only so
the power check can make the classic half-pixel mistake on purpose.
"""

from __future__ import annotations

import drjit as dr
import mitsuba as mi

NAME = "spec_screen"


class SpecScreen(mi.Sensor):
    """Rays from `eye` through the spec's screen; weight 1 (pixel values are radiance)."""

    def __init__(self, props: mi.Properties):
        super().__init__(props)
        film = self.film()
        nx, ny = film.size()
        if nx < 2 or ny < 2:
            raise ValueError("the spec's camera needs at least 2 x 2 pixels")
        # With a crop window, sample2 spans the window: film x = offset + sample2.x * size.
        (ox, oy), (cx, cy) = film.crop_offset(), film.crop_size()
        shift = props.get("shift", 0.0)
        eye = [props.get("eye_x", 0.0), props.get("eye_y", 0.0), props.get("eye_z", 0.0)]
        # screen x = -2 + (4/(nx-1)) * (ox + sample2.x * cx - 1/2 + shift), as a*u + b.
        px, py = 4.0 / (nx - 1), 2.0 / (ny - 1)
        self.ax, self.bx = px * cx, -2.0 + px * (ox + shift - 0.5)
        self.ay, self.by = -py * cy, 1.0 - py * (oy + shift - 0.5)
        self.eye = mi.Point3f(*eye)

    def sample_ray(self, time, sample1, sample2, sample3, active=True):
        d = mi.Vector3f(dr.fma(sample2.x, self.ax, self.bx),
                        dr.fma(sample2.y, self.ay, self.by), -1.0)
        return mi.Ray3f(self.eye, dr.normalize(d), time, []), mi.Spectrum(1.0)

    def sample_ray_differential(self, time, sample1, sample2, sample3, active=True):
        # No differentials: nothing in a converted scene filters textures.
        ray, weight = self.sample_ray(time, sample1, sample2, sample3, active)
        return mi.RayDifferential3f(ray), weight

    def to_string(self):
        return f"SpecScreen[eye={self.eye}]"


def register() -> None:
    """Makes `{'type': 'spec_screen', ...}` available to mi.load_dict (once per variant)."""
    mi.register_sensor(NAME, lambda props: SpecScreen(props))
