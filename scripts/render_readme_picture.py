# The README picture: the genus-2 "eight" textured with a checkerboard through the Conformal
# Sphere UV layer, beside its layered sphere. Headless Cycles on the CPU:
#   blender -b --factory-startup --python scripts/render_readme_picture.py -- ADDON_ZIP OUT.png
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

with open(os.path.join(HERE, "..", "tests", "data", "eight.off")) as stream:
    rows = [l.split() for l in stream if l.strip() and not l.startswith("#")]
nv, nf = int(rows[1][0]), int(rows[1][1])
mesh = bpy.data.meshes.new("Eight")
mesh.from_pydata([tuple(map(float, r[:3])) for r in rows[2:2 + nv]], [],
                 [tuple(map(int, r[1:4])) for r in rows[2 + nv:2 + nv + nf]])
eight = bpy.data.objects.new("Eight", mesh)
bpy.context.collection.objects.link(eight)
bpy.context.view_layer.objects.active = eight
eight.select_set(True)
for polygon in mesh.polygons:
    polygon.use_smooth = True
bpy.ops.mesh.meromorph_conformal_sphere_map(layer_gap=0.25)
sphere = bpy.data.objects["Eight Layered Sphere"]
for polygon in sphere.data.polygons:
    polygon.use_smooth = True


def checker_material(name, use_uv):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    checker = nodes.new("ShaderNodeTexChecker")
    checker.inputs["Scale"].default_value = 24.0
    checker.inputs["Color1"].default_value = (0.9, 0.85, 0.75, 1)
    checker.inputs["Color2"].default_value = (0.15, 0.25, 0.5, 1)
    bsdf = nodes["Principled BSDF"]
    if use_uv:
        uv = nodes.new("ShaderNodeUVMap")
        uv.uv_map = "Conformal Sphere"
        links.new(uv.outputs["UV"], checker.inputs["Vector"])
        links.new(checker.outputs["Color"], bsdf.inputs["Base Color"])
    else:
        layer = nodes.new("ShaderNodeAttribute")
        layer.attribute_name = "layer"
        ramp = nodes.new("ShaderNodeValToRGB")
        ramp.color_ramp.elements[0].color = (0.8, 0.35, 0.2, 1)
        ramp.color_ramp.elements[1].color = (0.2, 0.5, 0.8, 1)
        links.new(layer.outputs["Fac"], ramp.inputs["Fac"])
        links.new(ramp.outputs["Color"], bsdf.inputs["Base Color"])
        # The outer layer half see-through, so the inner one shows.
        alpha = nodes.new("ShaderNodeMath")
        alpha.operation = "MULTIPLY_ADD"
        alpha.inputs[1].default_value = -0.6
        alpha.inputs[2].default_value = 1.0
        links.new(layer.outputs["Fac"], alpha.inputs[0])
        links.new(alpha.outputs["Value"], bsdf.inputs["Alpha"])
    return material


eight.data.materials.append(checker_material("Checker", True))
sphere.data.materials.append(checker_material("Layers", False))
# Fit the eight to about the sphere's size, side by side.
size = max(eight.dimensions)
eight.scale = (2.4 / size,) * 3
eight.location = (-1.8, 0, 0)
eight.rotation_euler = (math.radians(70), 0, math.radians(20))
sphere.location = (1.6, 0, 0)

readme_render_scene.render(OUT)
