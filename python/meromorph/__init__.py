"""meromorph: conformal maps of closed triangle meshes of any genus onto the sphere.

Arrays in, arrays out (numpy), over the same C library as the command-line tool, MeshLab's filter
and Blender's add-on::

    import meromorph
    V, F = meromorph.read("eight.ply")            # positions (n, 3) float64, triangles (m, 3) int32
    m = meromorph.param(V, F)                     # the map: m.uv, m.sphere, m.layer, m.degree, ...
    m.write("eight.uv.ply", sphere="eight.sphere.ply", report="eight.json")
    f = meromorph.forms(V, F)                     # periods, modulus or Riemann matrix
    r = meromorph.remesh(V, F, vertices=5000)     # a new triangulation through the sphere

Errors are exceptions: InputError (the mesh cannot be mapped: where and what to do), NoValidMap
(no valid map on this triangulation), ArgumentError (a bad option or array), Cancelled (the
progress callable returned False, raised, or Ctrl+C), WriteError (a file could not be written).
The library works with the GIL released; several threads may map different meshes at once.
"""

from __future__ import annotations

import json
import os
from typing import Callable, Optional, Sequence, Tuple, Union

import numpy as np

from . import _native

__version__ = _native.version
__all__ = [
    "read", "param", "forms", "remesh", "match", "Map", "Forms", "Remesh", "Match", "Error",
    "InputError",
    "NoValidMap", "ArgumentError", "Cancelled", "WriteError", "InternalError",
]

Progress = Callable[[float, str], Optional[bool]]


class Error(Exception):
    """Every failure meromorph raises. `remedies` lists what to do, in words."""

    def __init__(self, message: str, remedies: Sequence[str] = ()):
        super().__init__(message)
        self.remedies = list(remedies)


class InputError(Error, ValueError):
    """The mesh cannot be mapped as it is (a broken file, a hole, a non-manifold spot, ...)."""


class NoValidMap(Error):
    """The map computed is not a valid branched cover; `report` has what was measured."""

    def __init__(self, message: str, remedies: Sequence[str] = (), report: Optional[dict] = None):
        super().__init__(message, remedies)
        self.report = report or {}


class ArgumentError(Error, ValueError):
    """A bad option, array shape or index."""


class Cancelled(Error):
    """The progress callable asked to stop."""


class WriteError(Error, OSError):
    """An output file could not be written (the system's reason is given)."""


class InternalError(Error, RuntimeError):
    """A bug in meromorph: please report it with the input."""


# The C library's remedy codes (meromorph.h), in the words of this package's options.
_REMEDY_WORDS = {
    1: "the safe repairs fix it: repair the mesh (merge seam duplicates, drop unused vertices, "
       "orient the faces consistently), or call without strict=True",
    2: "let meromorph close them for the computation only (close_holes=True), or close them in "
       "the model",
    3: "let meromorph take them apart for the computation (split_nonmanifold=True)",
    4: "meromorph takes them out of the computation and keeps them in its outputs",
    5: "remove the doubles (faces on the same three vertices)",
    6: "remesh the surface (meromorph.remesh, or an isotropic remesher) and map it again",
    7: "refine it (a midpoint subdivision) and map it again",
    8: "use the default generic pair (forms=None)",
    9: "shorten or thicken them, or map them separately",
    10: "remove the stray vertex, or bring the coordinates to one unit",
    11: "use pack_uv=True with uv='spherical' (the default)",
    12: "let meromorph add the vertices the map needs (add_vertices=True, strict=False)",
}

_STATUS_ERRORS = {1: InternalError, 2: ArgumentError, 3: InputError, 4: Cancelled, 5: WriteError}


def _raise(error: _native.NativeError) -> None:
    status, message, codes = error.args
    remedies = [_REMEDY_WORDS[c] for c in codes if c in _REMEDY_WORDS]
    text = message + "".join("; " + r for r in remedies)
    raise _STATUS_ERRORS.get(status, InternalError)(text, remedies) from None


def _call(function, *args):
    try:
        return function(*args)
    except _native.NativeError as error:
        _raise(error)


