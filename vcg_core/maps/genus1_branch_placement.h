// Genus 1: the three finite branch points of P on vertices, fold-free in the written map.
//
// In:  a genus-1 mesh, its face incidence, its genus-1 map (flat coordinate z per vertex, the
//      P-function; genus1_map.h), the Moebius centring applied to the map, and the map's values
//      (centred: centring applied to P(z)). Folds are judged on the centred map, as written.
// Out: `values` changed near each half period w_k: of the vertices nearest w_k, a vertex c takes
//      P's critical value e_k exactly, and the map there becomes P(z + t s) with s = w_k - z_c
//      (the shortest such shift), then centred: t = 1 on c's one-ring, so the written map doubles
//      angles about c itself, fading smoothly to 0 at a flat distance of K |s| beyond the ring. The
//      shift's gradient stays below 1 / K, so it is a diffeomorphism and P stays exact everywhere.
//      Of the candidates (nearest first), the one whose written map folds no face and winds exactly
//      twice around c wins, the nearest such. Returns the three vertices and the number of
//      candidates that were tried. Also: the widest corner of each vertex in the flat coordinate (a
//      branch vertex of local degree 2 doubles its corners, so it needs them below 90 degrees), for
//      choosing the pole.
#pragma once

#include <array>
#include <vector>

#include "maps/genus1_map.h"
#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"
#include "mesh/prepared_mesh.h"

namespace meromorph {

struct Genus1Placement {
  std::array<int, 3> vertices{-1, -1, -1};
  std::array<bool, 3> fold_free{false, false, false};
  int candidates_tried = 0;
};

Genus1Placement place_half_period_branch_points(const PreparedMesh &prepared, const Genus1Map &map,
                                                const Mobius &centring,
                                                std::vector<PlaneValue> &values);

// Per vertex: its widest corner, in radians, measured in the flat coordinate (face sides
// d = sign * psi[edge]).
std::vector<double> widest_flat_corners(const PreparedMesh &prepared, const Eigen::VectorXcd &psi);

// Per vertex: the flat area of its star over its surface area (the square of the conformal
// scale there; a long thin part's is exponentially small).
std::vector<double> flat_area_ratios(const PreparedMesh &prepared, const Eigen::VectorXcd &psi);

} // namespace meromorph
