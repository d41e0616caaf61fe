// Texture coordinates from sphere positions.
//
// In:  a mesh, a unit-sphere position per vertex, and the kind of coordinates.
// Out: per vertex (u, v) and per face corner (wedge) (u, v).
//      Spherical: u = phi / 2 pi + 1/2, v = theta / pi (phi the longitude, theta the angle from the
//      north pole), as in the paper's figures. Wedges are seam-correct: a face that straddles
//      phi = +-pi gets its corners unwrapped (u may exceed 1, for a repeating texture), and a
//      corner at a pole takes the longitude of the face's other corners. A face whose image
//      contains a pole has corners all around it in longitude: no wedge layout keeps it from
//      spanning the texture; `around_pole` marks those faces (a few per layer). Stereographic: the
//      plane coordinate w of sphere_geometry.h, (u, v) = (Re w, Im w), capped at 1e6 in magnitude
//      near the north pole; wedges equal the vertex values.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace meromorph {

enum class UvKind { spherical, stereographic };

struct TextureCoordinates {
  std::vector<std::array<double, 2>> vertex;
  std::vector<std::array<std::array<double, 2>, 3>> wedge;
  std::vector<char> around_pole; // per face
};

// The texture coordinates of one sphere position (as at a vertex above).
std::array<double, 2> texture_coordinate(const Eigen::Vector3d &p, UvKind kind);

TextureCoordinates texture_coordinates(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere,
                                       UvKind kind);

} // namespace meromorph