def _arrays(V, F=None) -> Tuple[np.ndarray, np.ndarray, Optional[str]]:
    """(positions, triangles, path): a path is read; arrays are checked for shape and values."""
    if F is None:
        if isinstance(V, (str, os.PathLike)):
            path = os.fspath(V)
            V, F = read(path)
            return V, F, path
        if isinstance(V, tuple) and len(V) == 2:
            V, F = V
        else:
            raise ArgumentError("give a path, or positions and triangles: param(V, F)")
    V = np.asarray(V)
    F = np.asarray(F)
    if V.ndim != 2 or V.shape[1] != 3 or V.dtype.kind not in "fiu":
        raise ArgumentError(f"positions must be numbers of shape (n, 3); got {V.dtype} {V.shape}")
    if F.ndim != 2 or F.shape[1] != 3 or F.dtype.kind not in "iu":
        raise ArgumentError(f"triangles must be integers of shape (m, 3); got {F.dtype} {F.shape}")
    if F.dtype != np.int32 and F.size and (F.min() < -2**31 or F.max() >= 2**31):
        raise ArgumentError(f"a triangle index is beyond 32 bits ({F.min()} to {F.max()})")
    if V.dtype.kind != "f" or V.dtype.itemsize not in (4, 8):
        V = V.astype(np.float64)
    return V, F, None


def read(path: Union[str, os.PathLike]) -> Tuple[np.ndarray, np.ndarray]:
    """The vertices (n, 3) float64 and triangles (m, 3) int32 of a PLY, OBJ, OFF or STL file, in
    file order (polygons are triangulated). Nothing is repaired or validated."""
    V, F, _notes = _call(_native.read, os.fspath(path))
    return V, F


def _bool(name: str, value) -> int:
    if not isinstance(value, (bool, np.bool_)):
        raise ArgumentError(f"{name} is {value!r}; use True or False")
    return int(value)


def _options(uv="spherical", mobius=True, area_correct=False, origin=None, forms=None,
             pole_face=None, layer_gap=0.0, close_holes=True, split_nonmanifold=True,
             strict=False, pack_uv=False, add_vertices=True) -> dict:
    if uv not in ("spherical", "stereographic"):
        raise ArgumentError(f"uv is {uv!r}; use 'spherical' or 'stereographic'")
    return {
        "uv_kind": 0 if uv == "spherical" else 1,
        "mobius": _bool("mobius", mobius),
        "area_correct": _bool("area_correct", area_correct),
        "origin_vertex": -1 if origin is None else int(origin),
        "form_pair": [-1, -1] if forms is None else [int(forms[0]), int(forms[1])],
        "pole_face": -1 if pole_face is None else int(pole_face),
        "layer_gap": float(layer_gap),
        "close_holes": _bool("close_holes", close_holes),
        "split_nonmanifold": _bool("split_nonmanifold", split_nonmanifold),
        "strict": _bool("strict", strict),
        "pack_uv": _bool("pack_uv", pack_uv),
        "add_vertices": _bool("add_vertices", add_vertices),
    }


class Map:
    """A conformal map of a surface onto the (layered) sphere, as `meromorph param` writes it.

    Per vertex of the surface as written (the input's vertices, then any the map added):
    `vertices` (n, 3), `uv` (n, 2) texture coordinates, `sphere` (n, 3) the image on the unit
    sphere, `layered` (n, 3) on the layered sphere (layer k at radius 1 + layer_gap k), `layer`
    (n,) the sheet, `component` (n,) the part. Per triangle: `triangles` (m, 3), `corner_uv`
    (m, 3, 2) seam-corrected. `branch_vertices`, `branch_degrees`: the branch points and their
    local degrees. `genus`, `degree`, `valid`, `report` (the JSON report as a dict),
    `added_vertices` (positions of the vertices the map added; `added_on`, `added_barycentric`:
    where). `write(...)` writes the files.
    """

    def __init__(self, native, arrays: dict, vertices: np.ndarray, protected: Sequence[str]):
        self._native = native
        self._protected = list(protected)
        self.vertices = vertices
        for key in ("uv", "sphere", "layered", "layer", "component", "triangles", "corner_uv",
                    "source_triangle", "branch_vertices", "branch_degrees", "genus", "degree",
                    "valid", "riemann_hurwitz_ok", "invalid_reasons", "sphere_source_vertex",
                    "sphere_layer", "sphere_branch"):
            setattr(self, key, arrays[key])
        self.added_vertices = arrays["added_xyz"]
        self.added_on = arrays["added_on"]
        self.added_barycentric = arrays["added_barycentric"]
        self.sphere_mesh = arrays["sphere_mesh"]
        self.report = json.loads(arrays["report"])

    def write(self, surface: Union[str, os.PathLike, None] = None, *,
              sphere: Union[str, os.PathLike, None] = None,
              report: Union[str, os.PathLike, None] = None) -> None:
        """Writes the surface with texture coordinates (.ply, .obj, .off), the layered sphere
        (.ply) and the JSON report, all or none, never over the file the mesh was read from."""
        _call(_native.write_map, self._native, surface, sphere, report, self._protected)

    def __repr__(self) -> str:
        return (f"<meromorph.Map genus {self.genus}, degree {self.degree}, "
                f"{len(self.branch_vertices)} branch points, {len(self.uv)} vertices, "
                f"{'valid' if self.valid else 'not valid'}>")


