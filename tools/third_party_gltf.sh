#!/usr/bin/env bash
# Renders glTF files a third-party exporter wrote: installs trimesh (pinned) in a venv
# under target/, writes a scene with it (tools/third_party_gltf.py) as .glb and as .gltf
# with .bin files, and has raytrace check and render both. The two renders must be the
# same bytes. Needs PyPI (about a minute the first time); not part of cargo test.
set -euo pipefail
cd "$(dirname "$0")/.."
venv=target/gltf-venv
out=target/third-party-gltf
if [[ ! -x "$venv/bin/python" ]]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet trimesh==5.2.0 numpy==2.4.6
fi
rm -rf "$out"
mkdir -p "$out"
"$venv/bin/python" tools/third_party_gltf.py "$out"
cargo build --quiet --release --bin raytrace
for model in "$out/scene.glb" "$out/scene.gltf"; do
    target/release/raytrace check "$model"
    target/release/raytrace render "$model" --width 320 --spp 16 --quiet --out "${model%.*}-${model##*.}.png"
done
cmp "$out/scene-glb.png" "$out/scene-gltf.png"
echo "the .glb and the .gltf trimesh wrote render the same bytes: $out/scene-glb.png"
