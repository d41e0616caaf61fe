# The operator "Transfer Through the Sphere": the UV maps, colour attributes and float attributes
# of the selected mesh carried onto the active one (and, optionally, a shape key that morphs it
# onto the selected one), each receiving vertex and face corner reading the other mesh at its
# corresponding point, found by libmeromorph through the two surfaces' conformal spheres (genus
# 0), flat tori (genus 1) or canonical maps (genus 2), whatever their placement, size, pose or
# triangulation. (Blender's Transfer Mesh Data reads the nearest point in space instead.) Values
# per face corner (UVs with seams) are read per receiving triangle from the one triangle of the
# other mesh that holds its centre, so a triangle never straddles a seam.
import time

import bpy
import numpy as np
from bpy.props import BoolProperty

from . import library, remedies
from .operator import ActiveMeshOperator, mesh_arrays

FLOAT_TYPES = {"FLOAT": ("value", 1), "FLOAT2": ("vector", 2), "FLOAT_VECTOR": ("vector", 3)}


class Carrier:
    """The receiving mesh's match onto the donor: reads values of the donor (per vertex or per face
    corner) at the receiver's vertices or face corners."""

    def __init__(self, receiver_loops, receiver_loop_count, donor_triangles, donor_loops, match):
        """Loop triangles as mesh_arrays gives them: their vertices and loops, 3 per triangle."""
        self.donor_vertices = donor_triangles.reshape(-1, 3)
        self.donor_loops = donor_loops.reshape(-1, 3)
        self.receiver_loops = receiver_loops.reshape(-1, 3)
        self.receiver_loop_count = receiver_loop_count
        self.match = match

    def per_donor_corner(self, values, domain):
        """(t, 3, width): the values at the donor mesh's loop triangle corners."""
        return values[self.donor_loops] if domain == "CORNER" else values[self.donor_vertices]

    def read(self, values, domain):
        """The donor mesh's values (per vertex or per loop, (n, width)) at the receiver's vertices
        (domain POINT) or loops (domain CORNER)."""
        corners = self.per_donor_corner(values, domain)
        if domain == "POINT":
            face = self.match["vertex_face"]
            out = np.einsum("vj,vjw->vw", self.match["vertex_weights"],
                            corners[np.maximum(face, 0)])
            out[face < 0] = 0
            return out
        face = self.match["triangle_face"]
        at_corners = np.einsum("tkj,tjw->tkw", self.match["triangle_weights"],
                               corners[np.maximum(face, 0)])
        at_corners[face < 0] = 0
        out = np.zeros((self.receiver_loop_count, values.shape[1]))
        out[self.receiver_loops.reshape(-1)] = at_corners.reshape(-1, values.shape[1])
        return out


def landmark_pairs(receiver, donor):
    """(receiver vertex, donor vertex) for each vertex group of the same name on both objects
    that holds one vertex on each."""
    def members(obj, index):
        return [v.index for v in obj.data.vertices
                if any(g.group == index and g.weight > 0 for g in v.groups)]
    pairs = []
    for group in receiver.vertex_groups:
        other = donor.vertex_groups.get(group.name)
        if other is None:
            continue
        mine, theirs = members(receiver, group.index), members(donor, other.index)
        if len(mine) == 1 and len(theirs) == 1:
            pairs.append((mine[0], theirs[0]))
    return pairs


def attribute_values(attribute, key, width, count):
    values = np.empty(count * width, dtype=np.float64)
    attribute.data.foreach_get(key, values)
    return values.reshape(count, width)


def domain_size(mesh, domain):
    return len(mesh.loops) if domain == "CORNER" else len(mesh.vertices)


