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

// Faces by directed edge and by vertex, for one pass; a vertex next to a change waits for the
// next pass.
struct Pass {
  std::map<std::pair<int, int>, size_t> face_of_edge;
  std::vector<std::vector<size_t>> faces_at;
  std::vector<char> touched;

  explicit Pass(const Work &w)
      : faces_at(w.mesh.positions.size()), touched(w.mesh.positions.size(), 0) {
    for (size_t f = 0; f < w.mesh.triangles.size(); ++f)
      if (w.alive[f])
        for (int k = 0; k < 3; ++k) {
          const auto &t = w.mesh.triangles[f];
          face_of_edge[{t[size_t(k)], t[size_t((k + 1) % 3)]}] = f;
          faces_at[size_t(t[size_t(k)])].push_back(f);
        }
  }
  void touch_around(const Work &w, int v) {
    for (size_t g : faces_at[size_t(v)])
      for (int u : w.mesh.triangles[g])
        touched[size_t(u)] = 1;
  }
};

// Merges `gone` into `keep` (the edge between them collapsed, its two faces gone). The vertices
// next to both ends must be the edge's two opposite corners only (the link condition), else the
// topology would change: refused, naming face f.
void collapse(Work &w, Pass &pass, size_t f, int keep, int gone, bool needle) {
  std::set<int> around_keep, around_gone, opposite;
  for (size_t g : pass.faces_at[size_t(keep)])
    for (int u : w.mesh.triangles[g])
      around_keep.insert(u);
  for (size_t g : pass.faces_at[size_t(gone)]) {
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
  common.erase(
      std::remove_if(common.begin(), common.end(), [&](int u) { return u == keep || u == gone; }),
      common.end());
  if (std::set<int>(common.begin(), common.end()) != opposite)
    throw InputError(face_name(w, f) + " has zero area (vertices " + std::to_string(keep) +
                     " and " + std::to_string(gone) + (needle ? " coincide" : " in line") +
                     "), and merging them would change the surface's topology; remesh there");
  pass.touch_around(w, keep);
  pass.touch_around(w, gone);
  for (size_t g : pass.faces_at[size_t(gone)]) {
    auto &s = w.mesh.triangles[g];
    if (std::count(s.begin(), s.end(), keep)) {
      w.alive[g] = 0;
      continue;
    }
    for (int &u : s)
      if (u == gone) u = keep;
  }
  w.merged_into[size_t(gone)] = keep;
}

// Flips face f's side from corner `longest` to the next (a -> b) with the face across it
// (b -> a -> d): (m, a, d) and (m, d, b). Refused, naming the face, where the side is on a hole
// or the new edge m-d is there already.
void flip(Work &w, Pass &pass, size_t f, int longest) {
  const std::array<int, 3> t = w.mesh.triangles[f];
  const int a = t[size_t(longest)], b = t[size_t((longest + 1) % 3)],
            m = t[size_t((longest + 2) % 3)];
  const auto across = pass.face_of_edge.find({b, a});
  if (across == pass.face_of_edge.end())
    throw InputError(face_name(w, f) +
                     " has zero area and its longest edge is on a hole; remesh there");
  const size_t g = across->second;
  int d = -1;
  for (int u : w.mesh.triangles[g])
    if (u != a && u != b) d = u;
  if (d < 0 || d == m || pass.face_of_edge.count({m, d}) || pass.face_of_edge.count({d, m}))
    throw InputError(face_name(w, f) +
                     " has zero area and its longest edge cannot be flipped; remesh there");
  pass.touch_around(w, a);
  pass.touch_around(w, b);
  w.mesh.triangles[f] = {m, a, d};
  w.mesh.triangles[g] = {m, d, b};
  w.origin[f] = w.origin[g] = -1;
}

// Takes out zero-area face f: a needle's shortest side collapsed (the later vertex into the
// earlier); a cap whose middle vertex has no face but the cap and the two beside it (a
// T-junction) has that vertex merged into the nearer end of the long side, so the face it split
// comes back whole; any other cap's longest side flipped.
void take_out(Work &w, Pass &pass, size_t f, ZeroAreaFix &out) {
  const std::array<int, 3> t = w.mesh.triangles[f];
  std::array<double, 3> side; // side k joins corners k and k + 1
  for (int k = 0; k < 3; ++k)
    side[size_t(k)] = length(w, t[size_t(k)], t[size_t((k + 1) % 3)]);
  const int shortest = int(std::min_element(side.begin(), side.end()) - side.begin()),
            longest = int(std::max_element(side.begin(), side.end()) - side.begin());
  const int middle = t[size_t((longest + 2) % 3)];
  const bool needle = side[size_t(shortest)] <= needle_ratio * side[size_t(longest)];
  if (needle) {
    const int a = t[size_t(shortest)], b = t[size_t((shortest + 1) % 3)];
    collapse(w, pass, f, std::min(a, b), std::max(a, b), true);
    ++out.collapsed_edges;
  } else if (pass.faces_at[size_t(middle)].size() == 3) {
    const int a = t[size_t(longest)], b = t[size_t((longest + 1) % 3)];
    collapse(w, pass, f, length(w, middle, a) <= length(w, middle, b) ? a : b, middle, false);
    ++out.collapsed_edges;
  } else {
    flip(w, pass, f, longest);
    ++out.flipped_edges;
  }
}

// The vertices left, in order, and the faces left, in order, as the work mesh; each input
// vertex's and face's place in it.
void compact(const Work &w, ZeroAreaFix &out, Mesh &work_mesh) {
  const size_t vertex_count = w.mesh.positions.size(), face_count = w.mesh.triangles.size();
  std::vector<int> index(vertex_count, -1);
  MeshArrays result;
  for (size_t v = 0; v < vertex_count; ++v)
    if (w.merged_into[v] == int(v)) {
      index[v] = int(result.positions.size());
      result.positions.push_back(w.mesh.positions[v]);
    }
  out.vertex_in_work.resize(vertex_count);
  for (size_t v = 0; v < vertex_count; ++v) {
    int root = int(v);
    while (w.merged_into[size_t(root)] != root)
      root = w.merged_into[size_t(root)];
    out.vertex_in_work[v] = index[size_t(root)];
  }
  out.face_in_work.assign(face_count, -1);
  for (size_t f = 0; f < face_count; ++f) {
    if (!w.alive[f]) continue;
    if (w.origin[f] >= 0) out.face_in_work[size_t(w.origin[f])] = int(result.triangles.size());
    std::array<int, 3> t = w.mesh.triangles[f];
    for (int &u : t)
      u = index[size_t(u)];
    result.triangles.push_back(t);
  }
  mesh_from_arrays(result, work_mesh);
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

  for (int round = 0;; ++round) {
    std::vector<size_t> flat;
    for (size_t f = 0; f < face_count; ++f)
      if (w.alive[f] && zero_area(w, w.mesh.triangles[f])) flat.push_back(f);
    if (flat.empty()) break;
    if (round == most_passes)
      throw InputError(face_name(w, flat[0]) +
                       " has zero area and stays so after edge flips and collapses around it; "
                       "remesh there");
    Pass pass(w);
    for (size_t f : flat) {
      const std::array<int, 3> &t = w.mesh.triangles[f];
      if (w.alive[f] && !pass.touched[size_t(t[0])] && !pass.touched[size_t(t[1])] &&
          !pass.touched[size_t(t[2])])
        take_out(w, pass, f, out);
    }
  }
  compact(w, out, work_mesh);
  return out;
}

} // namespace meromorph
