#!/usr/bin/env bash
# Renders the README's pictures into docs/images/: every example at its default settings,
# four_mirrors 800 pixels wide and the others 400, the Cornell box scene file, and the
# dragon scene file (its mesh comes from tools/fetch_meshes.sh), and the materials example.
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cargo build --release --quiet --examples --bin raytrace
for spec in "four_mirrors 800" matte_spheres glass plane_and_triangles point_lights random_spheres; do
    read -r name width <<<"$spec"
    "target/release/examples/$name" --width "${width:-400}" --out "$out" >/dev/null
    cp "$out/$name.png" "docs/images/$name.png"
    echo "docs/images/$name.png"
done
target/release/raytrace render scenes/cornell_box.toml --quiet --out docs/images/cornell_box.png
bash tools/fetch_meshes.sh >/dev/null
target/release/raytrace render scenes/dragon.toml --quiet --out docs/images/dragon.png
target/release/raytrace render scenes/environment.toml --quiet --out docs/images/environment.png
"target/release/examples/materials" --out "$out" >/dev/null
cp "$out/materials.png" docs/images/materials.png
echo docs/images/materials.png
