#include "job/set_aside.h"

#include <algorithm>
#include <numeric>

#include "common/wording.h"
#include "mesh/mesh_from_arrays.h"

namespace meromorph {

bool has_defects_to_set_aside(const Validation &validation) {
  return validation.find(FindingKind::duplicate_vertices) ||
         validation.find(FindingKind::repeated_vertex_in_face) ||
         validation.find(FindingKind::duplicate_faces) ||
         validation.find(FindingKind::unreferenced_vertices);
}

namespace {

// Per vertex: the vertex it is welded into (itself when it is not a seam duplicate).
std::vector<int> welded_vertices(size_t vertex_count, const Validation &validation) {
  std::vector<int> into(vertex_count);
  std::iota(into.begin(), into.end(), 0);
  if (const Finding *seam = validation.find(FindingKind::duplicate_vertices))
    for (const auto &pair : seam->edges) // (the first vertex at the position, a duplicate)
      into[size_t(pair[1])] = pair[0];
  return into;
}

// Per face: whether it is computed on, after the weld: not when it uses a vertex twice or the
// same three vertices as an earlier face.
std::vector<char> faces_kept(const std::vector<std::array<int, 3>> &triangles, int &repeating,
                             int &doubled) {
  std::vector<char> kept(triangles.size(), 1);
  for (size_t f = 0; f < triangles.size(); ++f) {
    const auto &t = triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      kept[f] = 0;
      ++repeating;
    }
  }
  for (const auto &pair : faces_on_the_same_vertices(triangles)) {
    kept[size_t(pair[1])] = 0; // the later of the two
    ++doubled;
  }
  return kept;
}

} // namespace

void set_aside_defects(const Mesh &input, const Validation &validation, SetAside &out) {
  MeshArrays arrays = arrays_from_mesh(input);
  const std::vector<int> into = welded_vertices(arrays.positions.size(), validation);
  int welded = 0;
  for (size_t v = 0; v < into.size(); ++v)
    welded += into[v] != int(v);
  for (auto &triangle : arrays.triangles)
    for (int &corner : triangle)
      corner = into[size_t(corner)];
  int repeating = 0, doubled = 0;
  const std::vector<char> kept = faces_kept(arrays.triangles, repeating, doubled);

  MeshArrays work;
  std::vector<char> used(arrays.positions.size(), 0);
  out.face_in_work.assign(arrays.triangles.size(), -1);
  for (size_t f = 0; f < arrays.triangles.size(); ++f)
    if (kept[f]) {
      out.face_in_work[f] = int(work.triangles.size());
      work.triangles.push_back(arrays.triangles[f]);
      for (int corner : arrays.triangles[f])
        used[size_t(corner)] = 1;
    }
  std::vector<int> renumbered(arrays.positions.size(), -1);
  int unreferenced = 0;
  for (size_t v = 0; v < arrays.positions.size(); ++v)
    if (used[v]) {
      renumbered[v] = int(work.positions.size());
      work.positions.push_back(arrays.positions[v]);
    } else if (into[v] == int(v)) {
      ++unreferenced; // on no face of the input's own (not a welded duplicate)
    }
  for (auto &triangle : work.triangles)
    for (int &corner : triangle)
      corner = renumbered[size_t(corner)];
  out.vertex_in_work.resize(arrays.positions.size());
  for (size_t v = 0; v < into.size(); ++v)
    out.vertex_in_work[v] = renumbered[size_t(into[v])];
  mesh_from_arrays(work, out.work);

  // "N things <what> for the computation (the outputs keep them, with the values of <whose>)"
  auto note = [&](int count, const char *one, const char *many, const std::string &what,
                  const std::string &whose) {
    if (count)
      out.notes.push_back(plural(size_t(count), one, many) + what +
                          " for the computation (the outputs keep them, with the values of " +
                          whose + ")");
  };
  note(welded, "seam duplicate vertex", "seam duplicate vertices",
       " welded into the vertex at the same position", "the vertex they sit on");
  note(repeating, "face that uses", "faces that use", " a vertex twice left out", "their corners");
  note(doubled, "doubled face", "doubled faces",
       " (on the same three vertices as an earlier face) left out", "their corners");
  if (unreferenced)
    out.notes.push_back(plural(size_t(unreferenced), "vertex", "vertices") +
                        " on no face left out of the computation: the outputs keep them at the "
                        "sphere's north pole, layer 0, texture coordinates of the pole");
}

} // namespace meromorph
