# The add-on in the real Blender: blender -b --factory-startup --python-exit-code 1 --python
# test_addon.py -- ADDON_ZIP MEROMORPH_CLI TEST_DATA WORK_DIR
# (BLENDER_USER_SCRIPTS points at an empty temporary folder, so the zip is installed fresh.)
import os
import subprocess
import sys

import bpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import activate, add_off, check, install_addon, summary  # noqa: E402

ADDON_ZIP, CLI, DATA, WORK = sys.argv[sys.argv.index("--") + 1:][:4]


def clear_scene():
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()
    for mesh in list(bpy.data.meshes):
        bpy.data.meshes.remove(mesh)


def run_operator(**options):
    return bpy.ops.mesh.meromorph_conformal_sphere_map(**options)


def expect_error(words, **options):
    try:
        run_operator(**options)
    except RuntimeError as error:
        check(words in str(error), "error should mention '%s': %s" % (words, error))
        return
    raise AssertionError("expected an error mentioning '%s'" % words)


def cli_corner_uvs(obj):
    """The CLI's wedge UVs for the same loop triangles, read back from an OBJ it writes."""
    mesh = obj.data
    mesh.calc_loop_triangles()
    path = os.path.join(WORK, obj.name.replace(" ", "_") + ".off")
    with open(path, "w") as stream:
        stream.write("OFF\n%d %d 0\n" % (len(mesh.vertices), len(mesh.loop_triangles)))
        for v in mesh.vertices:
            stream.write("%r %r %r\n" % tuple(float(np.float32(c)) for c in v.co))
        for t in mesh.loop_triangles:
            stream.write("3 %d %d %d\n" % tuple(t.vertices))
    out = path[:-4] + ".cli.obj"
    subprocess.run([CLI, "param", path, "-o", out, "--quiet"], check=True)
    texcoords, corners = [], []
    with open(out) as stream:
        for line in stream:
            parts = line.split()
            if parts and parts[0] == "vt":
                texcoords.append((float(parts[1]), float(parts[2])))
            elif parts and parts[0] == "f":
                corners.extend(texcoords[int(p.split("/")[1]) - 1] for p in parts[1:4])
    return np.array(corners)


def check_result(obj, genus_degree_branch, quads=False):
    genus, degree, branch_count = genus_degree_branch
    mesh = obj.data
    check("Conformal Sphere" in mesh.uv_layers, "the UV layer exists")
    sphere = bpy.data.objects.get(obj.name + " Layered Sphere")
    check(sphere is not None, "the layered sphere object exists")
    check(len(sphere.data.vertices) == len(mesh.vertices), "same vertex count")
    layers = np.empty(len(sphere.data.vertices), dtype=np.int32)
    sphere.data.attributes["layer"].data.foreach_get("value", layers)
    check(set(layers.tolist()) == set(range(degree)), "layers 0..degree-1: %s" % set(layers.tolist()))
    co = np.empty(3 * len(sphere.data.vertices))
    sphere.data.vertices.foreach_get("co", co)
    radii = np.linalg.norm(co.reshape(-1, 3), axis=1)
    check(np.allclose(radii, 1.0 + 0.3 * layers, atol=1e-5), "radius 1 + gap * layer")
    group = sphere.vertex_groups["branch_points"]
    members = [v.index for v in sphere.data.vertices if any(g.group == group.index for g in v.groups)]
    check(len(members) == branch_count, "branch_points group has %d (expected %d)" % (len(members), branch_count))
    selected = [v.index for v in mesh.vertices if v.select]
    check(sorted(selected) == sorted(members), "branch vertices selected on the original")
    if not quads:
        # Per-loop UVs equal the CLI's wedge UVs for the same triangles.
        mesh.calc_loop_triangles()
        loops = np.empty(3 * len(mesh.loop_triangles), dtype=np.int32)
        mesh.loop_triangles.foreach_get("loops", loops)
        uv = np.empty(2 * len(mesh.loops))
        mesh.uv_layers["Conformal Sphere"].data.foreach_get("uv", uv)
        ours = uv.reshape(-1, 2)[loops]
        theirs = cli_corner_uvs(obj)
        check(ours.shape == theirs.shape, "as many corners as the CLI")
        check(np.abs(ours - theirs).max() < 1e-5, "UVs equal the CLI's (max difference %g)"
              % np.abs(ours - theirs).max())