class OBJECT_OT_conformal_transfer(ActiveMeshOperator, bpy.types.Operator):
    """Copy the UV maps, colors and attributes of the selected mesh to the active one, each point
    reading its corresponding point through the conformal maps (closed meshes of the same genus:
    0, 1 or 2), whatever their placement, size, pose or triangulation"""
    bl_idname = "object.meromorph_conformal_transfer"
    bl_label = "Transfer Through the Sphere"
    bl_options = {"REGISTER", "UNDO"}

    uvs: BoolProperty(name="UV Maps", default=True,
                      description="Every UV map of the mesh copied from")
    colors: BoolProperty(name="Color Attributes", default=True,
                         description="Every color attribute of the mesh copied from (per vertex "
                                     "or per face corner)")
    attributes: BoolProperty(name="Float Attributes", default=True,
                             description="The other float, 2D and 3D vector attributes of the "
                                         "mesh copied from, per vertex or per face corner")
    shape_key: BoolProperty(name="Shape Key", default=False,
                            description="Also add a shape key, named after the mesh copied from, "
                                        "that puts each vertex on its matched point there: a "
                                        "morph from one surface to the other")
    landmarks: BoolProperty(name="Landmarks from Vertex Groups", default=True,
                            description="Vertex groups of the same name on both meshes that hold "
                                        "one vertex each pair those vertices (a sphere-like mesh "
                                        "needs three pairs, a torus-like one one or more): for "
                                        "symmetric shapes, which otherwise may be matched turned")

    @staticmethod
    def donor_of(context):
        """The one other selected mesh, or None."""
        others = [o for o in context.selected_objects
                  if o.type == "MESH" and o != context.active_object]
        return others[0] if len(others) == 1 else None

    back_to_edit_mode = False

    @classmethod
    def poll(cls, context):
        if not super().poll(context):
            return False
        if cls.donor_of(context) is None:
            cls.poll_message_set("Select the mesh to copy from, then the one that receives "
                                 "(active)")
            return False
        return True

    def run(self, context, receiver, progress):
        """ActiveMeshOperator's frame (Object Mode, progress) around the transfer onto the active
        mesh."""
        donor = self.donor_of(context)
        if donor is None:
            self.report({"ERROR"}, "Select the mesh to copy from, then the mesh that receives "
                                   "(active)")
            return {"CANCELLED"}
        started = time.time()
        positions, triangles, loops = mesh_arrays(receiver.data)
        donor_positions, donor_triangles, donor_loops = mesh_arrays(donor.data)
        pairs = landmark_pairs(receiver, donor) if self.landmarks else []
        try:
            match = library.match(positions, triangles, donor_positions, donor_triangles,
                                  landmarks=pairs, progress=progress)
        except library.MeromorphError as error:
            self.report({"ERROR"}, "'%s' cannot be matched with '%s': %s (vertex numbers are "
                        "Blender's)" % (receiver.name, donor.name,
                                        remedies.with_remedies(str(error), error.remedies)))
            return {"CANCELLED"}
        copied = self.carry(donor.data, receiver.data,
                            Carrier(loops, len(receiver.data.loops), donor_triangles, donor_loops,
                                    match))
        if self.shape_key:
            self.add_shape_key(receiver, donor, donor_positions.reshape(-1, 3),
                               donor_triangles.reshape(-1, 3), match)
            copied.append("shape key '%s'" % donor.name)
        report = match["report"]
        alternatives = report["alignment"]["alternatives"]
        self.report({"INFO"}, "'%s': %s from '%s' (genus %d%s; matched mesh angle error %.2f deg, "
                    "%d folded faces)%s (%.2f s)" % (
                        receiver.name, ", ".join(copied) or "nothing to copy", donor.name,
                        report["genus"], ", %d landmarks" % len(pairs) if pairs else "",
                        report["matched_mesh"]["angle_error_mean_degrees"],
                        report["matched_mesh"]["folded_faces"],
                        "; WARNING: %d other alignments fit almost as well (a symmetric "
                        "surface): give landmarks, vertex groups of the same name on both meshes "
                        "holding one vertex each" % len(alternatives)
                        if alternatives and not pairs else "", time.time() - started))
        return {"FINISHED"}

    @staticmethod
    def add_shape_key(receiver, donor, donor_positions, donor_triangles, match):
        """A shape key on `receiver` named after `donor`: each vertex at its matched point on the
        donor, placed where the donor is (through both objects' transforms), for morphing."""
        face = np.maximum(match["vertex_face"], 0)
        corners = donor_positions[donor_triangles[face]]  # (n, 3, 3)
        points = np.einsum("vj,vjc->vc", match["vertex_weights"], corners)
        to_receiver = np.array(receiver.matrix_world.inverted() @ donor.matrix_world)
        points = points @ to_receiver[:3, :3].T + to_receiver[:3, 3]
        if receiver.data.shape_keys is None:
            receiver.shape_key_add(name="Basis", from_mix=False)
        key = receiver.data.shape_keys.key_blocks.get(donor.name) or \
            receiver.shape_key_add(name=donor.name, from_mix=False)
        key.data.foreach_set("co", points.astype(np.float32).ravel())
        receiver.data.update()

    def carry(self, source, receiver, carrier):
        """Copies what the options ask from mesh `source` to mesh `receiver`; returns what."""
        copied = []
        if self.uvs:
            for layer in source.uv_layers:
                values = np.empty(2 * len(source.loops))
                layer.data.foreach_get("uv", values)
                out = receiver.uv_layers.get(layer.name) or receiver.uv_layers.new(name=layer.name)
                out.data.foreach_set("uv", carrier.read(values.reshape(-1, 2), "CORNER").ravel())
                copied.append("UV map '%s'" % layer.name)
        if self.colors:
            for attribute in source.color_attributes:
                if attribute.domain not in ("POINT", "CORNER"):
                    continue
                values = attribute_values(attribute, "color", 4,
                                          domain_size(source, attribute.domain))
                out = self.receiving(receiver, attribute.name, attribute.data_type,
                                     attribute.domain, colors=True)
                out.data.foreach_set("color", carrier.read(values, attribute.domain).ravel())
                copied.append("color '%s'" % attribute.name)
        if self.attributes:
            for attribute in source.attributes:
                if (attribute.name.startswith(".") or attribute.name == "position" or
                        attribute.data_type not in FLOAT_TYPES or
                        attribute.domain not in ("POINT", "CORNER")):
                    continue
                key, width = FLOAT_TYPES[attribute.data_type]
                values = attribute_values(attribute, key, width,
                                          domain_size(source, attribute.domain))
                out = self.receiving(receiver, attribute.name, attribute.data_type,
                                     attribute.domain)
                out.data.foreach_set(key, carrier.read(values, attribute.domain).ravel())
                copied.append("attribute '%s'" % attribute.name)
        receiver.update()
        return copied

    @staticmethod
    def receiving(mesh, name, data_type, domain, colors=False):
        """The receiver's attribute `name` of this type and domain (replaced if it differs)."""
        collection = mesh.color_attributes if colors else mesh.attributes
        existing = collection.get(name)
        if existing is not None and (existing.data_type != data_type or existing.domain != domain):
            collection.remove(existing)
            existing = None
        return existing or collection.new(name, data_type, domain)
