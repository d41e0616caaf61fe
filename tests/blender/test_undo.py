# Undo in the real Blender with a window (undo needs one): xvfb-run -a blender --factory-startup
# --python-exit-code 1 --python test_undo.py -- ADDON_ZIP MEROMORPH_CLI
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import add_off, check, install_addon, summary  # noqa: E402

ADDON_ZIP, CLI = sys.argv[sys.argv.index("--") + 1:][:2]


def cad_plate():
    """A plate with a hole as CAD programs export it (meromorph make cad), the active object."""
    subprocess.run([CLI, "make", "cad", "--holes", "1", "--segments", "64", "--thickness", "0.05",
                    "-o", "cad_plate.off"], check=True, stdout=subprocess.DEVNULL)
    return add_off("cad_plate.off", "CAD Plate")


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
        # Transfer Through the Sphere onto a copy of the torus without UVs (with a shape key):
        # undo takes the copied UV map and the shape key away again.
        torus = bpy.data.objects[name]
        copy = torus.copy()
        copy.data = torus.data.copy()
        copy.name = "Receiving Torus"
        bpy.context.collection.objects.link(copy)
        while copy.data.uv_layers:
            copy.data.uv_layers.remove(copy.data.uv_layers[0])
        bpy.ops.ed.undo_push(message="Add Receiving Torus")
        bpy.ops.object.select_all(action="DESELECT")
        torus.select_set(True)
        copy.select_set(True)
        bpy.context.view_layer.objects.active = copy
        check(bpy.ops.object.meromorph_conformal_transfer("EXEC_DEFAULT", True, shape_key=True) ==
              {"FINISHED"}, "transferred")
        copy = bpy.data.objects["Receiving Torus"]
        check(len(copy.data.uv_layers) > 0 and copy.data.shape_keys is not None,
              "UV map and shape key copied")
        bpy.ops.ed.undo()
        copy = bpy.data.objects["Receiving Torus"]
        check(len(copy.data.uv_layers) == 0 and copy.data.shape_keys is None,
              "undo removed the copied UV map and the shape key")
    print(summary())


try:
    main()
except Exception:
    import traceback
    traceback.print_exc()
    sys.exit(1)
bpy.ops.wm.quit_blender()
