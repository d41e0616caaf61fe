#include "shapes/rigid_motion.h"

#include <cmath>
#include <random>

#include <Eigen/Geometry>

namespace meromorph {
namespace {

// A double in [0, 1) from the 53 high bits: unlike std::uniform_real_distribution, the same
// numbers with every standard library.
double uniform01(std::mt19937_64 &generator) {
  return double(generator() >> 11) * 0x1.0p-53;
}

} // namespace

Similarity random_rigid_motion(std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  const double u1 = uniform01(generator), u2 = uniform01(generator), u3 = uniform01(generator);
  const double two_pi = 2.0 * M_PI;
  const Eigen::Quaterniond q(
      std::sqrt(u1) * std::cos(two_pi * u3), std::sqrt(1 - u1) * std::sin(two_pi * u2),
      std::sqrt(1 - u1) * std::cos(two_pi * u2), std::sqrt(u1) * std::sin(two_pi * u3));
  Similarity motion;
  motion.rotation = q.normalized().toRotationMatrix();
  for (int i = 0; i < 3; ++i)
    motion.translation[i] = 2.0 * uniform01(generator) - 1.0;
  return motion;
}

void apply_similarity(const Similarity &motion, Mesh &mesh) {
  for (MeshVertex &vertex : mesh.vert) {
    if (vertex.IsD()) continue;
    const Eigen::Vector3d p = vertex.cP().ToEigenVector<Eigen::Vector3d>();
    const Eigen::Vector3d moved = motion.scale * (motion.rotation * p) + motion.translation;
    vertex.P() = Point3(moved[0], moved[1], moved[2]);
  }
  vcg::tri::UpdateBounding<Mesh>::Box(mesh);
}

} // namespace meromorph
