# The operator "Conformal Sphere Remesh": the active mesh in, a new object beside it out (the
# surface resampled through its layered sphere by libmeromorph), with each vertex's layer as the
# integer attribute "layer" and the branch vertices in the vertex group "branch_points".
import bpy
import numpy as np
from bpy.props import BoolProperty, IntProperty

from . import library, remedies
from .operator import ActiveMeshOperator, add_mesh_object, mesh_arrays


class OBJECT_OT_conformal_sphere_remesh(ActiveMeshOperator, bpy.types.Operator):
    """Remesh the active mesh through its conformal map onto the (layered) sphere: a new object
    of the same genus, with regular triangles and vertices where the map branches"""
    bl_idname = "object.meromorph_conformal_sphere_remesh"
    bl_label = "Conformal Sphere Remesh"
    bl_options = {"REGISTER", "UNDO"}

    target_vertices: IntProperty(name="Vertices", default=0, min=0,
                                 description="About how many vertices the new mesh should have "
                                             "(0: as many as the mesh has)")
    area_correct: BoolProperty(name="Even Out the Sampling", default=True,
                               description="First move the map so the surface's area spreads "
                                           "most evenly over the sphere")

    back_to_edit_mode = False  # the new object is active, in Object Mode

    def run(self, context, obj, progress):
        positions, triangles, _ = mesh_arrays(obj.data)
        try:
            result = library.remesh(positions, triangles, target_vertices=self.target_vertices,
                                    area_correct=self.area_correct, progress=progress)
        except library.MeromorphError as error:
            self.report({"ERROR"}, "'%s' cannot be remeshed: %s (vertex numbers are Blender's)"
                        % (obj.name, remedies.with_remedies(str(error), error.remedies)))
            return {"CANCELLED"}

        name = obj.name + " Remeshed"
        remeshed = add_mesh_object(context, obj, name, result["positions"],
                                   result["triangles"].reshape(-1, 3).tolist(),
                                   {"layer": result["layer"]}, np.flatnonzero(result["branch"] >= 2))
        bpy.ops.object.select_all(action="DESELECT")
        remeshed.select_set(True)
        context.view_layer.objects.active = remeshed
        self.report({"INFO"}, result["summary"].replace("the mesh", obj.name, 1))
        return {"FINISHED"}
