# Shared by the Blender test scripts: counted checks and installing the built add-on zip.
import addon_utils
import bpy

passed = 0


def check(condition, message):
    global passed
    if not condition:
        raise AssertionError(message)
    passed += 1


def install_addon(zip_path):
    """Install the zip into BLENDER_USER_SCRIPTS and enable it; any error is raised."""
    def raise_it(error):
        raise error

    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    addon_utils.enable("meromorph_blender", default_set=True, handle_error=raise_it)


def summary():
    return "%d passed, 0 failed" % passed
