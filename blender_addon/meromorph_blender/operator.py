# The operator "Conformal Sphere Map": Blender's mesh in, UVs, selection and a layered sphere out.
import time

import bmesh
import bpy
import numpy as np
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty

from . import library, remedies


def mesh_arrays(mesh):
    """Vertex positions and loop triangles of `mesh` (as it is, without modifiers)."""
    mesh.calc_loop_triangles()
    positions = np.empty(3 * len(mesh.vertices), dtype=np.float32)
    mesh.vertices.foreach_get("co", positions)
    triangles = np.empty(3 * len(mesh.loop_triangles), dtype=np.int32)
    mesh.loop_triangles.foreach_get("vertices", triangles)
    loops = np.empty(3 * len(mesh.loop_triangles), dtype=np.int32)
    mesh.loop_triangles.foreach_get("loops", loops)
    return positions, triangles, loops


def loop_uvs(mesh, loops, corner_uv):
    """Per-loop UVs from the per-triangle-corner ones; a polygon split into several triangles is
    kept on one side of the seam (its corners lifted by one turn together)."""
    uv = np.zeros(2 * len(mesh.loops))
    corner_uv = corner_uv.reshape(-1, 2)
    uv.reshape(-1, 2)[loops] = corner_uv
    per_loop = uv.reshape(-1, 2)
    for polygon in mesh.polygons:
        if polygon.loop_total <= 3:
            continue
        span = slice(polygon.loop_start, polygon.loop_start + polygon.loop_total)
        u = per_loop[span, 0] % 1.0
        if u.max() - u.min() > 0.5:
            u = np.where(u < 0.5, u + 1.0, u)
        per_loop[span, 0] = u
    return uv


def add_written_vertices(mesh, result):
    """The vertices the map needed added to `mesh` (after its own), and the polygons whose
    triangles they cut replaced by the written surface's triangles (with the polygon's material and
    shading). Returns the mesh's loop triangles' loops and, per loop, the written surface's
    triangle corner it is (an index into the result's per-corner arrays)."""
    polygon_of = np.empty(len(mesh.loop_triangles), dtype=np.int32)
    mesh.loop_triangles.foreach_get("polygon_index", polygon_of)
    surface = result["surface_triangles"].reshape(-1, 3)
    source_polygon = polygon_of[result["surface_source"]]
    replaced = np.unique(polygon_of[np.unique(result["surface_source"][len(polygon_of):])])
    looks = {int(p): (mesh.polygons[int(p)].material_index, mesh.polygons[int(p)].use_smooth)
             for p in replaced}
    bm = bmesh.new()
    bm.from_mesh(mesh)
    bm.faces.ensure_lookup_table()
    bmesh.ops.delete(bm, geom=[bm.faces[int(p)] for p in replaced], context="FACES_ONLY")
    for co in result["added_xyz"].reshape(-1, 3):
        bm.verts.new(co)
    bm.verts.ensure_lookup_table()
    for k in np.flatnonzero(np.isin(source_polygon, replaced)):
        face = bm.faces.new([bm.verts[int(v)] for v in surface[k]])
        face.material_index, face.smooth = looks[int(source_polygon[k])]
    bm.to_mesh(mesh)
    bm.free()
    mesh.update()
    mesh.calc_loop_triangles()
    triangles = np.empty(3 * len(mesh.loop_triangles), dtype=np.int32)
    mesh.loop_triangles.foreach_get("vertices", triangles)
    loops = np.empty(3 * len(mesh.loop_triangles), dtype=np.int32)
    mesh.loop_triangles.foreach_get("loops", loops)
    corner_of = {}
    for k, corners in enumerate(surface.tolist()):
        for c, v in enumerate(corners):
            corner_of[(tuple(sorted(corners)), v)] = 3 * k + c
    triangles = triangles.reshape(-1, 3).tolist()
    order = np.array([corner_of[(tuple(sorted(t)), v)] for t in triangles for v in t])
    return loops, order


def add_branch_group(obj, vertices):
    """The vertex group "branch_points" of `obj`, holding `vertices`."""
    group = obj.vertex_groups.new(name="branch_points")
    if len(vertices):
        group.add([int(v) for v in vertices], 1.0, "REPLACE")
    return group


