# meromorph for Blender: conformal maps of closed meshes of any genus onto the sphere.
#
# In:  the active mesh object (quads and n-gons through its loop triangles; the mesh as it is,
#      without modifiers).
# Out (Object > Conformal Sphere Remesh): a new object "<name> Remeshed", the surface resampled
#      through its layered sphere, with an integer attribute "layer" and a vertex group
#      "branch_points".
# Out (Object > Link/Transfer Data > Transfer Through the Sphere): the selected mesh's UV maps,
#      colour and float attributes on the active mesh (closed, the same genus, 0, 1 or 2), read at
#      corresponding points through the two conformal maps; optionally a shape key (a morph).
# Out (Conformal Sphere Map): a UV layer with seam-correct per-loop coordinates, a new object "<name> Layered Sphere"
#      (the same vertices on the sphere, radius by layer, an integer attribute "layer" and a vertex
#      group "branch_points"), the branch vertices selected, and a report. All the mathematics is
#      in libmeromorph (shipped inside this add-on); this file only moves data.
bl_info = {
    "name": "meromorph: Conformal Sphere Map",
    "author": "meromorph developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > UV > Conformal Sphere Map (Edit Mode, U), Object > Conformal Sphere Map, "
                "Object > Conformal Sphere Remesh, Object > Link/Transfer Data > Transfer Through "
                "the Sphere",
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
    importlib.reload(transfer_operator)  # noqa: F821

import bpy

from . import library, operator, remedies, remesh_operator, transfer_operator  # noqa: F401


def menu_entry(self, context):
    self.layout.operator(operator.MESH_OT_conformal_sphere_map.bl_idname,
                         text="Conformal Sphere Map")


def remesh_menu_entry(self, context):
    self.layout.operator(remesh_operator.OBJECT_OT_conformal_sphere_remesh.bl_idname,
                         text="Conformal Sphere Remesh")


def transfer_menu_entry(self, context):
    self.layout.operator(transfer_operator.OBJECT_OT_conformal_transfer.bl_idname,
                         text="Transfer Through the Sphere")


def register():
    bpy.utils.register_class(operator.MESH_OT_conformal_sphere_map)
    bpy.utils.register_class(remesh_operator.OBJECT_OT_conformal_sphere_remesh)
    bpy.utils.register_class(transfer_operator.OBJECT_OT_conformal_transfer)
    bpy.types.VIEW3D_MT_make_links.append(transfer_menu_entry)
    bpy.types.VIEW3D_MT_uv_map.append(menu_entry)
    bpy.types.VIEW3D_MT_object.append(menu_entry)
    bpy.types.VIEW3D_MT_object.append(remesh_menu_entry)


def unregister():
    bpy.types.VIEW3D_MT_make_links.remove(transfer_menu_entry)
    bpy.utils.unregister_class(transfer_operator.OBJECT_OT_conformal_transfer)
    bpy.types.VIEW3D_MT_object.remove(remesh_menu_entry)
    bpy.utils.unregister_class(remesh_operator.OBJECT_OT_conformal_sphere_remesh)
    bpy.types.VIEW3D_MT_object.remove(menu_entry)
    bpy.types.VIEW3D_MT_uv_map.remove(menu_entry)
    bpy.utils.unregister_class(operator.MESH_OT_conformal_sphere_map)
