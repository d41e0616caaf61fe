# ctypes binding of libmeromorph (vcg_core/meromorph.h), shipped beside this file.
#
# In:  flat numpy arrays (float32 positions, int32 triangles) and options.
# Out: a dict of numpy arrays (sphere and layered positions, per-vertex and per-corner UVs,
#      layers, branch vertices and local degrees; the layered sphere as a mesh, with the copies of
#      vertices that were split at non-manifold spots; the vertices added where the mesh's
#      triangles could not carry the map, and the triangles of the surface with them) and figures; MeromorphError with the
#      library's message, status and remedy codes when the mesh cannot be mapped or the library cannot be
#      loaded.
import ctypes
import json
import os

import numpy as np

ABI_VERSION = 5
STATUS_NAMES = {1: "internal failure", 2: "bad argument", 3: "cannot be mapped", 4: "cancelled"}

PROGRESS = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_double, ctypes.c_char_p, ctypes.c_void_p)


class Options(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_size_t),
        ("uv_kind", ctypes.c_int),
        ("mobius", ctypes.c_int),
        ("origin_vertex", ctypes.c_int),
        ("form_pair", ctypes.c_int * 2),
        ("layer_gap", ctypes.c_double),
        ("pole_face", ctypes.c_int),
        ("progress", PROGRESS),
        ("progress_user", ctypes.c_void_p),
        ("close_holes", ctypes.c_int),
        ("split_nonmanifold", ctypes.c_int),
        ("pack_uv", ctypes.c_int),
        ("area_correct", ctypes.c_int),
        ("strict", ctypes.c_int),
        ("add_vertices", ctypes.c_int),
        ("remesh_edge_length", ctypes.c_double),
        ("remesh_max_error", ctypes.c_double),
    ]


class Distortion(ctypes.Structure):
    _fields_ = [
        ("angle_error_mean_degrees", ctypes.c_double),
        ("quasi_conformal_mean", ctypes.c_double),
        ("quasi_conformal_p95", ctypes.c_double),
        ("quasi_conformal_max", ctypes.c_double),
        ("folded_faces_away_from_branch_points", ctypes.c_int32),
        ("folded_faces", ctypes.c_int32),
    ]


class MeromorphError(Exception):
    def __init__(self, status, message, remedies=()):
        super().__init__(message)
        self.status = status
        self.remedies = list(remedies)  # meromorph_remedy codes, worded by remedies.py


_library = None


