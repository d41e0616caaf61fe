// The sphere mesh that a remesh samples: a geodesic icosphere with the branch values on vertices.
//
// In:  the frequency k >= 1 (each face of the icosahedron cut into k^2 triangles; k = 2^N gives
//      the icosphere of N midpoint subdivisions) and the branch values (unit vectors; values
//      closer than 1e-12 count as one).
// Out: `GeodesicSphere`: 10 k^2 + 2 unit vectors, refined toward every branch value that lies
//      closer than an edge (and 0.05) to another one (faces near it split 1-to-4, neighbours
//      halved, until those faces are smaller than a third of the distance between the two values;
//      + one per branch value that needed a face split), and faces counter-clockwise seen from
//      outside; every branch value is a vertex: the nearest vertex moved onto it (inside its
//      Voronoi cell, so its faces keep their orientation), or, when that vertex already carries
//      another value, the face holding the value split in three; sides around what was refined or
//      moved flipped toward the sphere's Delaunay triangulation; an edge joining two branch values
//      split at its midpoint; per vertex the index of the branch value it carries (among the
//      distinct ones), -1 elsewhere; and its neighbours (counter-clockwise order not promised).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

namespace meromorph {

struct GeodesicSphere {
  int frequency = 1;
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;
  std::vector<int> branch_value; // per vertex
  std::vector<std::vector<int>> neighbours;
};

// `refine_at`: points around which the sphere is refined as around close values, down to an
// eighth of its longest side (where a lift did not close).
GeodesicSphere geodesic_sphere(int frequency, const std::vector<Eigen::Vector3d> &branch_values,
                               const std::vector<Eigen::Vector3d> &refine_at = {});

// The frequency whose sphere, taken `sheets` times less `ramification` vertices, comes nearest
// to `vertices` vertices (at least 1).
int frequency_for_vertices(long long vertices, int sheets, int ramification);

} // namespace meromorph
