# The README's remesh picture: the genus-2 "eight" as given (left) and remeshed through its
# layered sphere by `meromorph remesh` (right, wireframe over the surface, branch vertices
# marked). Headless Cycles on the CPU:
#   blender -b --factory-startup --python scripts/render_remesh_picture.py -- REMESHED.off OUT.png
import math
import os
import sys

import bpy

REMESHED, OUT = sys.argv[sys.argv.index("--") + 1:][:2]
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import readme_render_scene  # noqa: E402
bpy.ops.object.select_all(action="SELECT")
bpy.ops.object.delete()


def off_object(path, name):
    with open(path) as stream:
        rows = [l.split() for l in stream if l.strip() and not l.startswith("#")]
    nv, nf = int(rows[1][0]), int(rows[1][1])
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([tuple(map(float, r[:3])) for r in rows[2:2 + nv]], [],
                     [tuple(map(int, r[1:4])) for r in rows[2 + nv:2 + nv + nf]])
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.collection.objects.link(obj)
    return obj


def material(name, color):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    m.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = color
    return m


def place(obj, x):
    size = max(obj.dimensions)
    obj.scale = (2.6 / size,) * 3
    obj.location = (x, 0, 0)
    obj.rotation_euler = (math.radians(70), 0, math.radians(20))


given = off_object(os.path.join(HERE, "..", "tests", "data", "eight.off"), "Given")
given.data.materials.append(material("Surface", (0.75, 0.72, 0.65, 1)))
given.data.materials.append(material("Edges", (0.1, 0.1, 0.12, 1)))
remeshed = off_object(REMESHED, "Remeshed")
remeshed.data.materials.append(material("Surface", (0.55, 0.7, 0.85, 1)))
remeshed.data.materials.append(material("Edges", (0.1, 0.1, 0.12, 1)))
for obj in (given, remeshed):
    wire = obj.modifiers.new("Wire", "WIREFRAME")
    wire.thickness = 0.008
    wire.use_replace = False
    wire.material_offset = 1
place(given, -1.7)
place(remeshed, 1.7)

readme_render_scene.render(OUT)
