// Random rigid motions (and uniform scales), reproducible from a seed on every platform.
//
// In:  a 64-bit seed (and for `apply_similarity`, a mesh).
// Out: a rotation drawn uniformly from SO(3) (Shoemake's quaternion method) and a translation in
//      [-1, 1]^3, from std::mt19937_64 whose output the C++ standard fixes; the mesh moved by
//      x -> scale * R x + t.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace meromorph {

struct Similarity {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double scale = 1.0;
};

Similarity random_rigid_motion(std::uint64_t seed);

void apply_similarity(const Similarity &motion, Mesh &mesh);

} // namespace meromorph
