// Genus 1: the Weierstrass P-function of the flat coordinate, a degree-2 map onto the sphere.
//
// In:  a closed genus-1 mesh, its edges, the normalized holomorphic form psi (per edge) with its
//      periods (A-period 1, B-period tau), and the origin vertex (where z = 0: a double pole; -1:
//      automatic, see below).
// Out: z per vertex by integrating psi along a breadth-first tree from the origin (defined up to
//      the lattice), F = P(z) per vertex (single-valued: P is doubly periodic) as a sphere point,
//      the P-function object, and the four branch values: P at the three half periods and infinity.
//      A piecewise-linear map branches only at vertices: the origin is a vertex, and
//      genus1_branch_placement.h puts the three others on vertices. The automatic origin is
//      where the flat metric is large (never on a long thin part) and the origin and the three
//      half periods from it fall at or near vertices with narrow corners (the branching doubles
//      them): see genus1_map.cpp.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "maps/weierstrass_p.h"
#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"
#include "mesh/prepared_mesh.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {

struct Genus1Map {
  std::vector<Complex> flat;      // z per vertex
  std::vector<PlaneValue> values; // P(z) per vertex
  WeierstrassP p_function;
  std::array<PlaneValue, 4> branch_values;
  int origin_vertex = -1;
};

// Vertices where the double pole may go, best first (at most 8; see genus1_map.cpp).
std::vector<int> genus1_origin_candidates(const PreparedMesh &prepared, const Eigen::VectorXcd &psi,
                                          const WeierstrassP &p_function);

// z per vertex: the form psi integrated along a breadth-first tree from `root` (z = 0 there);
// `incident`: the edges at each vertex.
std::vector<Complex> integrated_form(int root, const IndexLists &incident, const MeshEdges &edges,
                                     const Eigen::VectorXcd &psi);

Genus1Map genus1_map(const PreparedMesh &prepared, const Eigen::VectorXcd &psi, Complex period_a,
                     Complex period_b, int origin_vertex);

} // namespace meromorph
