// Helpers shared by the direct tests of the stages (tests/test_units_*.cpp): meshes whose
// answers are known exactly.
//
// In:  sizes. Out: an icosphere's arrays; two icospheres touching at one vertex (the shared
//      vertex's index); a mesh's positions (as they are, or pushed onto the unit sphere); the
//      folded faces of a map.
#pragma once

#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cholmod.h>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

#include "forms/harmonic_forms.h"
#include "forms/holomorphic_forms.h"
#include "forms/holomorphic_pipeline.h"
#include "forms/homology_basis.h"
#include "forms/periods.h"
#include "job/parts_map.h"
#include "maps/branch_star.h"
#include "maps/floater_embedding.h"
#include "maps/fold_untangling.h"
#include "maps/form_pair_search.h"
#include "maps/form_pairs.h"
#include "maps/form_ratio_map.h"
#include "maps/genus0_correction.h"
#include "maps/genus0_map.h"
#include "maps/genus1_branch_placement.h"
#include "maps/south_cap_prediction.h"
#include "maps/star_kernel.h"
#include "mesh/cotan_laplacian.h"
#include "mesh/face_vectors.h"
#include "mesh/mesh_edges.h"
#include "mesh/mesh_from_arrays.h"
#include "mesh/nonmanifold_split.h"
#include "mesh/prepared_mesh.h"
#include "mesh/surface_parts.h"
#include "mesh/topology.h"
#include "mesh/validation.h"
#include "mesh/zero_area_faces.h"
#include "shapes/generated_surfaces.h"
#include "solvers/cluster_jacobi.h"
#include "solvers/hermitian_cg.h"
#include "solvers/laplacian_solver.h"
#include "solvers/leading_block_solve.h"
#include "solvers/metis_order.h"
#include "solvers/reweighted_solve.h"
#include "sphere/arc_grid.h"
#include "sphere/branch_points.h"
#include "sphere/map_quality.h"
#include "sphere/plane_triangles.h"
#include "sphere/sheets.h"
#include "sphere/sphere_geometry.h"
#include "sphere/texture_coordinates.h"
#include "test_support.h"

namespace meromorph::test {

inline MeshArrays icosphere_arrays(int subdivisions) {
  Mesh mesh;
  make_icosphere(mesh, subdivisions);
  return arrays_from_mesh(mesh);
}

// Two icospheres side by side along x, the second's leftmost vertex merged into the first's
// rightmost: one vertex where two closed surfaces touch.
inline MeshArrays spheres_touching_at_a_vertex(int &shared) {
  MeshArrays one = icosphere_arrays(1), other = one;
  auto extreme = [](const MeshArrays &arrays, double sign) {
    size_t best = 0;
    for (size_t v = 0; v < arrays.positions.size(); ++v)
      if (sign * arrays.positions[v][0] > sign * arrays.positions[best][0]) best = v;
    return int(best);
  };
  shared = extreme(one, 1);
  const int left = extreme(other, -1);
  const Point3 shift = one.positions[size_t(shared)] - other.positions[size_t(left)];
  std::vector<int> renumber(other.positions.size());
  for (size_t v = 0; v < other.positions.size(); ++v) {
    if (int(v) == left) {
      renumber[v] = shared;
      continue;
    }
    renumber[v] = int(one.positions.size());
    one.positions.push_back(other.positions[v] + shift);
  }
  for (const auto &t : other.triangles)
    one.triangles.push_back(
        {renumber[size_t(t[0])], renumber[size_t(t[1])], renumber[size_t(t[2])]});
  return one;
}

inline std::vector<Eigen::Vector3d> vertex_positions(const Mesh &mesh) {
  std::vector<Eigen::Vector3d> positions;
  for (const MeshVertex &vertex : mesh.vert)
    positions.push_back(vertex.cP().ToEigenVector<Eigen::Vector3d>());
  return positions;
}

// The vertex positions pushed out onto the unit sphere.
inline std::vector<Eigen::Vector3d> unit_positions(const Mesh &mesh) {
  std::vector<Eigen::Vector3d> positions = vertex_positions(mesh);
  for (Eigen::Vector3d &p : positions)
    p.normalize();
  return positions;
}

inline int folded_count(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere) {
  int count = 0;
  for (size_t f = 0; f < in.corners.size(); ++f)
    count += folded_face(in, sphere, int(f));
  return count;
}

} // namespace meromorph::test