# Install the built zip into the temporary user scripts folder and enable it.
install_addon(ADDON_ZIP)
check(hasattr(bpy.types, "MESH_OT_meromorph_conformal_sphere_map"), "operator registered")
for menu in (bpy.types.VIEW3D_MT_uv_map, bpy.types.VIEW3D_MT_object):  # the U menu and Object menu
    names = [getattr(f, "__module__", "") for f in menu._dyn_ui_initialize()]
    check(any(n.startswith("meromorph_blender") for n in names), "entry in %s" % menu.__name__)

# A torus primitive (quads), triangulated to compare with the CLI, and as quads.
clear_scene()
bpy.ops.mesh.primitive_torus_add(major_segments=48, minor_segments=16)
torus = bpy.context.active_object
torus.name = "Torus"
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.select_all(action="SELECT")
bpy.ops.mesh.quads_convert_to_tris()
bpy.ops.object.mode_set(mode="OBJECT")
check(run_operator(layer_gap=0.3) == {"FINISHED"}, "torus mapped")
check_result(torus, (1, 2, 4))

clear_scene()
bpy.ops.mesh.primitive_torus_add(major_segments=48, minor_segments=16)
quad_torus = bpy.context.active_object
quad_torus.name = "Quad Torus"
# From Edit Mode, as the U menu runs it.
bpy.ops.object.mode_set(mode="EDIT")
check(run_operator(layer_gap=0.3) == {"FINISHED"}, "quad torus mapped from edit mode")
check(quad_torus.mode == "EDIT", "back in edit mode")
bpy.ops.object.mode_set(mode="OBJECT")
check_result(quad_torus, (1, 2, 4), quads=True)
uv = np.empty(2 * len(quad_torus.data.loops))
quad_torus.data.uv_layers["Conformal Sphere"].data.foreach_get("uv", uv)
sphere = bpy.data.objects["Quad Torus Layered Sphere"].data
co = np.empty(3 * len(sphere.vertices))
sphere.vertices.foreach_get("co", co)
co = co.reshape(-1, 3)
for polygon in quad_torus.data.polygons:  # seam-correct per polygon, away from the poles
    u = uv.reshape(-1, 2)[polygon.loop_start:polygon.loop_start + polygon.loop_total, 0]
    polar = max(abs(co[v][2]) / np.linalg.norm(co[v]) for v in polygon.vertices) > 0.95
    check(polar or u.max() - u.min() <= 0.5, "polygon %d spans %g of the texture" % (polygon.index, u.max() - u.min()))

# The genus-2 "eight".
clear_scene()
eight = add_off(os.path.join(DATA, "eight.off"), "Eight")
check(run_operator(layer_gap=0.3) == {"FINISHED"}, "eight mapped")
check_result(eight, (2, 2, 6))

# A quad cube: genus 0, one layer, no branch point.
clear_scene()
bpy.ops.mesh.primitive_cube_add()
cube = bpy.context.active_object
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.subdivide(number_cuts=4)
bpy.ops.object.mode_set(mode="OBJECT")
check(run_operator(layer_gap=0.3) == {"FINISHED"}, "cube mapped")
check_result(cube, (0, 1, 0), quads=True)