def load():
    global _library
    if _library is None:
        path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "libmeromorph.so")
        try:
            lib = ctypes.CDLL(path)
        except OSError as error:
            raise MeromorphError(1, "the add-on's library cannot be loaded (%s): reinstall the "
                                 "add-on from its zip" % error)
        lib.meromorph_last_error.restype = ctypes.c_char_p
        lib.meromorph_version.restype = ctypes.c_char_p
        lib.meromorph_report_json.restype = ctypes.c_char_p
        lib.meromorph_advice.restype = ctypes.c_char_p
        lib.meromorph_advice.argtypes = [ctypes.c_void_p]
        lib.meromorph_advice_count.argtypes = [ctypes.c_void_p]
        lib.meromorph_advice_cause.restype = ctypes.c_char_p
        lib.meromorph_advice_cause.argtypes = [ctypes.c_void_p, ctypes.c_int]
        lib.meromorph_advice_remedy.argtypes = [ctypes.c_void_p, ctypes.c_int]
        lib.meromorph_last_error_remedies.argtypes = [ctypes.c_void_p, ctypes.c_int]
        lib.meromorph_invalid_reasons.restype = ctypes.c_char_p
        lib.meromorph_invalid_reasons.argtypes = [ctypes.c_void_p]
        lib.meromorph_parameterize_f.argtypes = [
            ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p, ctypes.c_size_t,
            ctypes.POINTER(Options), ctypes.POINTER(ctypes.c_void_p)]
        lib.meromorph_sphere_mesh.argtypes = [ctypes.c_void_p] * 7
        for name in ("vertex_count", "triangle_count", "branch_point_count",
                     "sphere_vertex_count", "added_vertex_count"):
            getattr(lib, "meromorph_" + name).restype = ctypes.c_size_t
            getattr(lib, "meromorph_" + name).argtypes = [ctypes.c_void_p]
        for name in ("genus", "degree", "riemann_hurwitz_ok", "map_valid"):
            getattr(lib, "meromorph_" + name).argtypes = [ctypes.c_void_p]
        for name in ("sphere_positions", "layered_positions", "vertex_uvs", "corner_uvs", "layers",
                     "vertex_components",
                     "report_json", "result_free", "map_distortion",
                     "map_distortion_away_from_branch_points"):
            getattr(lib, "meromorph_" + name).argtypes = [ctypes.c_void_p] + (
                [] if name in ("report_json", "result_free") else [ctypes.c_void_p])
        lib.meromorph_branch_points.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
        lib.meromorph_added_vertices.argtypes = [ctypes.c_void_p] * 4
        lib.meromorph_surface_triangles.argtypes = [ctypes.c_void_p] * 3
        lib.meromorph_remesh_d.argtypes = [
            ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p, ctypes.c_size_t,
            ctypes.POINTER(Options), ctypes.c_int64, ctypes.c_int, ctypes.POINTER(ctypes.c_void_p)]
        for name in ("remesh_vertex_count", "remesh_triangle_count"):
            getattr(lib, "meromorph_" + name).restype = ctypes.c_size_t
            getattr(lib, "meromorph_" + name).argtypes = [ctypes.c_void_p]
        lib.meromorph_remesh_mesh.argtypes = [ctypes.c_void_p] * 6
        lib.meromorph_remesh_summary.restype = ctypes.c_char_p
        lib.meromorph_remesh_summary.argtypes = [ctypes.c_void_p]
        lib.meromorph_remesh_report_json.restype = ctypes.c_char_p
        lib.meromorph_remesh_report_json.argtypes = [ctypes.c_void_p]
        lib.meromorph_remesh_free.argtypes = [ctypes.c_void_p]
        lib.meromorph_match_d.argtypes = [
            ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p, ctypes.c_size_t,
            ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p, ctypes.c_size_t,
            ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(Options),
            ctypes.POINTER(ctypes.c_void_p)]
        for name in ("match_vertex_count", "match_triangle_count"):
            getattr(lib, "meromorph_" + name).restype = ctypes.c_size_t
            getattr(lib, "meromorph_" + name).argtypes = [ctypes.c_void_p]
        lib.meromorph_match_points.argtypes = [ctypes.c_void_p] * 4
        lib.meromorph_match_triangles.argtypes = [ctypes.c_void_p] * 3
        lib.meromorph_match_report_json.restype = ctypes.c_char_p
        lib.meromorph_match_report_json.argtypes = [ctypes.c_void_p]
        lib.meromorph_match_free.argtypes = [ctypes.c_void_p]
        if lib.meromorph_abi_version() != ABI_VERSION:
            raise MeromorphError(1, "libmeromorph has ABI %d, this add-on needs %d"
                                 % (lib.meromorph_abi_version(), ABI_VERSION))
        _library = lib
    return _library


def last_error(lib, status):
    """The calling thread's last failure as a MeromorphError, with its remedies."""
    # How many remedies there are first, then all of them.
    message = lib.meromorph_last_error().decode("utf-8", "replace")
    remedies = np.zeros(max(0, lib.meromorph_last_error_remedies(None, 0)), dtype=np.int32)
    count = lib.meromorph_last_error_remedies(remedies.ctypes.data, len(remedies))
    return MeromorphError(status, message, remedies[:max(0, min(count, len(remedies)))].tolist())


def options_with(lib, close_holes, split_nonmanifold, progress):
    """Default options with these settings; the ctypes callback is returned to be kept alive."""
    options = Options()
    lib.meromorph_default_options(ctypes.byref(options))
    options.close_holes = 1 if close_holes else 0
    options.split_nonmanifold = 1 if split_nonmanifold else 0
    callback = PROGRESS(lambda fraction, stage, user: 1 if progress is None else progress(fraction))
    options.progress = callback
    return options, callback


