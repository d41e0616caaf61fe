# The README's transfer picture: a checkerboard through the kitten's conformal UVs (left, 10,000
# vertices) carried by Transfer Through the Sphere onto the kitten triangulated apart (right,
# 40,000 vertices, ten times the size): the squares land on the same places. Headless
# Cycles on the CPU:
#   blender -b --factory-startup --python scripts/render_transfer_picture.py -- ADDON_ZIP OUT.png
import math
import os
import sys

import addon_utils
import bpy

ADDON_ZIP, OUT = sys.argv[sys.argv.index("--") + 1:][:2]
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import readme_render_scene  # noqa: E402

bpy.ops.preferences.addon_install(filepath=ADDON_ZIP, overwrite=True)
addon_utils.enable("meromorph_blender", default_set=True)
bpy.ops.object.select_all(action="SELECT")
bpy.ops.object.delete()


def off_object(name, file):
    with open(os.path.join(HERE, "..", "tests", "data", file)) as stream:
        rows = [l.split() for l in stream if l.strip() and not l.startswith("#")]
    nv, nf = int(rows[1][0]), int(rows[1][1])
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([tuple(map(float, r[:3])) for r in rows[2:2 + nv]], [],
                     [tuple(map(int, r[1:4])) for r in rows[2 + nv:2 + nv + nf]])
    for polygon in mesh.polygons:
        polygon.use_smooth = True
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.collection.objects.link(obj)
    return obj


def only(*selected, active):
    bpy.ops.object.select_all(action="DESELECT")
    for obj in selected:
        obj.select_set(True)
    bpy.context.view_layer.objects.active = active


donor = off_object("Kitten", "kitten.nf20k.off")
receiver = off_object("Kitten Triangulated Apart", "kitten.nv40k.off")
only(donor, active=donor)
bpy.ops.mesh.meromorph_conformal_sphere_map(create_sphere=False, select_branch=False)
only(donor, receiver, active=receiver)
bpy.ops.object.meromorph_conformal_transfer()

material = bpy.data.materials.new("Checker")
material.use_nodes = True
nodes, links = material.node_tree.nodes, material.node_tree.links
checker = nodes.new("ShaderNodeTexChecker")
checker.inputs["Scale"].default_value = 16.0
checker.inputs["Color1"].default_value = (0.9, 0.85, 0.75, 1)
checker.inputs["Color2"].default_value = (0.15, 0.25, 0.5, 1)
uv = nodes.new("ShaderNodeUVMap")
uv.uv_map = "Conformal Sphere"
links.new(uv.outputs["UV"], checker.inputs["Vector"])
links.new(checker.outputs["Color"], nodes["Principled BSDF"].inputs["Base Color"])
for obj, x, turn in ((donor, -1.7, 20), (receiver, 1.7, 20)):
    obj.data.materials.append(material)
    obj.scale = (2.6 / max(obj.dimensions),) * 3
    obj.location = (x, 0, 0)
    obj.rotation_euler = (math.radians(80), 0, math.radians(turn))

readme_render_scene.render(OUT)
