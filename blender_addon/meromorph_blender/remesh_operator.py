# The operator "Conformal Sphere Remesh": the active mesh in, a new object beside it out (the
# surface resampled through its layered sphere by libmeromorph), with each vertex's layer as the
# integer attribute "layer" and the branch vertices in the vertex group "branch_points".
import bpy
import numpy as np
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty

from . import library, remedies
from .operator import ActiveMeshOperator, add_mesh_object, mesh_arrays


class OBJECT_OT_conformal_sphere_remesh(ActiveMeshOperator, bpy.types.Operator):
    """Remesh the active mesh through its conformal map onto the (layered) sphere: a new object
    of the same genus, with regular triangles and vertices where the map branches"""
    bl_idname = "object.meromorph_conformal_sphere_remesh"
    bl_label = "Conformal Sphere Remesh"
    bl_options = {"REGISTER", "UNDO"}

    size_by: EnumProperty(
        name="Size", default="VERTICES",
        items=[("VERTICES", "Vertex Count", "About a number of vertices"),
               ("EDGE_LENGTH", "Edge Length", "About an edge length"),
               ("MAX_ERROR", "Max Distance", "Within a distance of the surface, with few vertices")])
    target_vertices: IntProperty(name="Vertices", default=0, min=0,
                                 description="About how many vertices the new mesh should have "
                                             "(0: as many as the mesh has)")
    edge_length: FloatProperty(name="Edge Length", default=0.05, min=1e-9, subtype="DISTANCE",
                               description="About this edge length, in the mesh's units")
    max_error: FloatProperty(name="Max Distance (%)", default=0.5, min=1e-4, max=50.0,
                             description="The new mesh within this distance of the surface both "
                                         "ways, in percent of the bounding box diagonal")
    area_correct: BoolProperty(name="Even Out the Sampling", default=True,
                               description="First move the map so the surface's area spreads "
                                           "most evenly over the sphere")

    back_to_edit_mode = False  # the new object is active, in Object Mode

    def draw(self, context):
        layout = self.layout
        layout.prop(self, "size_by")
        if self.size_by == "VERTICES":
            layout.prop(self, "target_vertices")
        elif self.size_by == "EDGE_LENGTH":
            layout.prop(self, "edge_length")
        else:
            layout.prop(self, "max_error")
        layout.prop(self, "area_correct")

    def run(self, context, obj, progress):
        positions, triangles, _ = mesh_arrays(obj.data)
        try:
            result = library.remesh(
                positions, triangles, target_vertices=self.target_vertices,
                area_correct=self.area_correct, progress=progress,
                edge_length=self.edge_length if self.size_by == "EDGE_LENGTH" else 0.0,
                max_error=self.max_error / 100 if self.size_by == "MAX_ERROR" else 0.0)
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
