"""Writes a glTF scene with a third-party exporter, trimesh, for raytrace to render: a
box of rough plastic, a polished metal ball and a second box placed by a node's matrix,
seen by a perspective camera that trimesh places (a node matrix with a turn in it).

Usage: python tools/third_party_gltf.py OUT_FOLDER (writes scene.glb and scene.gltf with
its .bin files). Run by tools/third_party_gltf.sh, which installs trimesh in a venv.
"""

import sys

import trimesh
from trimesh.visual import TextureVisuals
from trimesh.visual.material import PBRMaterial


def main(out):
    scene = trimesh.Scene()
    box = trimesh.creation.box(extents=(1.0, 1.0, 1.0))
    box.visual = TextureVisuals(
        material=PBRMaterial(baseColorFactor=[200, 80, 40, 255], metallicFactor=0.0, roughnessFactor=0.6)
    )
    ball = trimesh.creation.icosphere(subdivisions=3, radius=0.6)
    ball.visual = TextureVisuals(
        material=PBRMaterial(baseColorFactor=[230, 230, 230, 255], metallicFactor=1.0, roughnessFactor=0.2)
    )
    scene.add_geometry(box, node_name="box")
    scene.add_geometry(ball, node_name="ball", transform=trimesh.transformations.translation_matrix([1.5, 0, 0]))
    scene.add_geometry(box, node_name="box2", transform=trimesh.transformations.translation_matrix([-1.5, 0, 0]))
    scene.set_camera(angles=(0.3, 0.2, 0.0), distance=6.0, fov=(60, 45))
    scene.export(f"{out}/scene.glb")
    scene.export(f"{out}/scene.gltf")


if __name__ == "__main__":
    main(sys.argv[1])
