#include "fold_untangling.h"

#include <set>

#include "mesh_edges.h"
#include "sphere_geometry.h"

namespace meromorph {

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
  return moved;
}

} // namespace meromorph