def param(V, F=None, *, uv: str = "spherical", mobius: bool = True, area_correct: bool = False,
          origin: Optional[int] = None, forms: Optional[Tuple[int, int]] = None,
          pole_face: Optional[int] = None, layer_gap: float = 0.0, close_holes: bool = True,
          split_nonmanifold: bool = True, strict: bool = False, pack_uv: bool = False,
          add_vertices: bool = True, keep_invalid: bool = False,
          progress: Optional[Progress] = None) -> Map:
    """The conformal map of a mesh onto the sphere, as `meromorph param` (same options, same
    defaults). `V, F`: positions (n, 3) and triangles (m, 3), counter-clockwise seen from outside;
    or a file path (then `write` never writes over that file). `progress(fraction, stage)` is
    called a few times a second; returning False cancels (Cancelled). Raises NoValidMap when the
    map is not a valid branched cover, unless keep_invalid."""
    V, F, path = _arrays(V, F)
    options = _options(uv, mobius, area_correct, origin, forms, pole_face, layer_gap, close_holes,
                       split_nonmanifold, strict, pack_uv, add_vertices)
    native = _call(_native.parameterize, V, F, options, progress)
    arrays = _native.map_arrays(native)
    vertices = V.astype(np.float64, copy=False)
    if len(arrays["added_xyz"]):
        vertices = np.vstack([vertices, arrays["added_xyz"]])
    result = Map(native, arrays, vertices, [path] if path else [])
    if not result.valid and not keep_invalid:
        remedies = [_REMEDY_WORDS.get(code, "") for _cause, code in arrays["advice"]]
        advice = "; ".join(f"{cause}: {_REMEDY_WORDS.get(code, '')}"
                           for cause, code in arrays["advice"])
        raise NoValidMap("no valid map on this triangulation: " + result.invalid_reasons +
                         (". What to do: " + advice if advice else ""), remedies, result.report)
    return result


class Forms:
    """The holomorphic 1-forms of a closed surface, as `meromorph forms`: `genus`, `modulus`
    (genus 1, complex, reduced to the fundamental domain), `riemann_matrix` (genus >= 2, g x g
    complex, in the canonical basis `symplectic_basis`), `a_periods`, `b_periods`, `report`."""

    def __init__(self, report: dict):
        self.report = report
        self.genus = int(report["genus"])

        def complex_matrix(rows):
            return np.array([[complex(*cell) for cell in row] for row in rows], dtype=complex)

        self.a_periods = complex_matrix(report.get("a_periods", []))
        self.b_periods = complex_matrix(report.get("b_periods", []))
        self.symplectic_basis = np.array(report.get("symplectic_basis", []), dtype=np.int64)
        self.modulus = complex(*report["modulus"]) if "modulus" in report else None
        self.riemann_matrix = (complex_matrix(report["riemann_matrix"])
                               if "riemann_matrix" in report else None)

    def __repr__(self) -> str:
        if self.modulus is not None:
            return f"<meromorph.Forms genus 1, modulus {self.modulus:.6g}>"
        return f"<meromorph.Forms genus {self.genus}>"


def forms(V, F=None, *, progress: Optional[Progress] = None) -> Forms:
    """Periods of the holomorphic 1-forms and the modulus (genus 1) or the Riemann matrix (genus
    >= 2) of a closed, connected surface (V, F) or a file path."""
    V, F, _path = _arrays(V, F)
    return Forms(json.loads(_call(_native.forms, V, F, progress)))


