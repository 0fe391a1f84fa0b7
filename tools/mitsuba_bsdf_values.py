#!/usr/bin/env python3
"""Mitsuba 3's own values of its BSDFs, for tests/it/bsdf_mitsuba.rs to compare with.

    python3 -m venv /tmp/mi && /tmp/mi/bin/pip install mitsuba==3.9.1
    /tmp/mi/bin/python tools/mitsuba_bsdf_values.py

For each material below (the test's `materials()` makes the same ones, in the same order)
and each pair of directions, prints Mitsuba's `eval` (the BSDF times the cosine, RGB) and
`pdf` in the `scalar_rgb` variant, as a Rust table. The shading frame is the identity;
`wi` is Mitsuba's (toward the viewer, the renderer's `wo`), `wo` Mitsuba's (toward the
light, the renderer's `wi`).
"""
import math

import mitsuba as mi

mi.set_variant('scalar_rgb')
mi.set_log_level(mi.LogLevel.Error)

MATERIALS = [
    {'type': 'roughconductor', 'material': 'Au', 'distribution': 'ggx', 'alpha': 0.2},
    {'type': 'roughconductor', 'material': 'Cu', 'distribution': 'beckmann', 'alpha': 0.3},
    {'type': 'roughconductor', 'material': 'Al', 'distribution': 'ggx', 'alpha_u': 0.05, 'alpha_v': 0.3},
    {'type': 'roughconductor', 'eta': {'type': 'rgb', 'value': [0.2, 0.9, 1.1]},
     'k': {'type': 'rgb', 'value': [3.9, 2.4, 2.1]}, 'distribution': 'ggx', 'alpha': 0.1,
     'specular_reflectance': {'type': 'rgb', 'value': [0.9, 0.8, 0.7]}},
    {'type': 'roughdielectric', 'distribution': 'ggx', 'alpha': 0.2, 'int_ior': 'bk7', 'ext_ior': 'air'},
    {'type': 'roughdielectric', 'distribution': 'beckmann', 'alpha': 0.3, 'int_ior': 1.33, 'ext_ior': 1.0},
    {'type': 'plastic', 'diffuse_reflectance': {'type': 'rgb', 'value': [0.6, 0.1, 0.1]}},
    {'type': 'plastic', 'diffuse_reflectance': {'type': 'rgb', 'value': [0.6, 0.1, 0.1]},
     'specular_reflectance': {'type': 'rgb', 'value': [0.5, 0.5, 0.5]}, 'nonlinear': True},
    {'type': 'roughplastic', 'distribution': 'ggx', 'alpha': 0.3,
     'diffuse_reflectance': {'type': 'rgb', 'value': [0.1, 0.2, 0.6]}},
    {'type': 'roughplastic', 'distribution': 'beckmann', 'alpha': 0.2, 'nonlinear': True,
     'diffuse_reflectance': {'type': 'rgb', 'value': [0.5, 0.5, 0.5]}},
    {'type': 'twosided', 'bsdf': {'type': 'roughconductor', 'material': 'Au', 'distribution': 'ggx', 'alpha': 0.2}},
]

# (θ, φ) in degrees of the viewer's direction, then of the light's directions.
VIEWS = [(40, 20), (140, 20), (75, 60)]
LIGHTS = [(40, 200), (20, 180), (70, 90), (160, 200), (150, 30)]


def lit(x):
    """`x` as a Rust `f64` literal, to nine significant digits (Mitsuba's are `f32`s)."""
    s = '%.9g' % x
    return s if ('.' in s or 'e' in s) else s + '.0'


def direction(theta, phi):
    t, p = math.radians(theta), math.radians(phi)
    return [math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t)]


ctx = mi.BSDFContext()
si = mi.SurfaceInteraction3f()
si.n = [0, 0, 1]
si.sh_frame = mi.Frame3f(mi.Vector3f(1, 0, 0), mi.Vector3f(0, 1, 0), mi.Vector3f(0, 0, 1))
print('//! Mitsuba 3\'s values of its BSDFs, for `bsdf_mitsuba.rs`: `(material, viewer (θ, φ),')
print('//! light (θ, φ), eval, pdf)`. Printed by tools/mitsuba_bsdf_values.py (Mitsuba %s,' % mi.__version__)
print('//! scalar_rgb).')
print()
print('/// `(material, viewer (θ, φ), light (θ, φ), eval, pdf)`, angles in degrees.')
print('pub type Row = (usize, [f64; 2], [f64; 2], [f64; 3], f64);')
print()
print('#[rustfmt::skip]')
print('pub const MITSUBA: [Row; %d] = [' % (len(MATERIALS) * len(VIEWS) * len(LIGHTS)))
for k, m in enumerate(MATERIALS):
    bsdf = mi.load_dict(m)
    for view in VIEWS:
        si.wi = direction(*view)
        for light in LIGHTS:
            wo = direction(*light)
            f, pdf = bsdf.eval(ctx, si, wo), bsdf.pdf(ctx, si, wo)
            rgb = ', '.join(lit(f[i]) for i in range(3))
            print('    (%d, [%g.0, %g.0], [%g.0, %g.0], [%s], %s),' % (k, *view, *light, rgb, lit(pdf)))
print('];')
