#include "job/carry_back.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace meromorph {
namespace {

struct Numbering {
  size_t whole_vertices, work_vertices, copies;
  const std::vector<int> &vertex_in_work;
  std::vector<int> first_whole; // per work vertex
  // A vertex of the work mesh (or of its split) in the whole mesh's numbering (or its split's).
  int of(int work_vertex) const {
    if (work_vertex < 0) return work_vertex;
    if (size_t(work_vertex) >= work_vertices)
      return int(whole_vertices + (size_t(work_vertex) - work_vertices));
    return first_whole[size_t(work_vertex)];
  }
  template <class T> void spread(std::vector<T> &values, const T &blank) const {
    if (values.empty()) return;
    std::vector<T> old = std::move(values);
    values.assign(whole_vertices + copies, blank);
    for (size_t v = 0; v < whole_vertices; ++v)
      if (vertex_in_work[v] >= 0) values[v] = old[size_t(vertex_in_work[v])];
    for (size_t c = 0; c < copies; ++c)
      values[whole_vertices + c] = old[work_vertices + c];
  }
};

void rename_vertices(const Numbering &numbering, Parameterization &map) {
  auto rename = [&](int &vertex) { vertex = numbering.of(vertex); };
  for (BranchPoint &b : map.branch_points) {
    rename(b.vertex);
    rename(b.sphere_vertex);
  }
  for (Parameterization &part : map.components)
    for (BranchPoint &b : part.branch_points)
      rename(b.vertex);
  for (ClosedHoleReport &hole : map.holes_closed)
    rename(hole.vertex);
  rename(map.origin_vertex);
  for (int &v : map.nonmanifold_split.vertices)
    rename(v);
  for (auto &edge : map.nonmanifold_split.edges)
    for (int &v : edge)
      rename(v);
}

void spread_vertex_values(const Numbering &numbering, const ParameterizeOptions &options,
                          Parameterization &map) {
  const Eigen::Vector3d pole(0, 0, 1);
  numbering.spread(map.sphere, pole);
  numbering.spread(map.layered, pole);
  numbering.spread(map.uv.vertex, texture_coordinate(pole, options.uv_kind));
  numbering.spread(map.sheets.vertex_layer, 0);
  numbering.spread(map.flat, Complex(0, 0));
  numbering.spread(map.vertex_component, 0);
  numbering.spread(map.branch_flag, 0);
  if (!map.sphere_source_vertex.empty()) { // the split's copies follow the whole vertices
    std::vector<int> source(numbering.whole_vertices + numbering.copies);
    std::iota(source.begin(), source.begin() + long(numbering.whole_vertices), 0);
    for (size_t c = 0; c < numbering.copies; ++c)
      source[numbering.whole_vertices + c] =
          numbering.of(map.sphere_source_vertex[numbering.work_vertices + c]);
    map.sphere_source_vertex = std::move(source);
  }
}

// A branch flag stays on the vertex that names the branch point and on others at its very position
// (seam copies), not on vertices merged into it from elsewhere (a needle's end).
void keep_branch_flags_at_branch_points(const Mesh &whole, const Numbering &numbering,
                                        Parameterization &map) {
  for (size_t v = 0; v < numbering.whole_vertices; ++v) {
    const int w = numbering.vertex_in_work[v];
    if (map.branch_flag[v] == 0 || w < 0) continue;
    const size_t named = size_t(numbering.first_whole[size_t(w)]);
    if (named != v && whole.vert[v].cP() != whole.vert[named].cP()) map.branch_flag[v] = 0;
  }
}

void carry_faces_back(const Mesh &whole, const Numbering &numbering,
                      const std::vector<int> &face_in_work, const ParameterizeOptions &options,
                      Parameterization &map) {
  const size_t face_count = whole.face.size();
  auto wedge = std::move(map.uv.wedge);
  auto around_pole = std::move(map.uv.around_pole);
  auto face_layer = std::move(map.sheets.face_layer);
  auto sphere_faces = std::move(map.sphere_faces);
  map.uv.wedge.resize(face_count);
  map.uv.around_pole.assign(face_count, 0);
  map.sheets.face_layer.assign(face_count, 0);
  if (!sphere_faces.empty()) map.sphere_faces.resize(face_count);
  std::vector<int> first_whole_face(wedge.size(), -1);
  for (size_t f = 0; f < face_count; ++f) {
    const MeshFace &face = whole.face[f];
    const int in_work = face_in_work[f];
    if (!sphere_faces.empty())
      for (int k = 0; k < 3; ++k) {
        const int split = in_work >= 0 ? sphere_faces[size_t(in_work)][size_t(k)] : -1;
        map.sphere_faces[f][size_t(k)] = split >= int(numbering.work_vertices)
                                             ? numbering.of(split)
                                             : index_of(whole, face.cV(k));
      }
    if (in_work >= 0) {
      if (first_whole_face[size_t(in_work)] < 0) first_whole_face[size_t(in_work)] = int(f);
      map.uv.wedge[f] = wedge[size_t(in_work)];
      map.uv.around_pole[f] = around_pole[size_t(in_work)];
      map.sheets.face_layer[f] = face_layer[size_t(in_work)];
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      auto uv = map.uv.vertex[size_t(index_of(whole, face.cV(k)))];
      if (options.uv_kind == UvKind::spherical && k > 0) // beside the first corner across the seam
        uv[0] += std::round(map.uv.wedge[f][0][0] - uv[0]);
      map.uv.wedge[f][size_t(k)] = uv;
    }
    map.sheets.face_layer[f] = map.sheets.vertex_layer[size_t(index_of(whole, face.cV(0)))];
  }
  auto rename = [&](int &face) {
    if (face >= 0 && size_t(face) < first_whole_face.size()) face = first_whole_face[size_t(face)];
  };
  rename(map.pole_face);
  for (int &f : map.quality.folded_face_indices)
    rename(f);
  for (int &f : map.quality.collapsed_face_indices)
    rename(f);
}

} // namespace

std::vector<int> carry_back(const Mesh &whole, size_t work_vertex_count,
                            const std::vector<int> &vertex_in_work,
                            const std::vector<int> &face_in_work,
                            const ParameterizeOptions &options, Parameterization &map) {
  Numbering numbering{whole.vert.size(), work_vertex_count,
                      map.sphere.size() - std::min(map.sphere.size(), work_vertex_count),
                      vertex_in_work, std::vector<int>(work_vertex_count, -1)};
  for (size_t v = 0; v < numbering.whole_vertices; ++v) {
    const int w = vertex_in_work[v];
    if (w >= 0 && numbering.first_whole[size_t(w)] < 0) numbering.first_whole[size_t(w)] = int(v);
  }
  spread_vertex_values(numbering, options, map);
  keep_branch_flags_at_branch_points(whole, numbering, map);
  rename_vertices(numbering, map);
  carry_faces_back(whole, numbering, face_in_work, options, map);
  return numbering.first_whole;
}

} // namespace meromorph