def remesh(positions, triangles, target_vertices=0, area_correct=True, close_holes=True,
           split_nonmanifold=True, progress=None, edge_length=0.0, max_error=0.0):
    """The surface remeshed through its layered sphere: vertices (n x 3), triangles (t x 3),
    per vertex its layer and branch degree (0 away from branch vertices), the summary line and
    the report. edge_length (> 0: about that edge length) or max_error (> 0: within that
    fraction of the diagonal both ways, with few vertices) set the size instead of
    target_vertices."""
    lib = load()
    positions = np.ascontiguousarray(positions, dtype=np.float64).reshape(-1)
    triangles = np.ascontiguousarray(triangles, dtype=np.int32).reshape(-1)
    options, callback = options_with(lib, close_holes, split_nonmanifold, progress)  # noqa: F841
    options.remesh_edge_length = max(0.0, float(edge_length))
    options.remesh_max_error = max(0.0, float(max_error))
    if edge_length > 0 or max_error > 0:
        target_vertices = 0
    result = ctypes.c_void_p()
    status = lib.meromorph_remesh_d(
        positions.ctypes.data, positions.size // 3, triangles.ctypes.data, triangles.size // 3,
        ctypes.byref(options), int(target_vertices), 1 if area_correct else 0,
        ctypes.byref(result))
    if status != 0:
        raise last_error(lib, status)
    try:
        n = lib.meromorph_remesh_vertex_count(result)
        t = lib.meromorph_remesh_triangle_count(result)
        out = {"positions": np.empty(3 * n), "triangles": np.empty(3 * t, dtype=np.int32),
               "layer": np.empty(n, dtype=np.int32), "branch": np.empty(n, dtype=np.int32)}
        if lib.meromorph_remesh_mesh(result, out["positions"].ctypes.data,
                                     out["triangles"].ctypes.data, out["layer"].ctypes.data,
                                     out["branch"].ctypes.data, None):
            raise last_error(lib, 1)
        out["summary"] = lib.meromorph_remesh_summary(result).decode("utf-8", "replace")
        out["report"] = json.loads(lib.meromorph_remesh_report_json(result).decode("utf-8"))
        return out
    finally:
        lib.meromorph_remesh_free(result)


def match(source_positions, source_triangles, target_positions, target_triangles, landmarks=(),
          progress=None):
    """Every source vertex on a point of the target (both closed, of genus 0, 1 or 2),
    aligned automatically: per source vertex the target triangle and the weights of its corners;
    per source triangle the target triangle holding its centre's image and, per corner, the
    weights of that triangle's corners (for values given per corner: UVs with seams); the
    report. landmarks: pairs (source vertex, target vertex) that fix the alignment."""
    lib = load()
    arrays = [np.ascontiguousarray(a, dtype=t).reshape(-1) for a, t in (
        (source_positions, np.float64), (source_triangles, np.int32),
        (target_positions, np.float64), (target_triangles, np.int32))]
    pairs = np.ascontiguousarray(np.asarray(landmarks, dtype=np.int32).reshape(-1))
    options, callback = options_with(lib, True, True, progress)  # noqa: F841
    result = ctypes.c_void_p()
    status = lib.meromorph_match_d(
        arrays[0].ctypes.data, arrays[0].size // 3, arrays[1].ctypes.data, arrays[1].size // 3,
        arrays[2].ctypes.data, arrays[2].size // 3, arrays[3].ctypes.data, arrays[3].size // 3,
        pairs.ctypes.data if pairs.size else None, pairs.size // 2, ctypes.byref(options),
        ctypes.byref(result))
    if status != 0:
        raise last_error(lib, status)
    try:
        n = lib.meromorph_match_vertex_count(result)
        t = lib.meromorph_match_triangle_count(result)
        out = {"vertex_face": np.empty(n, dtype=np.int32), "vertex_weights": np.empty((n, 3)),
               "triangle_face": np.empty(t, dtype=np.int32),
               "triangle_weights": np.empty((t, 3, 3))}
        if (lib.meromorph_match_points(result, out["vertex_face"].ctypes.data,
                                       out["vertex_weights"].ctypes.data, None) or
                lib.meromorph_match_triangles(result, out["triangle_face"].ctypes.data,
                                              out["triangle_weights"].ctypes.data)):
            raise last_error(lib, 1)
        out["report"] = json.loads(lib.meromorph_match_report_json(result).decode("utf-8"))
        return out
    finally:
        lib.meromorph_match_free(result)


