#include "maps/fold_untangling.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "maps/branch_star.h"
#include "maps/floater_embedding.h"
#include "maps/star_kernel.h"
#include "mesh/mesh_edges.h"
#include "sphere/branch_points.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {
namespace {

constexpr int largest_ring = 5;

// The Chebyshev centre of vertex v's star kernel (star_kernel.h) in the gnomonic chart at
// `centre`, on the sphere; nothing where its ring is not one cycle, leaves the chart or has no
// kernel.
std::optional<Eigen::Vector3d> kernel_point(const FaceIncidence &incidence,
                                            const std::vector<Eigen::Vector3d> &sphere, int v,
                                            const Eigen::Vector3d &centre) {
  const std::vector<int> ring = ordered_ring(incidence, v);
  if (ring.empty()) return std::nullopt;
  const GnomonicChart chart(centre);
  std::vector<Eigen::Vector2d> points(ring.size());
  for (size_t j = 0; j < ring.size(); ++j)
    if (!chart.to_chart(sphere[size_t(ring[j])], points[j])) return std::nullopt;
  const auto inside = star_kernel_centre(points);
  if (!inside) return std::nullopt;
  return chart.to_sphere(inside->first);
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
  const auto &faces_of = incidence.faces_of_vertex;
  const RingDistances ring_of = ring_distances(incidence, seeds, rings + 1);
  auto is_free = [&](int v) {
    const auto at = ring_of.find(v);
    return at != ring_of.end() && at->second <= rings && !is_fixed[size_t(v)];
  };
  const GnomonicChart gnomonic(centre);
  PlanePositions chart;
  for (const auto &[v, r] : ring_of)
    if (!gnomonic.to_chart(sphere[size_t(v)], chart[v])) return false;
  std::set<int> region_faces;
  std::vector<int> free;
  for (const auto &[v, r] : ring_of)
    if (is_free(v)) {
      free.push_back(v);
      for (int g : faces_of[size_t(v)])
        region_faces.insert(g);
    }
  if (free.empty() || !floater_embedding(mesh, incidence, free, chart)) return false;
  std::vector<std::pair<int, Eigen::Vector3d>> before;
  for (int v : free) {
    before.push_back({v, sphere[size_t(v)]});
    sphere[size_t(v)] = gnomonic.to_sphere(chart[v]);
  }
  for (int g : region_faces) {
    if (folded_face(incidence, sphere, g)) {
      for (const auto &[v, p] : before)
        sphere[size_t(v)] = p;
      return false;
    }
  }
  return true;
}

// Face f still folded: its region re-embedded, widening until it holds (next to a branch vertex
// too: it stays on the rim); beside a branch vertex, else, the rings around its star re-embedded
// about its value. Returns whether it worked.
bool reembed_folded_face(const PreparedMesh &prepared, const std::vector<char> &is_fixed,
                         std::vector<Eigen::Vector3d> &sphere, size_t f) {
  const Mesh &mesh = prepared.mesh;
  const FaceIncidence &incidence = prepared.incidence;
  const auto &corners = incidence.corners;
  const std::vector<int> seeds(corners[f].begin(), corners[f].end());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int v : seeds)
    mean += sphere[size_t(v)];
  if (!(mean.norm() > 0)) return false;
  bool done = false;
  for (int rings = 1; rings <= largest_ring && !done; ++rings)
    done = reembed(mesh, incidence, is_fixed, sphere, seeds, rings, mean.normalized());
  // Beside a branch vertex: the rings around its star re-embedded about its value, its one-ring
  // kept; else with its one-ring (a fold within the star).
  for (const OneRing one_ring : {OneRing::kept, OneRing::moves})
    for (const auto &[b, d] : ring_distances(incidence, seeds, 2))
      for (int rings = one_ring == OneRing::kept ? 2 : 1;
           rings <= largest_ring && !done && is_fixed[size_t(b)]; ++rings)
        if (const auto around =
                reembed_around_branch(mesh, incidence, sphere, b, rings, one_ring)) {
          std::vector<std::pair<int, Eigen::Vector3d>> before;
          for (const auto &[w, point] : *around) {
            before.push_back({w, sphere[size_t(w)]});
            sphere[size_t(w)] = point;
          }
          done = true;
          for (const auto &[w, point] : *around)
            for (int g : incidence.faces_of_vertex[size_t(w)])
              done = done && !folded_face(incidence, sphere, g);
          if (!done)
            for (const auto &[w, point] : before)
              sphere[size_t(w)] = point;
        }
  return done;
}

} // namespace

int untangle_folds(const PreparedMesh &prepared, std::vector<Eigen::Vector3d> &sphere,
                   const std::vector<int> &fixed) {
  const Mesh &mesh = prepared.mesh;
  const FaceIncidence &incidence = prepared.incidence;
  const auto &corners = incidence.corners;
  const auto &faces_of = incidence.faces_of_vertex;
  std::vector<char> is_fixed(mesh.vert.size(), 0);
  for (int v : fixed)
    is_fixed[v] = 1;
  auto folded = [&](int f) { return folded_face(incidence, sphere, f); };
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
        // v at `point` if fewer faces around it are folded there, else back where it was.
        auto moves_to = [&](const Eigen::Vector3d &point) {
          sphere[v] = point;
          if (folded_around(v) < before) return true;
          sphere[v] = original;
          return false;
        };
        // To its one-ring's mean; else into its star's kernel (where every face around it turns
        // the right way), in the gnomonic chart at that mean, if the ring leaves one.
        bool unfolded = moves_to(mean.normalized());
        if (!unfolded)
          if (const auto inside = kernel_point(incidence, sphere, v, mean.normalized()))
            unfolded = moves_to(*inside);
        if (unfolded) {
          ++moved;
          changed = true;
          break;
        }
      }
    }
    if (!changed) break;
  }
  // What is still folded: its region re-embedded.
  for (size_t f = 0; f < mesh.face.size(); ++f)
    if (folded(int(f))) moved += reembed_folded_face(prepared, is_fixed, sphere, f);
  return moved;
}

} // namespace meromorph
