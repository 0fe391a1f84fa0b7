#!/usr/bin/env python3
"""The RGB complex indices of refraction Mitsuba 3 uses for its named conductors.

    python3 -m venv /tmp/mi && /tmp/mi/bin/pip install mitsuba==3.9.1
    /tmp/mi/bin/python tools/mitsuba_ior.py > /tmp/metals.txt

For every `data/ior/NAME.eta.spd` Mitsuba ships, loads `{'type': 'conductor', 'material': NAME}`
in the `scalar_rgb` variant and prints the `eta` and `k` colours Mitsuba made from the spectra
(`spectrum_list_to_srgb`: the spectrum against the CIE 1931 matching functions, XYZ to linear
sRGB, out-of-gamut negatives clamped to 0), each an f32 in its shortest round-trip form. This
is where the table in src/material/ior/metals.rs comes from.
"""
import os
import struct

import mitsuba as mi

mi.set_variant('scalar_rgb')
# Out-of-gamut spectra are clamped (a warning each, on stdout): keep stdout for the table.
mi.set_log_level(mi.LogLevel.Error)


def shortest(x):
    f = struct.unpack('f', struct.pack('f', x))[0]
    for n in range(6, 10):
        s = '%.*g' % (n, f)
        if struct.unpack('f', struct.pack('f', float(s)))[0] == f:
            return s
    return repr(f)


folder = os.path.join(os.path.dirname(mi.__file__), 'data', 'ior')
for name in sorted({f.rsplit('.', 2)[0] for f in os.listdir(folder)}):
    params = mi.traverse(mi.load_dict({'type': 'conductor', 'material': name}))
    eta, k = params['eta.value'], params['k.value']
    print(name, [shortest(eta[i]) for i in range(3)], [shortest(k[i]) for i in range(3)])
