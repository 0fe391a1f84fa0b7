#!/usr/bin/env python3
"""Writes a scene file of N instances of one mesh on a grid (default: 10^4 of the 871k-face
Stanford dragon, fetched by tools/fetch_meshes.sh), to measure what instancing costs:

    python3 bench/forest.py 10000 > /tmp/forest.toml
    /usr/bin/time -v target/release/raytrace render /tmp/forest.toml --out /tmp/forest.png

The file names the mesh by its absolute path, so it may be written anywhere."""
import math, random, sys
from pathlib import Path

n = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000
mesh = Path(sys.argv[2] if len(sys.argv) > 2 else
            Path(__file__).resolve().parent.parent / "assets/meshes/dragon_vrip.ply").resolve()
side = math.ceil(math.sqrt(n))
rng = random.Random(1)
print(f"""# {n} instances of {mesh.name} on a {side} x {side} grid (bench/forest.py).
[render]
width = 400
spp = 4
max_depth = 4
precision = "f32"

[camera]
type = "look_at"
from = [0, 0.5, 1.2]
at = [0, 0.05, -2]
vfov = 45
aspect = 2

[meshes.dragon]
file = "{mesh}"

[materials.floor]
type = "lambertian"
albedo = [0.4, 0.45, 0.35]

[materials.green]
type = "lambertian"
albedo = [0.2, 0.5, 0.2]

[materials.gold]
type = "rough_conductor"
material = "Au"
alpha = 0.2

[[objects]]
type = "plane"
point = [0, 0, 0]
normal = [0, 1, 0]
material = "floor"
""")
for k in range(n):
    i, j = k % side, k // side
    x, z = (i - side / 2) * 0.3, -j * 0.3
    print(f"""[[objects]]
type = "instance"
mesh = "dragon"
scale = {rng.uniform(1.0, 1.6):.3f}
rotate = [0, {rng.uniform(0, 360):.1f}, 0]
translate = [{x:.3f}, {-0.053 * 1.3:.3f}, {z:.3f}]
material = "{'gold' if rng.random() < 0.1 else 'green'}"
""")
