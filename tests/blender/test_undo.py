# Undo in the real Blender with a window (undo needs one): xvfb-run -a blender --factory-startup
# --python-exit-code 1 --python test_undo.py -- ADDON_ZIP
import sys

import addon_utils
import bpy

ADDON_ZIP = sys.argv[sys.argv.index("--") + 1]
checks = 0


def check(condition, message):
    global checks
    if not condition:
        raise AssertionError(message)
    checks += 1


def raise_it(error):
    raise error


def main():
    bpy.ops.preferences.addon_install(filepath=ADDON_ZIP, overwrite=True)
    addon_utils.enable("meromorph_blender", default_set=True, handle_error=raise_it)
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
    print("%d passed, 0 failed" % checks)


try:
    main()
except Exception:
    import traceback
    traceback.print_exc()
    sys.exit(1)
bpy.ops.wm.quit_blender()
