// Genus 1: the Weierstrass P-function of the flat coordinate, a degree-2 map onto the sphere.
//
// In:  a closed genus-1 mesh, its edges, the normalized holomorphic form psi (per edge) with its
//      periods (A-period 1, B-period tau), and the origin vertex (where z = 0: a double pole; -1:
//      automatic, see below).
// Out: z per vertex by integrating psi along a breadth-first tree from the origin (defined up to
//      the lattice), F = P(z) per vertex (single-valued: P is doubly periodic) as a sphere point,
//      the P-function object, and the four branch values: P at the three half periods and infinity.
//      A piecewise-linear map branches only at vertices: the origin is a vertex, and
//      genus1_branch_placement.h puts the three others on vertices. The automatic origin is,
//      of the vertices whose corners in the flat coordinate are all below 80 degrees (the double
//      pole doubles them), the one where the flat metric is largest against the surface's (never
//      on a long thin part); else the vertex whose widest corner is narrowest.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh.h"
#include "mesh_edges.h"
#include "sphere_geometry.h"
#include "weierstrass_p.h"

namespace meromorph {

struct Genus1Map {
  std::vector<Complex> flat;      // z per vertex
  std::vector<PlaneValue> values; // P(z) per vertex
  WeierstrassP p_function;
  std::array<PlaneValue, 4> branch_values;
  int origin_vertex = -1;
};

Genus1Map genus1_map(const Mesh &mesh, const MeshEdges &edges, const Eigen::VectorXcd &psi,
                     Complex period_a, Complex period_b, int origin_vertex);

} // namespace meromorph
