"""Shape descriptors from conformal maps, for clustering and searching collections.

- genus 0: `spherical_harmonic_energies`: the surface's coordinates as functions on its centred
  conformal sphere, expanded in spherical harmonics; per degree l (0..16 by default) the energy
  sum_m |c_lm|^2 summed over x, y, z. Invariant under rotations of the sphere (the centred map is
  unique up to one) and rigid motions of the surface; the coordinates are centred and divided by
  the square root of the area, so scale drops out (SPHARM, Brechbuehler, Gerig, Kuebler 1995).
- genus 1: `reduced_modulus`: the modulus tau in the fundamental domain of SL(2, Z) (|Re tau| <=
  1/2, |tau| >= 1, Im tau > 0): equal for conformally equivalent tori.
- genus >= 2: the Riemann matrix (meromorph.forms, or the map's report), in the canonical basis
  of homology the forms chose.
"""

from __future__ import annotations

import math
from typing import Optional

import numpy as np


def reduced_modulus(tau: complex) -> complex:
    """tau moved into the fundamental domain by tau -> tau + n and tau -> -1 / tau."""
    tau = complex(tau)
    if tau.imag < 0:
        tau = tau.conjugate()  # the mirror torus: the same shape for shape analysis
    if tau.imag <= 0:
        raise ValueError(f"a modulus has a positive imaginary part; got {tau}")
    for _ in range(1000):
        tau -= round(tau.real)
        if abs(tau) < 1 - 1e-12:
            tau = -1 / tau
        else:
            break
    if abs(tau.real + 0.5) < 1e-12:  # the two edges of the domain are one shape
        tau += 1
    return tau


def _legendre_by_order(lmax: int, x: np.ndarray):
    """For m = 0..lmax, yields (m, [Q[m, m], Q[m+1, m], ..., Q[lmax, m]]) where Q[l, m] =
    sqrt((2l+1)/(4 pi) (l-m)!/(l+m)!) P_l^m(x), by the stable three-term recurrences (the
    spherical harmonic is Q e^{i m phi}); one order at a time, so memory stays O(lmax n)."""
    sine = np.sqrt(np.clip(1 - x * x, 0, None))
    diagonal = np.full(len(x), math.sqrt(1 / (4 * math.pi)))
    for m in range(0, lmax + 1):
        if m > 0:
            diagonal = -math.sqrt((2 * m + 1) / (2 * m)) * sine * diagonal
        column = [diagonal]
        if m < lmax:
            column.append(math.sqrt(2 * m + 3) * x * diagonal)
        for l in range(m + 2, lmax + 1):
            a = math.sqrt((4 * l * l - 1) / (l * l - m * m))
            b = math.sqrt(((l - 1) ** 2 - m * m) / (4 * (l - 1) ** 2 - 1))
            column.append(a * (x * column[-1] - b * column[-2]))
        yield m, column


def _normalized_legendre(lmax: int, x: np.ndarray) -> np.ndarray:
    """Q[l, m, i] for 0 <= m <= l <= lmax (all at once: for checks on small point sets)."""
    Q = np.zeros((lmax + 1, lmax + 1, len(x)))
    for m, column in _legendre_by_order(lmax, x):
        for k, values in enumerate(column):
            Q[m + k, m] = values
    return Q


def sphere_vertex_weights(sphere: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Quadrature weights on the sphere: a third of each incident spherical triangle's area
    (Van Oosterom and Strackee's solid angle), summing to 4 pi on a one-to-one map."""
    a, b, c = (sphere[triangles[:, k]] for k in range(3))
    numerator = np.abs(np.einsum("ij,ij->i", a, np.cross(b, c)))
    denominator = 1 + np.einsum("ij,ij->i", a, b) + np.einsum("ij,ij->i", b, c) + \
        np.einsum("ij,ij->i", c, a)
    solid = 2 * np.arctan2(numerator, denominator)
    return sum(np.bincount(triangles[:, k], weights=solid / 3, minlength=len(sphere))
               for k in range(3))


def spherical_harmonic_energies(vertices: np.ndarray, triangles: np.ndarray,
                                sphere: np.ndarray, degree: int = 16) -> np.ndarray:
    """Energies per degree 0..`degree` of the surface coordinates over the sphere map (genus 0):
    `vertices` (n, 3) the surface, `triangles` (m, 3), `sphere` (n, 3) each vertex's image on the
    unit sphere (a meromorph.Map's `sphere`, or the written layered sphere of a genus-0 map)."""
    vertices = np.asarray(vertices, dtype=np.float64)
    triangles = np.asarray(triangles, dtype=np.int64)
    sphere = np.asarray(sphere, dtype=np.float64)
    sphere = sphere / np.linalg.norm(sphere, axis=1, keepdims=True)
    # Centred and scaled by the surface's area (both from the surface, not the sphere).
    p0, p1, p2 = (vertices[triangles[:, k]] for k in range(3))
    face_area = 0.5 * np.linalg.norm(np.cross(p1 - p0, p2 - p0), axis=1)
    area = face_area.sum()
    centroid = ((p0 + p1 + p2) / 3 * face_area[:, None]).sum(axis=0) / area
    f = (vertices - centroid) / math.sqrt(area)
    w = sphere_vertex_weights(sphere, triangles)
    phi = np.arctan2(sphere[:, 1], sphere[:, 0])
    energies = np.zeros(degree + 1)
    weighted = f * w[:, None]  # (n, 3)
    for m, column in _legendre_by_order(degree, np.clip(sphere[:, 2], -1, 1)):
        # Real and imaginary parts of the coefficients, three per degree (one per coordinate).
        cosine = weighted * np.cos(m * phi)[:, None]
        sine = weighted * np.sin(m * phi)[:, None]
        for k, values in enumerate(column):
            real, imaginary = values @ cosine, values @ sine
            energies[m + k] += (1 if m == 0 else 2) * float(np.sum(real**2 + imaginary**2))
    return energies


def describe(genus: int, report: dict, vertices: Optional[np.ndarray] = None,
             triangles: Optional[np.ndarray] = None, sphere: Optional[np.ndarray] = None,
             degree: int = 16) -> dict:
    """The descriptor of one map: {"modulus": [re, im]} (genus 1, reduced), {"riemann_matrix":
    [[[re, im], ...], ...]} (genus >= 2, from the report), {"spharm": [E_0, ..., E_degree]}
    (genus 0, needs vertices, triangles and sphere)."""
    if genus == 1 and "modulus" in report:
        tau = reduced_modulus(complex(*report["modulus"]))
        return {"modulus": [tau.real, tau.imag]}
    if genus >= 2 and "riemann_matrix" in report:
        return {"riemann_matrix": report["riemann_matrix"]}
    if genus == 0 and vertices is not None and sphere is not None:
        return {"spharm": spherical_harmonic_energies(vertices, triangles, sphere,
                                                      degree).tolist()}
    return {}
