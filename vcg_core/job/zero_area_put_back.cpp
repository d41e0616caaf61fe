#include "job/zero_area_put_back.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/wording.h"
#include "job/carry_back.h"
#include "job/parts_map.h"
#include "job/zero_area_images.h"

namespace meromorph {
namespace {

// The zero-area faces' images oriented (zero_area_images.h), and what follows the moved
// positions: the layered sphere, the texture coordinates at the vertices and the face corners.
void orient_put_back_faces(const Mesh &whole, const ZeroAreaFix &fix,
                           const std::vector<int> &representative,
                           const ParameterizeOptions &options, Parameterization &map) {
  const size_t vertex_count = whole.vert.size();
  std::vector<char> is_copy(vertex_count), is_branch(vertex_count);
  for (size_t v = 0; v < vertex_count; ++v) {
    is_copy[v] = representative[size_t(fix.vertex_in_work[v])] != int(v);
    is_branch[v] = map.branch_flag[v] > 1;
  }
  const std::vector<Eigen::Vector3d> before = map.sphere;
  const std::vector<int> moved =
      orient_zero_area_images(whole, fix.zero_area_faces, is_copy, is_branch, map.sphere);
  if (moved.empty()) return;
  // Packed parts' texture coordinates are scaled into their cells.
  const size_t parts = std::max<size_t>(1, map.components.size());
  const double cells = options.pack_uv ? texture_grid_cells(parts) : 1.0;
  std::vector<std::array<double, 2>> shift(vertex_count, {0.0, 0.0});
  for (int v : moved) {
    const size_t i = size_t(v);
    map.layered[i] +=
        (map.sphere[i] - before[i]) * (1.0 + options.layer_gap * map.sheets.vertex_layer[i]);
    const auto from = texture_coordinate(before[i], options.uv_kind),
               to = texture_coordinate(map.sphere[i], options.uv_kind);
    double du = to[0] - from[0];
    if (options.uv_kind == UvKind::spherical) du -= std::round(du); // across the seam
    shift[i] = {du / cells, (to[1] - from[1]) / cells};
    map.uv.vertex[i][0] += shift[i][0];
    map.uv.vertex[i][1] += shift[i][1];
  }
  for (size_t f = 0; f < whole.face.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto &d = shift[size_t(index_of(whole, whole.face[f].cV(k)))];
      map.uv.wedge[f][size_t(k)][0] += d[0];
      map.uv.wedge[f][size_t(k)][1] += d[1];
    }
  map.notes.push_back(plural(moved.size(), "vertex", "vertices") +
                      " of zero-area faces moved a little on the sphere so that their images, "
                      "and those of the faces around them, are turned the right way");
}

} // namespace

void with_zero_area_faces(const Mesh &whole, const ZeroAreaFix &fix,
                          const ParameterizeOptions &options, Parameterization &map) {
  const std::vector<int> representative =
      carry_back(whole, map.sphere.size(), fix.vertex_in_work, fix.face_in_work, options, map);
  orient_put_back_faces(whole, fix, representative, options, map);
}

} // namespace meromorph