class Match:
    """Every vertex of a source surface on a point of a target (`match`): per source vertex the
    target's triangle `target_face` (n,) (-1 where none), the `weights` (n, 3) of its corners and
    the `points` (n, 3); `report` (dict: genus, method, alignment, landmark residuals, the matched
    mesh's angle error and folds, genus 1 the moduli and the map's dilatation). Per source triangle,
    `triangle_face` (t,): the target triangle holding the image of its centre, and
    `triangle_weights` (t, 3, 3): per corner, the weights of that triangle's corners.
    `transfer(values)` reads per-vertex values of the target (shape (m,) or (m, k)) at the source's
    vertices; `transfer_corners(values)` reads values per target triangle corner (shape (f, 3) or
    (f, 3, k), such as texture coordinates with seams) at the source's triangle corners, each
    source triangle from one side of a seam."""

    def __init__(self, arrays: dict, target_triangles: np.ndarray):
        self.target_face = arrays["target_face"]
        self.weights = arrays["weights"]
        self.points = arrays["points"]
        self.triangle_face = arrays["triangle_face"]
        self.triangle_weights = arrays["triangle_weights"]
        self.report = json.loads(arrays["report"])
        self._target_triangles = target_triangles

    def transfer(self, values) -> np.ndarray:
        values = np.asarray(values)
        corners = self._target_triangles[np.maximum(self.target_face, 0)]  # (n, 3)
        w = self.weights.reshape(self.weights.shape + (1,) * (values.ndim - 1))
        out = (w * values[corners]).sum(axis=1)
        out[self.target_face < 0] = np.nan
        return out

    def transfer_corners(self, values) -> np.ndarray:
        values = np.asarray(values)
        picked = values[np.maximum(self.triangle_face, 0)]  # (t, 3, ...)
        out = np.einsum("tkj,tj...->tk...", self.triangle_weights, picked)
        out[self.triangle_face < 0] = np.nan
        return out

    def __repr__(self) -> str:
        return (f"<meromorph.Match genus {self.report['genus']}, {len(self.points)} vertices: "
                f"{self.report['method']}>")


def match(source, target, *, landmarks=None, progress: Optional[Progress] = None) -> Match:
    """Every vertex of `source` on a point of `target` (each (V, F) or a file path; closed, both
    genus 0, 1 or 2), through their conformal spheres, flat tori or canonical maps, as `meromorph match`:
    aligned by `landmarks` (pairs (source vertex, target vertex); genus 0 needs three or more) or
    automatically."""
    source_V, source_F, _ = _arrays(source)
    target_V, target_F, _ = _arrays(target)
    pairs = np.zeros((0, 2), dtype=np.int32) if landmarks is None else np.asarray(landmarks)
    if pairs.size and (pairs.ndim != 2 or pairs.shape[1] != 2 or pairs.dtype.kind not in "iu"):
        raise ArgumentError(f"landmarks must be integer pairs of shape (k, 2); got {pairs.shape}")
    arrays = _call(_native.match, source_V, source_F, target_V, target_F,
                   pairs.astype(np.int32).reshape(-1), progress)
    return Match(arrays, np.asarray(target_F, dtype=np.int64))


class Remesh:
    """A remesh through the layered sphere: `vertices` (n, 3), `triangles` (m, 3), `layer` (n,),
    `branch` (n,) local degree at branch vertices (0 elsewhere), `sphere` (n, 3) each vertex's
    value on the sphere, `report` (dict, its "remesh" section has the Hausdorff distances and
    angles), `summary` (one line)."""

    def __init__(self, arrays: dict):
        for key in ("vertices", "triangles", "layer", "branch", "sphere", "summary"):
            setattr(self, key, arrays[key])
        self.report = json.loads(arrays["report"])

    def __repr__(self) -> str:
        return f"<meromorph.Remesh {len(self.vertices)} vertices: {self.summary}>"


def remesh(V, F=None, *, vertices: Optional[int] = None, edge_length: Optional[float] = None,
           max_error: Optional[float] = None, area_correct: bool = True, strict: bool = False,
           close_holes: bool = True, split_nonmanifold: bool = True,
           progress: Optional[Progress] = None) -> Remesh:
    """A new closed triangulation of the same genus through the layered sphere, as
    `meromorph remesh`: about `vertices` vertices (default: the input's count), or edges of about
    `edge_length` (the input's units), or within `max_error` percent of the bounding-box diagonal
    of the surface both ways with as few vertices as the tries find. One size at most."""
    V, F, _path = _arrays(V, F)
    if sum(x is not None for x in (vertices, edge_length, max_error)) > 1:
        raise ArgumentError("give one size: vertices, edge_length or max_error")
    options = _options(close_holes=close_holes, split_nonmanifold=split_nonmanifold,
                       strict=strict)
    if edge_length is not None:
        options["remesh_edge_length"] = float(edge_length)
    if max_error is not None:
        options["remesh_max_error"] = float(max_error) / 100.0
    target = 0 if vertices is None else int(vertices)
    return Remesh(_call(_native.remesh, V, F, options, target, bool(area_correct), progress))