def add_mesh_object(context, beside, name, positions, polygons, point_attributes, branch):
    """A new object named `name` beside `beside` (same placement), from flat positions and
    polygons, with integer per-vertex attributes and the branch vertices as a vertex group."""
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(positions.reshape(-1, 3).tolist(), [], polygons)
    for attribute_name, values in point_attributes.items():
        mesh.attributes.new(attribute_name, "INT", "POINT").data.foreach_set("value", values)
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    context.collection.objects.link(obj)
    obj.matrix_world = beside.matrix_world.copy()
    add_branch_group(obj, branch)
    return obj


class ActiveMeshOperator:
    """What both operators share: they need an active mesh object (in Object Mode while they
    run) and report progress to the window manager."""

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        if obj is None or obj.type != "MESH":
            cls.poll_message_set("Select a mesh object first")
            return False
        return True

    def execute(self, context):
        obj = context.active_object
        if obj is None or obj.type != "MESH":
            self.report({"ERROR"}, "No active mesh: select a mesh object first")
            return {"CANCELLED"}
        if len(obj.data.polygons) < 4:
            self.report({"ERROR"}, "'%s' has %d faces: a closed surface needs at least 4"
                        % (obj.name, len(obj.data.polygons)))
            return {"CANCELLED"}
        was_editing = obj.mode == "EDIT"
        if was_editing:
            bpy.ops.object.mode_set(mode="OBJECT")
        window_manager = context.window_manager
        window_manager.progress_begin(0, 100)

        def progress(fraction):
            window_manager.progress_update(int(100 * fraction))
            return 1

        try:
            return self.run(context, obj, progress)
        finally:
            window_manager.progress_end()
            if was_editing and self.back_to_edit_mode:
                bpy.ops.object.mode_set(mode="EDIT")


