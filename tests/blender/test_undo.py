# Undo in the real Blender with a window (undo needs one): xvfb-run -a blender --factory-startup
# --python-exit-code 1 --python test_undo.py -- ADDON_ZIP
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, install_addon, summary  # noqa: E402

ADDON_ZIP = sys.argv[sys.argv.index("--") + 1]


def cad_plate():
    """A plate with a hole as CAD programs export it: the flat faces fanned from the square's
    corners to the hole's circle, the walls strips of two triangles (segments 64, thickness 0.05),
    as meromorph make cad writes it (vertex for vertex)."""
    import math
    segments, thickness = 64, 0.05
    top = [(i, j, thickness) for i in range(2) for j in range(2)]
    for k in range(segments):
        angle = 2 * math.pi * (k + 0.5) / segments
        top.append((0.5 + 0.3 * math.cos(angle), 0.5 + 0.3 * math.sin(angle), thickness))
    layer = len(top)
    circle = [4 + k for k in range(segments)] + [4]
    nearest = [3, 1, 0, 2]  # the corner each quarter of the circle faces
    faces, walls = [], []
    for k in range(segments):
        here, there = nearest[4 * k // segments], nearest[(4 * (k + 1) // segments) % 4]
        if here != there:
            faces.append((circle[k], here, there))
        faces.append((circle[k], there, circle[k + 1]))
        walls.append((circle[k + 1], circle[k]))
    walls += [(0, 2), (2, 3), (3, 1), (1, 0)]
    mesh_faces = faces + [(a + layer, c + layer, b + layer) for a, b, c in faces]
    for a, b in walls:
        mesh_faces += [(a + layer, b + layer, b), (a + layer, b, a)]
    vertices = top + [(x, y, z - thickness) for x, y, z in top]
    mesh = bpy.data.meshes.new("CAD Plate")
    mesh.from_pydata(vertices, [], mesh_faces)
    obj = bpy.data.objects.new("CAD Plate", mesh)
    bpy.context.collection.objects.link(obj)
    bpy.ops.object.select_all(action="DESELECT")
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj
    return obj


def main():
    install_addon(ADDON_ZIP)
    window = bpy.context.window_manager.windows[0]
    with bpy.context.temp_override(window=window):
        bpy.ops.object.select_all(action="SELECT")
        bpy.ops.object.delete()
        # As from the interface: each operator call is its own undo step.
        bpy.ops.mesh.primitive_torus_add("EXEC_DEFAULT", True, major_segments=32, minor_segments=12)
        torus = bpy.context.active_object
        name = torus.name
        before = len(torus.data.uv_layers)
        check(bpy.ops.mesh.meromorph_conformal_sphere_map("EXEC_DEFAULT", True) == {"FINISHED"}, "mapped")
        check(len(bpy.data.objects[name].data.uv_layers) == before + 1, "UV layer added")
        check(bpy.data.objects.get(name + " Layered Sphere") is not None, "sphere added")
        bpy.ops.ed.undo()
        check(len(bpy.data.objects[name].data.uv_layers) == before, "undo removed the UV layer")
        check(bpy.data.objects.get(name + " Layered Sphere") is None, "undo removed the sphere object")
        # A CAD plate whose triangles cannot carry the map: undo removes the added vertices too.
        plate = cad_plate()
        bpy.ops.ed.undo_push(message="Add CAD Plate")  # made through the data API: its own step
        plate_name = plate.name
        vertices, faces = len(plate.data.vertices), len(plate.data.polygons)
        check(bpy.ops.mesh.meromorph_conformal_sphere_map("EXEC_DEFAULT", True) == {"FINISHED"},
              "plate mapped")
        check(len(bpy.data.objects[plate_name].data.vertices) > vertices, "vertices added")
        bpy.ops.ed.undo()
        plate = bpy.data.objects[plate_name]
        check((len(plate.data.vertices), len(plate.data.polygons)) == (vertices, faces),
              "undo removed the added vertices and faces")
        torus = bpy.data.objects[name]
        bpy.ops.object.select_all(action="DESELECT")
        torus.select_set(True)
        bpy.context.view_layer.objects.active = torus
        check(bpy.ops.object.meromorph_conformal_sphere_remesh("EXEC_DEFAULT", True) == {"FINISHED"},
              "remeshed")
        check(bpy.data.objects.get(name + " Remeshed") is not None, "remeshed object added")
        bpy.ops.ed.undo()
        check(bpy.data.objects.get(name + " Remeshed") is None, "undo removed the remeshed object")
    print(summary())


try:
    main()
except Exception:
    import traceback
    traceback.print_exc()
    sys.exit(1)
bpy.ops.wm.quit_blender()