# Errors in Blender's words, nothing changed.
clear_scene()
expect_error("Select a mesh object")
bpy.ops.mesh.primitive_grid_add()
grid = bpy.context.active_object
expect_error("boundary loop", close_holes=False)
expect_error("turn on Close Holes in the operator's panel", close_holes=False)
check(len(grid.data.uv_layers) == 1 and "Conformal Sphere" not in grid.data.uv_layers, "grid unchanged")
check(bpy.data.objects.get(grid.name + " Layered Sphere") is None, "no sphere object for the grid")
# With Close Holes (the default) the open grid is mapped: every face keeps its UVs.
check(run_operator(layer_gap=0.0) == {"FINISHED"}, "grid mapped with its hole closed")
check("Conformal Sphere" in grid.data.uv_layers, "the grid has the UV layer")
grid_sphere = bpy.data.objects[grid.name + " Layered Sphere"].data
check(len(grid_sphere.vertices) == len(grid.data.vertices), "grid sphere keeps every vertex")
co = np.empty(3 * len(grid_sphere.vertices))
grid_sphere.vertices.foreach_get("co", co)
check(np.allclose(np.linalg.norm(co.reshape(-1, 3), axis=1), 1.0, atol=1e-5), "grid on the sphere")
clear_scene()
# Two parts: each mapped on its own, side by side in one layered-sphere object.
bpy.ops.mesh.primitive_cube_add(location=(0, 0, 0))
first = bpy.context.active_object
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.subdivide(number_cuts=3)
bpy.ops.object.mode_set(mode="OBJECT")
bpy.ops.mesh.primitive_cube_add(location=(5, 0, 0))
second = bpy.context.active_object
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.subdivide(number_cuts=3)
bpy.ops.object.mode_set(mode="OBJECT")
first.select_set(True)
bpy.ops.object.join()
joined = bpy.context.active_object
check(run_operator(layer_gap=0.0) == {"FINISHED"}, "two parts mapped")
joined_sphere = bpy.data.objects[joined.name + " Layered Sphere"].data
co = np.empty(3 * len(joined_sphere.vertices))
joined_sphere.vertices.foreach_get("co", co)
co = co.reshape(-1, 3)
half = len(co) // 2
centres = sorted(round(float(c), 3) for c in (co[:half].mean(axis=0)[0], co[half:].mean(axis=0)[0]))
check(abs(centres[1] - centres[0] - 2.5) < 0.1, "the parts' spheres side by side: %s" % centres)
components = np.empty(len(joined_sphere.vertices), dtype=np.int32)
joined_sphere.attributes["component"].data.foreach_get("value", components)
check(sorted(set(components.tolist())) == [0, 1], "component attribute 0 and 1")
check(len(set(components[:half].tolist())) == 1 and len(set(components[half:].tolist())) == 1,
      "one component per cube")
for part in (co[:half], co[half:]):
    centre = np.array([round(part[:, 0].mean() / 2.5) * 2.5, 0, 0])
    check(np.allclose(np.linalg.norm(part - centre, axis=1), 1.0, atol=1e-5), "each part on its sphere")
# Suzanne as Blender makes her: three parts (head and two eyes) and four holes, mapped with the
# defaults: every face gets UVs, one layered-sphere object with a part per component.
clear_scene()
bpy.ops.mesh.primitive_monkey_add()
suzanne = bpy.context.active_object
check(run_operator(layer_gap=0.0) == {"FINISHED"}, "Suzanne mapped with the defaults")
uv = np.empty(2 * len(suzanne.data.loops))
suzanne.data.uv_layers["Conformal Sphere"].data.foreach_get("uv", uv)
check(np.isfinite(uv).all() and len(uv) == 2 * len(suzanne.data.loops), "every loop has a UV")
suzanne_sphere = bpy.data.objects[suzanne.name + " Layered Sphere"].data
components = np.empty(len(suzanne_sphere.vertices), dtype=np.int32)
suzanne_sphere.attributes["component"].data.foreach_get("value", components)
check(sorted(set(components.tolist())) == [0, 1, 2], "Suzanne's three parts: %s" % set(components.tolist()))
check(len(suzanne_sphere.polygons) == len(suzanne.data.polygons), "the sphere has every face")

# Two cubes sharing an edge (a non-manifold edge of four faces): split for the computation, the
# layered sphere gets the copies of the edge's two vertices, the cube keeps its vertices.
clear_scene()
corners = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
vertices = corners + [(x + 1, y + 1, z) for (x, y, z) in corners]
second = {k: 8 + k for k in range(8)}
second[0], second[1] = 6, 7  # (1, 1, z) of the second cube is (1, 1, z) of the first
faces = quads + [tuple(second[v] for v in q) for q in quads]  # counter-clockwise from outside
used = sorted({v for f in faces for v in f})
index = {v: i for i, v in enumerate(used)}
mesh = bpy.data.meshes.new("Cubes")
mesh.from_pydata([vertices[v] for v in used], [], [tuple(index[v] for v in f) for f in faces])
cubes = bpy.data.objects.new("Cubes", mesh)
bpy.context.collection.objects.link(cubes)
activate(cubes)
expect_error("non-manifold", split_nonmanifold=False)
expect_error("turn on Split Non-Manifold Spots", split_nonmanifold=False)
check(run_operator(layer_gap=0.0) == {"FINISHED"}, "two cubes sharing an edge mapped")
cubes_sphere = bpy.data.objects["Cubes Layered Sphere"].data
check(len(cubes_sphere.vertices) == len(mesh.vertices) + 2,
      "the sphere has two more vertices: %d" % len(cubes_sphere.vertices))
