#include "mesh/zero_area_faces.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

#include "common/errors.h"
#include "mesh/mesh_from_arrays.h"
#include "mesh/validation.h"

namespace meromorph {
namespace {

// A needle: its shortest edge is below this fraction of its longest (else it is a cap).
constexpr double needle_ratio = 1e-4;
constexpr int most_passes = 8;

struct Work {
  MeshArrays mesh;
  std::vector<char> alive;
  std::vector<int> origin;      // per face: the input face it still is, -1 once changed
  std::vector<int> merged_into; // per vertex: itself, or the vertex it was merged into
};

bool zero_area(const Work &w, const std::array<int, 3> &t) {
  return has_zero_area(w.mesh.positions[size_t(t[0])], w.mesh.positions[size_t(t[1])],
                       w.mesh.positions[size_t(t[2])]);
}

double length(const Work &w, int a, int b) {
  return (w.mesh.positions[size_t(a)] - w.mesh.positions[size_t(b)]).Norm();
}

std::string face_name(const Work &w, size_t f) {
  return w.origin[f] >= 0 ? "face " + std::to_string(w.origin[f])
                          : "a face at vertex " + std::to_string(w.mesh.triangles[f][0]);
}

} // namespace

ZeroAreaFix take_out_zero_area_faces(const Mesh &input, Mesh &work_mesh) {
  Work w;
  w.mesh = arrays_from_mesh(input);
  const size_t face_count = w.mesh.triangles.size(), vertex_count = w.mesh.positions.size();
  w.alive.assign(face_count, 1);
  w.origin.resize(face_count);
  std::iota(w.origin.begin(), w.origin.end(), 0);
  w.merged_into.resize(vertex_count);
  std::iota(w.merged_into.begin(), w.merged_into.end(), 0);

  ZeroAreaFix out;
  for (size_t f = 0; f < face_count; ++f)
    if (zero_area(w, w.mesh.triangles[f])) out.zero_area_faces.push_back(int(f));

  for (int pass = 0;; ++pass) {
    std::vector<size_t> flat;
    for (size_t f = 0; f < face_count; ++f)
      if (w.alive[f] && zero_area(w, w.mesh.triangles[f])) flat.push_back(f);
    if (flat.empty()) break;
    if (pass == most_passes)
      throw InputError(face_name(w, flat[0]) +
                       " has zero area and stays so after edge flips and collapses around it; "
                       "remesh there");
    // Faces by directed edge and by vertex, for this pass; a vertex next to a change waits for
    // the next pass.
    std::map<std::pair<int, int>, size_t> face_of_edge;
    std::vector<std::vector<size_t>> faces_at(vertex_count);
    for (size_t f = 0; f < face_count; ++f)
      if (w.alive[f])
        for (int k = 0; k < 3; ++k) {
          const auto &t = w.mesh.triangles[f];
          face_of_edge[{t[size_t(k)], t[size_t((k + 1) % 3)]}] = f;
          faces_at[size_t(t[size_t(k)])].push_back(f);
        }
    std::vector<char> touched(vertex_count, 0);
    auto touch_around = [&](int v) {
      for (size_t g : faces_at[size_t(v)])
        for (int u : w.mesh.triangles[g])
          touched[size_t(u)] = 1;
    };
    for (size_t f : flat) {
      const std::array<int, 3> t = w.mesh.triangles[f];
      if (!w.alive[f] || touched[size_t(t[0])] || touched[size_t(t[1])] || touched[size_t(t[2])])
        continue;
      std::array<double, 3> side; // side k joins corners k and k + 1
      for (int k = 0; k < 3; ++k)
        side[size_t(k)] = length(w, t[size_t(k)], t[size_t((k + 1) % 3)]);
      const int shortest = int(std::min_element(side.begin(), side.end()) - side.begin()),
                longest = int(std::max_element(side.begin(), side.end()) - side.begin());
      // A cap's middle vertex with no face but the cap and the two beside it (a T-junction) is
      // merged into the nearer end of the long side: the face it split comes back whole.
      const int middle = t[size_t((longest + 2) % 3)];
      const bool needle = side[size_t(shortest)] <= needle_ratio * side[size_t(longest)];
      const bool t_junction = !needle && faces_at[size_t(middle)].size() == 3;
      if (needle || t_junction) {
        int keep, gone;
        if (needle) {
          const int a = t[size_t(shortest)], b = t[size_t((shortest + 1) % 3)];
          keep = std::min(a, b);
          gone = std::max(a, b);
        } else {
          const int a = t[size_t(longest)], b = t[size_t((longest + 1) % 3)];
          keep = length(w, middle, a) <= length(w, middle, b) ? a : b;
          gone = middle;
        }
        // Collapse: the vertices next to both ends must be the edge's two opposite corners only.
        std::set<int> around_keep, around_gone, opposite;
        for (size_t g : faces_at[size_t(keep)])
          for (int u : w.mesh.triangles[g])
            around_keep.insert(u);
        for (size_t g : faces_at[size_t(gone)]) {
          const auto &s = w.mesh.triangles[g];
          const bool on_edge = std::count(s.begin(), s.end(), keep) > 0;
          for (int u : s) {
            around_gone.insert(u);
            if (on_edge && u != keep && u != gone) opposite.insert(u);
          }
        }
        std::vector<int> common;
        std::set_intersection(around_keep.begin(), around_keep.end(), around_gone.begin(),
                              around_gone.end(), std::back_inserter(common));
        common.erase(std::remove_if(common.begin(), common.end(),
                                    [&](int u) { return u == keep || u == gone; }),
                     common.end());
        if (std::set<int>(common.begin(), common.end()) != opposite)
          throw InputError(face_name(w, f) + " has zero area (vertices " + std::to_string(keep) +
                           " and " + std::to_string(gone) + (needle ? " coincide" : " in line") +
                           "), and merging them would change the surface's topology; remesh "
                           "there");
        touch_around(keep);
        touch_around(gone);
        for (size_t g : faces_at[size_t(gone)]) {
          auto &s = w.mesh.triangles[g];
          if (std::count(s.begin(), s.end(), keep)) {
            w.alive[g] = 0;
            continue;
          }
          for (int &u : s)
            if (u == gone) u = keep;
        }
        w.merged_into[size_t(gone)] = keep;
        ++out.collapsed_edges;
      } else {
        // Flip the longest edge a -> b with the face across it (b -> a -> d).
        const int a = t[size_t(longest)], b = t[size_t((longest + 1) % 3)],
                  m = t[size_t((longest + 2) % 3)];
        const auto across = face_of_edge.find({b, a});
        if (across == face_of_edge.end())
          throw InputError(face_name(w, f) +
                           " has zero area and its longest edge is on a hole; remesh there");
        const size_t g = across->second;
        const auto &s = w.mesh.triangles[g];
        int d = -1;
        for (int u : s)
          if (u != a && u != b) d = u;
        if (d < 0 || d == m || face_of_edge.count({m, d}) || face_of_edge.count({d, m}))
          throw InputError(face_name(w, f) +
                           " has zero area and its longest edge cannot be flipped; remesh there");
        touch_around(a);
        touch_around(b);
        w.mesh.triangles[f] = {m, a, d};
        w.mesh.triangles[g] = {m, d, b};
        w.origin[f] = w.origin[g] = -1;
        ++out.flipped_edges;
      }
    }
  }

  // The vertices left, in order; faces left, in order.
  std::vector<int> compact(vertex_count, -1);
  MeshArrays result;
  for (size_t v = 0; v < vertex_count; ++v)
    if (w.merged_into[v] == int(v)) {
      compact[v] = int(result.positions.size());
      result.positions.push_back(w.mesh.positions[v]);
    }
  out.vertex_in_work.resize(vertex_count);
  for (size_t v = 0; v < vertex_count; ++v) {
    int root = int(v);
    while (w.merged_into[size_t(root)] != root)
      root = w.merged_into[size_t(root)];
    out.vertex_in_work[v] = compact[size_t(root)];
  }
  out.face_in_work.assign(face_count, -1);
  for (size_t f = 0; f < face_count; ++f) {
    if (!w.alive[f]) continue;
    if (w.origin[f] >= 0) out.face_in_work[size_t(w.origin[f])] = int(result.triangles.size());
    std::array<int, 3> t = w.mesh.triangles[f];
    for (int &u : t)
      u = compact[size_t(u)];
    result.triangles.push_back(t);
  }
  mesh_from_arrays(result, work_mesh);
  return out;
}

} // namespace meromorph