class MESH_OT_conformal_sphere_map(ActiveMeshOperator, bpy.types.Operator):
    """Map the active mesh conformally onto the sphere: UVs, branch points, layered sphere"""
    bl_idname = "mesh.meromorph_conformal_sphere_map"
    bl_label = "Conformal Sphere Map"
    bl_options = {"REGISTER", "UNDO"}

    uv_kind: EnumProperty(
        name="UV Kind", default="SPHERICAL",
        items=[("SPHERICAL", "Spherical", "Longitude and latitude on the sphere"),
               ("STEREOGRAPHIC", "Stereographic", "The plane seen from the north pole")])
    mobius: BoolProperty(name="Moebius Normalization", default=True,
                         description="Centre the map so the area spreads evenly over the sphere")
    origin: IntProperty(name="Genus 1 Pole Vertex", default=-1, min=-1,
                        description="Torus: the vertex at the double pole (-1: automatic)")
    pole_face: IntProperty(name="Genus 0 Pole Face", default=-1, min=-1,
                           description="Sphere-like meshes: the triangle (of the mesh's loop "
                                       "triangles) mapped around the north pole (-1: automatic)")
    form_i: IntProperty(name="Form i", default=-1, min=-1,
                        description="Genus 2 or more: the map is (psi_i + psi_j) / (psi_i - psi_j); "
                                    "-1 and -1: a generic pair mixing all forms")
    form_j: IntProperty(name="Form j", default=-1, min=-1, description="Genus 2 or more: j")
    uv_name: bpy.props.StringProperty(name="UV Map", default="Conformal Sphere")
    create_sphere: BoolProperty(name="Create Layered Sphere", default=True,
                                description="Add an object with the mesh on the sphere, by layer")
    layer_gap: FloatProperty(name="Layer Gap", default=0.2, min=0.0, max=10.0,
                             description="Layer k lies on the sphere of radius 1 + gap * k")
    select_branch: BoolProperty(name="Select Branch Vertices", default=True)
    close_holes: BoolProperty(name="Close Holes", default=True,
                              description="Close every hole for the computation only: the mesh "
                                          "keeps its faces, the holes show as gaps on the sphere")
    split_nonmanifold: BoolProperty(
        name="Split Non-Manifold Spots", default=True,
        description="Take non-manifold vertices and edges apart for the computation: the mesh "
                    "keeps its vertices (UVs per face corner); the layered sphere gets the split "
                    "vertices")
    strict: BoolProperty(
        name="Strict", default=False,
        description="Refuse the mesh, naming the problem, instead of dealing with it for the "
                    "computation: holes and non-manifold spots (whatever the two options above "
                    "say), seam duplicates (welded), doubled faces, faces that use a vertex "
                    "twice and loose vertices (left out; the mesh keeps them all)")
    pack_uv: BoolProperty(name="Pack Parts' UVs", default=False,
                          description="Several parts: each part's UVs in its own cell of the "
                                      "unit square instead of each filling it")
    add_vertices: BoolProperty(
        name="Add Vertices Where Needed", default=True,
        description="Where the mesh's triangles cannot carry the map without turning some over "
                    "(slivers, coarse faces at branch points), add the vertices it needs and cut "
                    "the faces they lie on (undo removes them); off: keep the mesh as it is and "
                    "report the map as not valid")

    back_to_edit_mode = True

    def run(self, context, obj, progress):
        mesh = obj.data
        started = time.time()
        positions, triangles, loops = mesh_arrays(mesh)
        try:
            result = library.parameterize(
                positions, triangles, uv_kind=0 if self.uv_kind == "SPHERICAL" else 1,
                mobius=self.mobius, origin_vertex=self.origin, pole_face=self.pole_face,
                form_pair=(self.form_i, self.form_j), layer_gap=self.layer_gap,
                close_holes=self.close_holes, split_nonmanifold=self.split_nonmanifold,
                pack_uv=self.pack_uv and self.uv_kind == "SPHERICAL", strict=self.strict,
                add_vertices=self.add_vertices, progress=progress)
        except library.MeromorphError as error:
            self.report({"ERROR"}, "'%s' cannot be mapped: %s (vertex numbers are Blender's)"
                        % (obj.name, remedies.with_remedies(str(error), error.remedies)))
            return {"CANCELLED"}

        order = np.arange(len(result["corner_uv"]) // 2)  # loop triangle corners = the result's
        added = len(result["added_xyz"]) // 3
        if added:
            loops, order = add_written_vertices(mesh, result)
        layer = mesh.uv_layers.get(self.uv_name) or mesh.uv_layers.new(name=self.uv_name)
        layer.data.foreach_set("uv", loop_uvs(mesh, loops, result["corner_uv"].reshape(-1, 2)[order]))
        mesh.uv_layers.active = layer

        branch = result["branch_vertices"]
        if self.select_branch:
            selected = np.zeros(len(mesh.vertices), dtype=bool)
            selected[branch] = True
            mesh.vertices.foreach_set("select", selected)
            mesh.polygons.foreach_set("select", np.zeros(len(mesh.polygons), dtype=bool))
            mesh.edges.foreach_set("select", np.zeros(len(mesh.edges), dtype=bool))
        mesh.update()

        if self.create_sphere:
            self.make_sphere_object(context, obj, result, order)

        elapsed = time.time() - started
        self.report({"INFO"}, "%s: genus %d, degree %d, %d branch points%s; away from them: "
                    "angle error %.2f deg, quasi-conformal mean %.2f (95th percentile %.2f); %.2f s%s"
                    % (obj.name, result["genus"], result["degree"], len(branch),
                       ", %d vertices added where the faces could not carry the map" % added
                       if added else "",
                       result["angle_error"], result["quasi_conformal_mean"],
                       result["quasi_conformal_p95"], elapsed,
                       "" if result["valid"]
                       else "; WARNING: not a valid map on this triangulation: "
                       + result["invalid_reasons"] + ". What to do: "
                       + remedies.advice_words(result["advice"])))
        return {"FINISHED"}

    def make_sphere_object(self, context, obj, result, order):
        mesh = obj.data
        name = obj.name + " Layered Sphere"
        # Each polygon on the sphere's vertices: a loop's sphere vertex is its triangle corner's
        # (the input's vertex, or its copy where a non-manifold spot was split).
        mesh.calc_loop_triangles()
        loops = np.empty(3 * len(mesh.loop_triangles), dtype=np.int32)
        mesh.loop_triangles.foreach_get("loops", loops)
        loop_vertex = np.empty(len(mesh.loops), dtype=np.int64)
        mesh.loops.foreach_get("vertex_index", loop_vertex)
        loop_vertex[loops] = result["sphere_triangles"][order]
        polygons = [loop_vertex[p.loop_start:p.loop_start + p.loop_total].tolist()
                    for p in mesh.polygons]
        return add_mesh_object(context, obj, name, result["sphere_layered"], polygons,
                               {"layer": result["sphere_layer"],
                                "component": result["sphere_component"],
                                "source_vertex": result["sphere_source"]},
                               np.flatnonzero(result["sphere_branch"]))
