#include "fold_untangling.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "mesh_edges.h"
#include "sphere_geometry.h"

namespace meromorph {
namespace {

constexpr int largest_ring = 5;

// Mean-value weight of the edge i -> j from the surface: (tan(alpha / 2) + tan(beta / 2)) / |ij|,
// alpha and beta the angles at i of the two faces on the edge; positive on any triangulation.
double mean_value_weight(const Mesh &mesh, const std::array<int, 3> &face, int i) {
  const Point3 &p = mesh.vert[size_t(face[size_t(i)])].cP(),
               &q = mesh.vert[size_t(face[size_t((i + 1) % 3)])].cP(),
               &r = mesh.vert[size_t(face[size_t((i + 2) % 3)])].cP();
  const Point3 a = q - p, b = r - p;
  const double angle = std::atan2((a ^ b).Norm(), a * b);
  return std::tan(angle / 2);
}

// Re-embeds the region within `rings` rings of `seeds` in the gnomonic chart at `centre` (which
// maps great circles to lines, so a face's orientation on the sphere is its orientation there):
// its free vertices (not fixed, not on the rim) go to the mean-value-weighted mean of their
// neighbours (Floater's embedding: no fold when the rim is convex), the rim and fixed vertices
// stay (a branch vertex on the rim keeps its star). Kept only if no face of the region is folded
// afterwards.
bool reembed(const Mesh &mesh, const FaceIncidence &incidence, const std::vector<char> &is_fixed,
             std::vector<Eigen::Vector3d> &sphere, const std::vector<int> &seeds, int rings,
             const Eigen::Vector3d &centre) {
  const auto &corners = incidence.corners;
  const auto &faces_of = incidence.faces_of_vertex;
  const std::map<int, int> ring_of = ring_distances(incidence, seeds, rings + 1);
  auto is_free = [&](int v) {
    const auto at = ring_of.find(v);
    return at != ring_of.end() && at->second <= rings && !is_fixed[size_t(v)];
  };
  const Eigen::Vector3d u1 = centre.unitOrthogonal(), u2 = centre.cross(u1);
  std::map<int, Eigen::Vector2d> chart;
  for (const auto &[v, r] : ring_of) {
    const double height = sphere[size_t(v)].dot(centre);
    if (!(height > 0.1)) return false; // too far round the sphere for one chart
    const Eigen::Vector3d p = sphere[size_t(v)] / height;
    chart[v] = {p.dot(u1), p.dot(u2)};
  }
  std::set<int> region_faces;
  for (const auto &[v, r] : ring_of)
    if (is_free(v))
      for (int g : faces_of[size_t(v)])
        region_faces.insert(g);
  // Mean-value weights of the free vertices' edges.
  std::map<int, std::map<int, double>> weight;
  for (const auto &[v, r] : ring_of) {
    if (!is_free(v)) continue;
    for (int g : faces_of[size_t(v)]) {
      const auto &t = corners[size_t(g)];
      const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      const int ahead = t[size_t((k + 1) % 3)], behind = t[size_t((k + 2) % 3)];
      const double w = mean_value_weight(mesh, t, k);
      const double to_ahead = (mesh.vert[size_t(v)].cP() - mesh.vert[size_t(ahead)].cP()).Norm(),
                   to_behind = (mesh.vert[size_t(v)].cP() - mesh.vert[size_t(behind)].cP()).Norm();
      if (!(to_ahead > 0 && to_behind > 0 && std::isfinite(w))) return false;
      weight[v][ahead] += w / to_ahead;
      weight[v][behind] += w / to_behind;
    }
  }
  if (weight.empty()) return false;
  for (int sweep = 0; sweep < 1000; ++sweep) { // Gauss-Seidel: the system is small
    double change = 0;
    for (auto &[v, neighbours] : weight) {
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      double total = 0;
      for (const auto &[w, value] : neighbours) {
        sum += value * chart[w];
        total += value;
      }
      const Eigen::Vector2d moved = sum / total;
      change = std::max(change, (moved - chart[v]).norm());
      chart[v] = moved;
    }
    if (change < 1e-15) break;
  }
  std::vector<std::pair<int, Eigen::Vector3d>> before;
  auto place = [&](int v, const Eigen::Vector2d &p) {
    before.push_back({v, sphere[size_t(v)]});
    sphere[size_t(v)] = (centre + p.x() * u1 + p.y() * u2).normalized();
  };
  for (const auto &[v, neighbours] : weight)
    place(v, chart[v]);
  for (int g : region_faces) {
    const auto &t = corners[size_t(g)];
    if (folded_image(sphere[size_t(t[0])], sphere[size_t(t[1])], sphere[size_t(t[2])])) {
      for (const auto &[v, p] : before)
        sphere[size_t(v)] = p;
      return false;
    }
  }
  return true;
}

} // namespace

int untangle_folds(const Mesh &mesh, std::vector<Eigen::Vector3d> &sphere,
                   const std::vector<int> &fixed) {
  const FaceIncidence incidence = face_incidence(mesh);
  const auto &corners = incidence.corners;
  const auto &faces_of = incidence.faces_of_vertex;
  std::vector<char> is_fixed(mesh.vert.size(), 0);
  for (int v : fixed)
    is_fixed[v] = 1;
  auto folded = [&](int f) {
    return folded_image(sphere[corners[f][0]], sphere[corners[f][1]], sphere[corners[f][2]]);
  };
  auto folded_around = [&](int v) {
    int count = 0;
    for (int f : faces_of[v])
      count += folded(f);
    return count;
  };

  int moved = 0;
  for (int pass = 0; pass < 3; ++pass) {
    bool changed = false;
    for (size_t f = 0; f < mesh.face.size(); ++f) {
      if (!folded(int(f))) continue;
      bool near_fixed = false;
      for (int v : corners[f])
        near_fixed |= is_fixed[v] != 0;
      if (near_fixed) continue;
      for (int v : corners[f]) {
        std::set<int> ring;
        for (int g : faces_of[v])
          for (int w : corners[g])
            if (w != v) ring.insert(w);
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for (int w : ring)
          mean += sphere[w];
        if (mean.norm() == 0) continue;
        const Eigen::Vector3d original = sphere[v];
        const int before = folded_around(v);
        sphere[v] = mean.normalized();
        if (folded_around(v) < before) {
          ++moved;
          changed = true;
          break;
        }
        sphere[v] = original;
      }
    }
    if (!changed) break;
  }
  // What is still folded: its region re-embedded, widening until it holds (next to a branch
  // vertex too: it stays on the rim).
  for (size_t f = 0; f < mesh.face.size(); ++f) {
    if (!folded(int(f))) continue;
    const std::vector<int> seeds(corners[f].begin(), corners[f].end());
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int v : seeds)
      mean += sphere[size_t(v)];
    if (!(mean.norm() > 0)) continue;
    for (int rings = 1; rings <= largest_ring; ++rings)
      if (reembed(mesh, incidence, is_fixed, sphere, seeds, rings, mean.normalized())) {
        ++moved;
        break;
      }
  }
  return moved;
}

} // namespace meromorph
