# meromorph for Blender: conformal maps of closed meshes of any genus onto the sphere.
#
# In:  the active mesh object (quads and n-gons through its loop triangles; the mesh as it is,
#      without modifiers).
# Out (Object > Conformal Sphere Remesh): a new object "<name> Remeshed", the surface resampled
#      through its layered sphere, with an integer attribute "layer" and a vertex group
#      "branch_points".
# Out (Conformal Sphere Map): a UV layer with seam-correct per-loop coordinates, a new object "<name> Layered Sphere"
#      (the same vertices on the sphere, radius by layer, an integer attribute "layer" and a vertex
#      group "branch_points"), the branch vertices selected, and a report. All the mathematics is
#      in libmeromorph (shipped inside this add-on); this file only moves data.
bl_info = {
    "name": "meromorph: Conformal Sphere Map",
    "author": "meromorph developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > UV > Conformal Sphere Map (Edit Mode, U), Object > Conformal Sphere Map "
                "and Object > Conformal Sphere Remesh",
    "description": "Conformal map of a closed mesh of any genus onto the sphere: UVs, branch "
                   "points and a layered sphere",
    "doc_url": "",
    "category": "UV",
    "support": "COMMUNITY",
}

if "bpy" in locals():
    import importlib
    importlib.reload(library)  # noqa: F821
    importlib.reload(remedies)  # noqa: F821
    importlib.reload(operator)  # noqa: F821
    importlib.reload(remesh_operator)  # noqa: F821

import bpy

from . import library, operator, remedies, remesh_operator  # noqa: F401


def menu_entry(self, context):
    self.layout.operator(operator.MESH_OT_conformal_sphere_map.bl_idname,
                         text="Conformal Sphere Map")


def remesh_menu_entry(self, context):
    self.layout.operator(remesh_operator.OBJECT_OT_conformal_sphere_remesh.bl_idname,
                         text="Conformal Sphere Remesh")


def register():
    bpy.utils.register_class(operator.MESH_OT_conformal_sphere_map)
    bpy.utils.register_class(remesh_operator.OBJECT_OT_conformal_sphere_remesh)
    bpy.types.VIEW3D_MT_uv_map.append(menu_entry)
    bpy.types.VIEW3D_MT_object.append(menu_entry)
    bpy.types.VIEW3D_MT_object.append(remesh_menu_entry)


def unregister():
    bpy.types.VIEW3D_MT_object.remove(remesh_menu_entry)
    bpy.utils.unregister_class(remesh_operator.OBJECT_OT_conformal_sphere_remesh)
    bpy.types.VIEW3D_MT_object.remove(menu_entry)
    bpy.types.VIEW3D_MT_uv_map.remove(menu_entry)
    bpy.utils.unregister_class(operator.MESH_OT_conformal_sphere_map)
