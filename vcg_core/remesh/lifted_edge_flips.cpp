#include "remesh/lifted_edge_flips.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <Eigen/Geometry>

#include "mesh/face_vectors.h"

namespace meromorph {
namespace {

using Side = std::pair<int, int>;

Side side(int a, int b) {
  return a < b ? Side{a, b} : Side{b, a};
}

Eigen::Vector3d unit_normal(const LiftedSphere &lifted, const std::array<int, 3> &face) {
  const Eigen::Vector3d &p = lifted.positions[face[0]];
  const Eigen::Vector3d n = (lifted.positions[face[1]] - p).cross(lifted.positions[face[2]] - p);
  const double norm = n.norm();
  return norm > 0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d::Zero();
}

double bend(const LiftedSphere &lifted, const std::array<int, 3> &f, const std::array<int, 3> &g) {
  return std::acos(std::clamp(unit_normal(lifted, f).dot(unit_normal(lifted, g)), -1.0, 1.0));
}

// Corner k of `face` rotated to the front.
std::array<int, 3> rotated(const std::array<int, 3> &face, int k) {
  return {face[k], face[(k + 1) % 3], face[(k + 2) % 3]};
}

} // namespace

int flip_lifted_edges(const MappedSurface &surface, int passes, LiftedSphere &lifted) {
  int flips = 0;
  std::vector<int> faces_at(lifted.positions.size(), 0);
  for (const auto &face : lifted.faces)
    for (int v : face)
      ++faces_at[v];
  for (int pass = 0; pass < passes; ++pass) {
    std::map<Side, std::array<int, 2>> faces_of; // side -> (face with it as a -> b, the other)
    for (size_t f = 0; f < lifted.faces.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = lifted.faces[f][k], b = lifted.faces[f][(k + 1) % 3];
        auto [entry, added] = faces_of.try_emplace(side(a, b), std::array<int, 2>{-1, -1});
        entry->second[a < b ? 0 : 1] = int(f);
      }
    std::set<Side> sides;
    for (const auto &entry : faces_of)
      sides.insert(entry.first);
    std::vector<char> touched(lifted.faces.size(), 0);
    int flipped = 0;
    for (const auto &[ends, pair] : faces_of) {
      if (pair[0] < 0 || pair[1] < 0 || touched[pair[0]] || touched[pair[1]]) continue;
      const auto &f0 = lifted.faces[pair[0]], &g0 = lifted.faces[pair[1]];
      int kf = 0, kg = 0;
      while (f0[kf] != ends.first)
        ++kf;
      while (g0[kg] != ends.second)
        ++kg;
      const std::array<int, 3> f = rotated(f0, kf),
                               g = rotated(g0, kg); // f = (a, b, c), g = (b, a, d)
      const int a = f[0], b = f[1], c = f[2], d = g[2];
      if (c == d || sides.count(side(c, d)) || faces_at[a] <= 4 || faces_at[b] <= 4) continue;
      const double opposite =
          corner_angle(lifted.positions[c], lifted.positions[a], lifted.positions[b]) +
          corner_angle(lifted.positions[d], lifted.positions[b], lifted.positions[a]);
      // A folded pair is flipped whenever the flip unfolds it.
      const bool unfolds =
          lifted_face_folds(surface, lifted, f) || lifted_face_folds(surface, lifted, g);
      if (opposite <= M_PI && !unfolds) continue;
      const std::array<int, 3> nf{a, d, c}, ng{d, b, c};
      if (!positive_on_sphere(lifted, nf) || !positive_on_sphere(lifted, ng)) continue;
      if (lifted_face_folds(surface, lifted, nf) || lifted_face_folds(surface, lifted, ng))
        continue;
      if (!unfolds &&
          (bend(lifted, nf, ng) > bend(lifted, f, g) + 10.0 * M_PI / 180.0 ||
           std::min(smallest_corner_angle(lifted, nf), smallest_corner_angle(lifted, ng)) <=
               std::min(smallest_corner_angle(lifted, f), smallest_corner_angle(lifted, g))))
        continue;
      lifted.faces[pair[0]] = nf;
      lifted.faces[pair[1]] = ng;
      touched[pair[0]] = touched[pair[1]] = 1;
      sides.erase(ends);
      sides.insert(side(c, d));
      --faces_at[a];
      --faces_at[b];
      ++faces_at[c];
      ++faces_at[d];
      ++flipped;
    }
    flips += flipped;
    if (flipped == 0) break;
  }
  lifted.folded_lifts = count_folded_lifts(surface, lifted);
  return flips;
}

} // namespace meromorph
