# Shared by the Blender test scripts: counted checks, installing the built add-on zip, and
# adding an OFF file as the active object.
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


def add_off(path, name):
    with open(path) as stream:
        lines = [l.split("#")[0].split() for l in stream]
    lines = [l for l in lines if l]
    start = 1 if lines[0] == ["OFF"] else 0
    nv, nf = int(lines[start][0]), int(lines[start][1])
    vertices = [tuple(map(float, l[:3])) for l in lines[start + 1:start + 1 + nv]]
    faces = [tuple(map(int, l[1:1 + int(l[0])])) for l in lines[start + 1 + nv:start + 1 + nv + nf]]
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices, [], faces)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.collection.objects.link(obj)
    activate(obj)
    return obj


def activate(obj):
    bpy.ops.object.select_all(action="DESELECT")
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj
