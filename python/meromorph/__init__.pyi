# Type stubs of the meromorph package (docs/python.md).
import os
from typing import Callable, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str
Progress = Callable[[float, str], Optional[bool]]
PathLike = Union[str, os.PathLike]
Mesh = Union[PathLike, Tuple[npt.ArrayLike, npt.ArrayLike], npt.ArrayLike]

class Error(Exception):
    remedies: List[str]
class InputError(Error, ValueError): ...
class NoValidMap(Error):
    report: dict
class ArgumentError(Error, ValueError): ...
class Cancelled(Error): ...
class WriteError(Error, OSError): ...
class InternalError(Error, RuntimeError): ...

def read(path: PathLike) -> Tuple[np.ndarray, np.ndarray]: ...

class Map:
    vertices: np.ndarray          # (n, 3) float64: the surface as written
    triangles: np.ndarray         # (m, 3) int32
    uv: np.ndarray                # (n, 2) float64
    corner_uv: np.ndarray         # (m, 3, 2) float64
    sphere: np.ndarray            # (n, 3) float64, on the unit sphere
    layered: np.ndarray           # (n, 3) float64, layer k at radius 1 + layer_gap k
    layer: np.ndarray             # (n,) int32
    component: np.ndarray         # (n,) int32
    source_triangle: np.ndarray   # (m,) int32
    branch_vertices: np.ndarray   # (b,) int32
    branch_degrees: np.ndarray    # (b,) int32
    added_vertices: np.ndarray    # (a, 3) float64
    added_on: np.ndarray          # (a,) int32
    added_barycentric: np.ndarray # (a, 2) float64
    sphere_mesh: Tuple[np.ndarray, np.ndarray]
    sphere_source_vertex: np.ndarray
    sphere_layer: np.ndarray
    sphere_branch: np.ndarray
    genus: int
    degree: int
    valid: bool
    riemann_hurwitz_ok: bool
    invalid_reasons: str
    report: dict
    def write(self, surface: Optional[PathLike] = ..., *, sphere: Optional[PathLike] = ...,
              report: Optional[PathLike] = ...) -> None: ...

def param(V: Mesh, F: Optional[npt.ArrayLike] = ..., *, uv: str = ..., mobius: bool = ...,
          area_correct: bool = ..., origin: Optional[int] = ...,
          forms: Optional[Tuple[int, int]] = ..., pole_face: Optional[int] = ...,
          layer_gap: float = ..., close_holes: bool = ..., split_nonmanifold: bool = ...,
          strict: bool = ..., pack_uv: bool = ..., add_vertices: bool = ...,
          keep_invalid: bool = ..., progress: Optional[Progress] = ...) -> Map: ...

class Forms:
    genus: int
    modulus: Optional[complex]
    riemann_matrix: Optional[np.ndarray]
    a_periods: np.ndarray
    b_periods: np.ndarray
    symplectic_basis: np.ndarray
    report: dict

def forms(V: Mesh, F: Optional[npt.ArrayLike] = ..., *,
          progress: Optional[Progress] = ...) -> Forms: ...

class Match:
    target_face: npt.NDArray[np.int32]
    weights: npt.NDArray[np.float64]
    points: npt.NDArray[np.float64]
    triangle_face: npt.NDArray[np.int32]
    triangle_weights: npt.NDArray[np.float64]
    report: dict
    def transfer(self, values: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    def transfer_corners(self, values: npt.ArrayLike) -> npt.NDArray[np.float64]: ...

def match(source: Mesh, target: Mesh, *, landmarks: Optional[npt.ArrayLike] = ...,
          progress: Optional[Progress] = ...) -> Match: ...

class Remesh:
    vertices: np.ndarray
    triangles: np.ndarray
    layer: np.ndarray
    branch: np.ndarray
    sphere: np.ndarray
    summary: str
    report: dict

def remesh(V: Mesh, F: Optional[npt.ArrayLike] = ..., *, vertices: Optional[int] = ...,
           edge_length: Optional[float] = ..., max_error: Optional[float] = ...,
           area_correct: bool = ..., strict: bool = ..., close_holes: bool = ...,
           split_nonmanifold: bool = ..., progress: Optional[Progress] = ...) -> Remesh: ...
