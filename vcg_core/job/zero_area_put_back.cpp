#include "job/zero_area_put_back.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/wording.h"
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
  const size_t vertex_count = whole.vert.size(), face_count = whole.face.size();
  std::vector<int> representative(map.sphere.size(), -1); // per work vertex: a whole vertex
  for (size_t v = 0; v < vertex_count; ++v)
    if (representative[size_t(fix.vertex_in_work[v])] < 0)
      representative[size_t(fix.vertex_in_work[v])] = int(v);
  auto expand = [&](auto &values, auto blank) {
    auto old = std::move(values);
    values.assign(vertex_count, blank);
    if (old.empty()) return;
    for (size_t v = 0; v < vertex_count; ++v)
      values[v] = old[size_t(fix.vertex_in_work[v])];
  };
  expand(map.sphere, Eigen::Vector3d::Zero().eval());
  expand(map.layered, Eigen::Vector3d::Zero().eval());
  expand(map.uv.vertex, std::array<double, 2>{});
  expand(map.sheets.vertex_layer, 0);
  if (!map.flat.empty()) expand(map.flat, Complex(0, 0));
  if (!map.vertex_component.empty()) expand(map.vertex_component, 0);
  std::vector<int> branch_flag = std::move(map.branch_flag);
  map.branch_flag.assign(vertex_count, 0);
  for (size_t w = 0; w < representative.size(); ++w)
    if (representative[w] >= 0) map.branch_flag[size_t(representative[w])] = branch_flag[w];
  auto to_whole = [&](int &vertex) {
    if (vertex >= 0) vertex = representative[size_t(vertex)];
  };
  for (BranchPoint &b : map.branch_points)
    to_whole(b.vertex);
  for (Parameterization &part : map.components)
    for (BranchPoint &b : part.branch_points)
      to_whole(b.vertex);
  for (ClosedHoleReport &hole : map.holes_closed)
    to_whole(hole.vertex);
  to_whole(map.origin_vertex);

  auto wedge = std::move(map.uv.wedge);
  auto around_pole = std::move(map.uv.around_pole);
  auto face_layer = std::move(map.sheets.face_layer);
  map.uv.wedge.resize(face_count);
  map.uv.around_pole.assign(face_count, 0);
  map.sheets.face_layer.assign(face_count, 0);
  for (size_t f = 0; f < face_count; ++f) {
    const int in_work = fix.face_in_work[f];
    if (in_work >= 0) {
      map.uv.wedge[f] = wedge[size_t(in_work)];
      map.uv.around_pole[f] = around_pole[size_t(in_work)];
      map.sheets.face_layer[f] = face_layer[size_t(in_work)];
      continue;
    }
    const MeshFace &face = whole.face[f];
    for (int k = 0; k < 3; ++k) {
      auto uv = map.uv.vertex[size_t(index_of(whole, face.cV(k)))];
      if (options.uv_kind == UvKind::spherical && k > 0) // beside the first corner across the seam
        uv[0] += std::round(map.uv.wedge[f][0][0] - uv[0]);
      map.uv.wedge[f][size_t(k)] = uv;
    }
    map.sheets.face_layer[f] = map.sheets.vertex_layer[size_t(index_of(whole, face.cV(0)))];
  }
  orient_put_back_faces(whole, fix, representative, options, map);
  if (map.pole_face >= 0)
    for (size_t f = 0; f < face_count; ++f)
      if (fix.face_in_work[f] == map.pole_face) {
        map.pole_face = int(f);
        break;
      }
}

} // namespace meromorph
