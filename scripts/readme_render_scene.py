# The README pictures' light, camera and headless Cycles render (CPU), shared by
# render_readme_picture.py and render_remesh_picture.py: in, the scene as built; out, OUT as PNG.
import math

import bpy


def render(out):
    bpy.ops.object.light_add(type="SUN",
                             rotation=(math.radians(40), math.radians(20), math.radians(30)))
    bpy.context.active_object.data.energy = 4.0
    bpy.ops.object.camera_add(location=(0, -9.5, 2.6), rotation=(math.radians(75), 0, 0))
    scene = bpy.context.scene
    scene.camera = bpy.context.active_object
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 32
    scene.cycles.use_denoising = False
    scene.render.resolution_x, scene.render.resolution_y = 800, 400
    scene.world = bpy.data.worlds.new("World")
    scene.world.color = (0.9, 0.9, 0.92)
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)
    print("wrote", out)