source = np.empty(len(cubes_sphere.vertices), dtype=np.int32)
cubes_sphere.attributes["source_vertex"].data.foreach_get("value", source)
for polygon, original in zip(cubes_sphere.polygons, mesh.polygons):
    check([int(source[v]) for v in polygon.vertices] == list(original.vertices),
          "sphere polygon %d comes from the cube's" % polygon.index)
co = np.empty(3 * len(cubes_sphere.vertices))
cubes_sphere.vertices.foreach_get("co", co)
components = np.empty(len(cubes_sphere.vertices), dtype=np.int32)
cubes_sphere.attributes["component"].data.foreach_get("value", components)
spacing = 2.5
for part in (0, 1):
    at = co.reshape(-1, 3)[components == part] - np.array([part * spacing, 0, 0])
    check(np.allclose(np.linalg.norm(at, axis=1), 1.0, atol=1e-5), "cube %d on its own sphere" % part)

clear_scene()
mesh = bpy.data.meshes.new("Triangle")
mesh.from_pydata([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [], [(0, 1, 2)])
triangle = bpy.data.objects.new("Triangle", mesh)
bpy.context.collection.objects.link(triangle)
activate(triangle)
expect_error("at least 4")

# Object > Conformal Sphere Remesh on the genus-2 eight: a new object beside it, closed with the
# same genus, about the asked vertex count, each vertex's layer and the six branch vertices.
clear_scene()
eight = add_off(os.path.join(DATA, "eight.off"), "Eight")
eight_vertices = len(eight.data.vertices)
check(bpy.ops.object.meromorph_conformal_sphere_remesh(target_vertices=800) == {"FINISHED"},
      "eight remeshed")
remeshed = bpy.data.objects.get("Eight Remeshed")
check(remeshed is not None, "a new object 'Eight Remeshed'")
check(bpy.context.active_object == remeshed, "the new object is active")
check(len(eight.data.vertices) == eight_vertices, "the original is untouched")
data = remeshed.data
check(abs(len(data.vertices) - 800) <= 80, "about 800 vertices: %d" % len(data.vertices))
check(all(len(p.vertices) == 3 for p in data.polygons), "triangles")
edge_faces = {}
for polygon in data.polygons:
    for key in polygon.edge_keys:
        edge_faces[key] = edge_faces.get(key, 0) + 1
check(all(count == 2 for count in edge_faces.values()), "closed: every edge on two faces")
check(len(data.vertices) - len(data.edges) + len(data.polygons) == -2, "genus 2 kept")
layers = np.empty(len(data.vertices), dtype=np.int32)
data.attributes["layer"].data.foreach_get("value", layers)
check(set(layers.tolist()) == {0, 1}, "two layers: %s" % sorted(set(layers.tolist())))
group = remeshed.vertex_groups["branch_points"].index
in_group = [v.index for v in data.vertices if any(g.group == group for g in v.groups)]
check(len(in_group) == 6, "six branch vertices in the group: %d" % len(in_group))
# Sized by a largest distance instead: the report's Hausdorff distance both ways within the 0.5%
# asked (a second object, the eight untouched).
activate(eight)
check(bpy.ops.object.meromorph_conformal_sphere_remesh(size_by="MAX_ERROR", max_error=0.5)
      == {"FINISHED"}, "eight remeshed within 0.5%")
within = bpy.context.active_object
check(within is not None and within != remeshed and within != eight, "a new object")
positions = np.empty(3 * len(within.data.vertices))
within.data.vertices.foreach_get("co", positions)
positions = positions.reshape(-1, 3)
originals = np.array([v.co[:] for v in eight.data.vertices])
diagonal = np.linalg.norm(originals.max(0) - originals.min(0))
nearest = max(np.min(np.linalg.norm(originals - p, axis=1)) for p in positions[::7])
check(nearest < 0.05 * diagonal, "the new mesh lies on the eight: %g" % (nearest / diagonal))
check(all(len(p.vertices) == 3 for p in within.data.polygons), "triangles")
check(len(within.data.vertices) - len(within.data.edges) + len(within.data.polygons) == -2,
      "genus 2 kept")
mesh = bpy.data.meshes.new("Lone Triangle")
mesh.from_pydata([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [], [(0, 1, 2)])
lone = bpy.data.objects.new("Lone Triangle", mesh)
bpy.context.collection.objects.link(lone)
activate(lone)
try:
    bpy.ops.object.meromorph_conformal_sphere_remesh()
    raise AssertionError("a single triangle should be refused")
except RuntimeError as error:
    check("at least 4" in str(error), "the refusal says why: %s" % error)

# A CAD part as exported (a plate with one hole, flat faces fanned into long thin triangles):
# its own triangles cannot carry the map, so the vertices it needs are added after the mesh's own
# (which keep their positions), and the written surface is a valid cover: no triangle of the
# layered sphere turned over, two layers, four branch points.
clear_scene()
cad_path = os.path.join(WORK, "cad_plate.off")
subprocess.run([CLI, "make", "cad", "--holes", "1", "--segments", "64", "--thickness", "0.05",
                "-o", cad_path], check=True, stdout=subprocess.DEVNULL)
plate = add_off(cad_path, "CAD Plate")
original = np.empty(3 * len(plate.data.vertices))
plate.data.vertices.foreach_get("co", original)
check(run_operator(layer_gap=0.3) == {"FINISHED"}, "CAD plate mapped")
check(len(plate.data.vertices) > len(original) // 3, "vertices added: %d -> %d"
      % (len(original) // 3, len(plate.data.vertices)))
now = np.empty(3 * len(plate.data.vertices))
plate.data.vertices.foreach_get("co", now)
check(np.abs(now[:len(original)] - original).max() < 1e-6, "the mesh's own vertices stay put")
check_result(plate, (1, 2, 4), quads=True)
sphere_data = bpy.data.objects[plate.name + " Layered Sphere"].data
sphere_data.calc_loop_triangles()
corners = np.empty(3 * len(sphere_data.loop_triangles), dtype=np.int32)
sphere_data.loop_triangles.foreach_get("vertices", corners)
co = np.empty(3 * len(sphere_data.vertices))
sphere_data.vertices.foreach_get("co", co)
on_sphere = co.reshape(-1, 3) / np.linalg.norm(co.reshape(-1, 3), axis=1)[:, None]
a, b, c = (on_sphere[corners.reshape(-1, 3)[:, k]] for k in range(3))
check((np.einsum("ij,ij->i", a, np.cross(b - a, c - a)) > 0).all(), "no triangle turned over")

# Object > Link/Transfer Data > Transfer Through the Sphere (the selected mesh's data onto the
# active one): a head with a UV map that has a
# seam (cylindrical: u turns once around the z axis) and a colour per vertex is copied onto the
# same head re-triangulated (every triangle into four, half the new inner edges flipped), turned,
# shrunk and moved in its mesh data, as two scans of one object come. The true values at every
# receiving vertex and face corner are known from where it came from; beside it, Blender's own
# Transfer Mesh Data (nearest face, interpolated) on a copy of the same receiver.
clear_scene()
head = add_off(os.path.join(DATA, "maxplanck.nf25k.off"), "Painted Head")
hv = np.empty(3 * len(head.data.vertices))
head.data.vertices.foreach_get("co", hv)
hv = hv.reshape(-1, 3)
centre, low, high = hv.mean(axis=0), hv.min(axis=0), hv.max(axis=0)


def cylinder_uv(points):
    d = points - centre
    return np.c_[np.arctan2(d[:, 1], d[:, 0]) / (2 * np.pi) + 0.5,
                 (points[:, 2] - low[2]) / (high[2] - low[2])]


def corner_truth(mesh, positions):
    """Per loop: the cylindrical UV of its vertex's true position, u taken on one side of the seam
    per polygon; and whether the polygon is near the axis (u means nothing there)."""
    loop_vertex = np.empty(len(mesh.loops), dtype=np.int64)
    mesh.loops.foreach_get("vertex_index", loop_vertex)
    uv = cylinder_uv(positions)[loop_vertex]
    radius = np.linalg.norm((positions - centre)[:, :2], axis=1)[loop_vertex]
    near_axis = np.zeros(len(mesh.loops), dtype=bool)
    for polygon in mesh.polygons:
        span = slice(polygon.loop_start, polygon.loop_start + polygon.loop_total)
        if uv[span, 0].max() - uv[span, 0].min() > 0.5:
            uv[span, 0] = np.where(uv[span, 0] < 0.5, uv[span, 0] + 1, uv[span, 0])
        near_axis[span] = radius[span].min() < 0.15 * radius.max()
    return uv, near_axis


uv_layer = head.data.uv_layers.new(name="Cylinder")
uv_layer.data.foreach_set("uv", corner_truth(head.data, hv)[0].ravel())
paint = head.data.color_attributes.new("Paint", "FLOAT_COLOR", "POINT")
paint.data.foreach_set("color", np.c_[(hv - low) / (high - low), np.ones(len(hv))].ravel())

faces = [tuple(p.vertices) for p in head.data.polygons]
points, midpoint, fine = [tuple(p) for p in hv], {}, []


def middle(a, b):
    key = (min(a, b), max(a, b))
    if key not in midpoint:
        points.append(tuple((hv[a] + hv[b]) / 2))
        midpoint[key] = len(points) - 1
    return midpoint[key]


for f, (a, b, c) in enumerate(faces):
    ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
    fine += ([(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)] if f % 2 == 0 else
             [(a, ab, bc), (a, bc, ca), (ab, b, bc), (ca, bc, c)])
true_positions = np.array(points)
turn = np.array([[0.36, 0.48, -0.8], [-0.8, 0.6, 0.0], [0.48, 0.64, 0.6]])  # a rotation
moved = 0.5 * true_positions @ turn.T + np.array([3.0, -1.0, 2.0])
receivers = []
for name in ("Scan", "Scan (Blender's transfer)"):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(moved.tolist(), [], fine)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.collection.objects.link(obj)
    receivers.append(obj)
ours, blenders = receivers

for menu in (bpy.types.VIEW3D_MT_make_links,):
    names = [getattr(f, "__module__", "") for f in menu._dyn_ui_initialize()]
    check(any(n.startswith("meromorph_blender") for n in names), "entry in %s" % menu.__name__)
activate(ours)
check(not bpy.ops.object.meromorph_conformal_transfer.poll(), "nothing to copy from: greyed")
head.select_set(True)  # the head selected, the scan active: the scan receives
check(bpy.ops.object.meromorph_conformal_transfer() == {"FINISHED"}, "transferred")
activate(blenders)
head.select_set(True)
bpy.context.view_layer.objects.active = head
bpy.ops.object.data_transfer(use_reverse_transfer=False, data_type="UV",
                             loop_mapping="POLYINTERP_NEAREST", layers_select_src="ALL",
                             layers_select_dst="NAME")
bpy.ops.object.data_transfer(data_type="VCOL", loop_mapping="POLYINTERP_NEAREST",
                             layers_select_src="ALL", layers_select_dst="NAME")

truth_uv, near_axis = corner_truth(ours.data, true_positions)
truth_color = (true_positions - low) / (high - low)
figures = {}
for obj in (ours, blenders):
    uv = np.empty(2 * len(obj.data.loops))
    obj.data.uv_layers["Cylinder"].data.foreach_get("uv", uv)
    uv = uv.reshape(-1, 2)
    du = np.abs(uv[:, 0] - truth_uv[:, 0]) % 1.0
    error = np.hypot(np.minimum(du, 1 - du), uv[:, 1] - truth_uv[:, 1])[~near_axis]
    straddling = 0
    for polygon in obj.data.polygons:
        span = slice(polygon.loop_start, polygon.loop_start + polygon.loop_total)
        straddling += not near_axis[span].any() and uv[span, 0].max() - uv[span, 0].min() > 0.5
    paint = obj.data.color_attributes.get("Paint")  # Blender's may carry it per corner, or not
    color = np.empty(4 * len(paint.data) if paint else 0)
    if paint:
        paint.data.foreach_get("color", color)
    if paint and paint.domain == "CORNER":
        loop_vertex = np.empty(len(obj.data.loops), dtype=np.int64)
        obj.data.loops.foreach_get("vertex_index", loop_vertex)
        color_error = np.abs(color.reshape(-1, 4)[:, :3] - truth_color[loop_vertex]).max(axis=1)
    else:
        color_error = (np.abs(color.reshape(-1, 4)[:, :3] - truth_color).max(axis=1) if paint
                       else np.array([np.nan]))
    figures[obj.name] = (error.mean(), np.percentile(error, 99), straddling, color_error.mean())
    print("%s: UV error mean %.4f, 99th percentile %.4f, %d triangles across the seam; colour "
          "error mean %.4f" % ((obj.name,) + figures[obj.name]))
mean, p99, straddling, color_mean = figures["Scan"]
check(mean < 0.003 and p99 < 0.02, "UVs where they belong: %g, %g" % (mean, p99))
check(straddling == 0, "%d triangles straddle the seam" % straddling)
check(color_mean < 0.003, "colours where they belong: %g" % color_mean)
check(mean < 0.1 * figures["Scan (Blender's transfer)"][0],
      "closer than Blender's nearest-face transfer on a moved scan")
hv_after = np.empty(3 * len(head.data.vertices))
head.data.vertices.foreach_get("co", hv_after)
check(np.array_equal(hv_after.reshape(-1, 3), hv), "the head copied from is unchanged")

# A torus turns onto itself: without landmarks the copy may land turned (the report warns); two
# vertex groups of the same name on both tori, one vertex each, fix it. The receiver is the same
# torus turned and moved in its mesh data, so every loop's true UV is the donor's same loop's.
clear_scene()
bpy.ops.mesh.primitive_torus_add(major_segments=48, minor_segments=12)
donor = bpy.context.active_object
donor.name = "Donor Torus"
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.select_all(action="SELECT")
bpy.ops.mesh.quads_convert_to_tris()
bpy.ops.object.mode_set(mode="OBJECT")
receiver = donor.copy()
receiver.data = donor.data.copy()
receiver.name = "Receiving Torus"
bpy.context.collection.objects.link(receiver)
co = np.empty(3 * len(receiver.data.vertices))
receiver.data.vertices.foreach_get("co", co)
co = co.reshape(-1, 3) @ np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]).T
receiver.data.vertices.foreach_set("co", (co + np.array([0.0, 0.0, 3.0])).ravel())
receiver.data.uv_layers.remove(receiver.data.uv_layers["UVMap"])
donor_uv = np.empty(2 * len(donor.data.loops))
donor.data.uv_layers["UVMap"].data.foreach_get("uv", donor_uv)


def transferred_uv_error(**options):
    activate(receiver)
    donor.select_set(True)
    check(bpy.ops.object.meromorph_conformal_transfer(**options) == {"FINISHED"},
          "torus transferred")
    uv = np.empty(2 * len(receiver.data.loops))
    receiver.data.uv_layers["UVMap"].data.foreach_get("uv", uv)
    return np.abs(uv - donor_uv).max()


unaided = transferred_uv_error()
for name, vertex in (("tip", 0), ("side", 100)):
    for obj in (donor, receiver):
        obj.vertex_groups.new(name=name).add([vertex], 1.0, "REPLACE")
with_landmarks = transferred_uv_error(shape_key=True)
print("torus: UV error %.4f without landmarks, %.2e with two" % (unaided, with_landmarks))
check(with_landmarks < 1e-4, "two landmarks put the torus's UVs where they belong: %g"
      % with_landmarks)
# The shape key morphs the receiving torus onto the donor: each vertex on its donor vertex.
key = receiver.data.shape_keys.key_blocks[donor.name]
morphed = np.empty(3 * len(receiver.data.vertices))
key.data.foreach_get("co", morphed)
donor_co = np.empty(3 * len(donor.data.vertices))
donor.data.vertices.foreach_get("co", donor_co)
check(np.abs(morphed - donor_co).max() < 1e-4, "the shape key lies on the donor: %g"
      % np.abs(morphed - donor_co).max())

print(summary())