def parameterize(positions, triangles, uv_kind=0, mobius=True, origin_vertex=-1, pole_face=-1,
                 form_pair=(-1, -1), layer_gap=0.0, close_holes=True, split_nonmanifold=True,
                 pack_uv=False, strict=False, add_vertices=True, progress=None):
    lib = load()
    positions = np.ascontiguousarray(positions, dtype=np.float32).reshape(-1)
    triangles = np.ascontiguousarray(triangles, dtype=np.int32).reshape(-1)
    options = Options()
    lib.meromorph_default_options(ctypes.byref(options))
    options.uv_kind = uv_kind
    options.mobius = 1 if mobius else 0
    options.origin_vertex = origin_vertex
    options.pole_face = pole_face
    options.form_pair[0], options.form_pair[1] = form_pair
    options.layer_gap = layer_gap
    options.close_holes = 1 if close_holes else 0
    options.split_nonmanifold = 1 if split_nonmanifold else 0
    options.pack_uv = 1 if pack_uv else 0
    options.strict = 1 if strict else 0
    options.add_vertices = 1 if add_vertices else 0
    callback = PROGRESS(lambda fraction, stage, user: 1 if progress is None else progress(fraction))
    options.progress = callback
    result = ctypes.c_void_p()
    status = lib.meromorph_parameterize_f(
        positions.ctypes.data, positions.size // 3, triangles.ctypes.data, triangles.size // 3,
        ctypes.byref(options), ctypes.byref(result))
    if status != 0:
        raise last_error(lib, status)
    try:
        n = lib.meromorph_vertex_count(result)
        t = lib.meromorph_triangle_count(result)
        out = {
            "sphere": np.empty(3 * n), "layered": np.empty(3 * n), "vertex_uv": np.empty(2 * n),
            "corner_uv": np.empty(6 * t), "layer": np.empty(n, dtype=np.int32),
            "component": np.empty(n, dtype=np.int32),
        }
        m = lib.meromorph_sphere_vertex_count(result)
        out.update({
            "sphere_layered": np.empty(3 * m), "sphere_triangles": np.empty(3 * t, dtype=np.int32),
            "sphere_source": np.empty(m, dtype=np.int32), "sphere_layer": np.empty(m, dtype=np.int32),
            "sphere_component": np.empty(m, dtype=np.int32),
            "sphere_branch": np.empty(m, dtype=np.int32),
        })
        statuses = [
            lib.meromorph_sphere_positions(result, out["sphere"].ctypes.data),
            lib.meromorph_layered_positions(result, out["layered"].ctypes.data),
            lib.meromorph_vertex_uvs(result, out["vertex_uv"].ctypes.data),
            lib.meromorph_corner_uvs(result, out["corner_uv"].ctypes.data),
            lib.meromorph_layers(result, out["layer"].ctypes.data),
            lib.meromorph_vertex_components(result, out["component"].ctypes.data),
            lib.meromorph_sphere_mesh(
                result, out["sphere_layered"].ctypes.data, out["sphere_triangles"].ctypes.data,
                out["sphere_source"].ctypes.data, out["sphere_layer"].ctypes.data,
                out["sphere_component"].ctypes.data, out["sphere_branch"].ctypes.data),
        ]
        # The surface as written: with vertices added, the input's then these, and its triangles.
        added = lib.meromorph_added_vertex_count(result)
        out["added_xyz"] = np.empty(3 * added)
        out["surface_triangles"] = np.empty(3 * t, dtype=np.int32)
        out["surface_source"] = np.empty(t, dtype=np.int32)
        statuses.append(lib.meromorph_added_vertices(result, None, None,
                                                     out["added_xyz"].ctypes.data))
        statuses.append(lib.meromorph_surface_triangles(
            result, out["surface_triangles"].ctypes.data, out["surface_source"].ctypes.data))
        count = lib.meromorph_branch_point_count(result)
        out["branch_vertices"] = np.empty(count, dtype=np.int32)
        out["branch_degrees"] = np.empty(count, dtype=np.int32)
        if count:
            statuses.append(lib.meromorph_branch_points(
                result, out["branch_vertices"].ctypes.data, out["branch_degrees"].ctypes.data))
        distortion = Distortion()
        statuses.append(lib.meromorph_map_distortion_away_from_branch_points(
            result, ctypes.byref(distortion)))
        if any(statuses):
            raise MeromorphError(1, "reading the result failed: %s"
                                 % lib.meromorph_last_error().decode("utf-8", "replace"))
        out["angle_error"] = distortion.angle_error_mean_degrees  # away from branch points
        out["quasi_conformal_mean"] = distortion.quasi_conformal_mean
        out["quasi_conformal_p95"] = distortion.quasi_conformal_p95
        out["folded_away"] = distortion.folded_faces_away_from_branch_points
        out["genus"] = lib.meromorph_genus(result)
        out["degree"] = lib.meromorph_degree(result)
        out["riemann_hurwitz_ok"] = bool(lib.meromorph_riemann_hurwitz_ok(result))
        out["valid"] = bool(lib.meromorph_map_valid(result))
        out["invalid_reasons"] = lib.meromorph_invalid_reasons(result).decode("utf-8", "replace")
        out["advice"] = [
            (lib.meromorph_advice_cause(result, i).decode("utf-8", "replace"),
             lib.meromorph_advice_remedy(result, i))
            for i in range(lib.meromorph_advice_count(result))]
        out["report"] = json.loads(lib.meromorph_report_json(result).decode("utf-8"))
        return out
    finally:
        lib.meromorph_result_free(result)
