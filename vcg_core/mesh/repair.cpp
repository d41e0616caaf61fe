#include "mesh/repair.h"

#include <algorithm>
#include <tuple>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/stat.h>

#include "mesh/topology.h"
#include "mesh/validation.h"

namespace meromorph {
namespace {

std::string count(int n, const char *one, const char *many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Merges vertices at exactly the same position when both are on the edge of a hole (a seam the
// merge closes); coinciding vertices that the surface keeps apart are left alone.
int merge_seam_vertices(Mesh &mesh) {
  const std::vector<char> boundary = boundary_vertices(mesh);
  std::vector<int> order;
  for (size_t v = 0; v < mesh.vert.size(); ++v)
    if (!mesh.vert[v].IsD() && boundary[v]) order.push_back(int(v));
  auto key = [&](int v) {
    const Point3 &p = mesh.vert[size_t(v)].cP();
    return std::make_tuple(p[0], p[1], p[2]);
  };
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
  std::vector<int> target(mesh.vert.size(), -1);
  int merged = 0;
  for (size_t i = 1; i < order.size(); ++i) {
    if (key(order[i]) != key(order[i - 1])) continue;
    const int first =
        target[size_t(order[i - 1])] >= 0 ? target[size_t(order[i - 1])] : order[i - 1];
    target[size_t(order[i])] = first;
    ++merged;
  }
  if (!merged) return 0;
  for (MeshFace &face : mesh.face) {
    if (face.IsD()) continue;
    for (int k = 0; k < 3; ++k) {
      const int v = index_of(mesh, face.V(k));
      if (target[size_t(v)] >= 0) face.V(k) = &mesh.vert[size_t(target[size_t(v)])];
    }
  }
  for (size_t v = 0; v < mesh.vert.size(); ++v)
    if (target[v] >= 0) vcg::tri::Allocator<Mesh>::DeleteVertex(mesh, mesh.vert[v]);
  return merged;
}

} // namespace

std::vector<std::string> repair_mesh(Mesh &mesh) {
  using Clean = vcg::tri::Clean<Mesh>;
  std::vector<std::string> repairs;

  if (int merged = merge_seam_vertices(mesh))
    repairs.push_back("merged " + count(merged, "duplicate vertex", "duplicate vertices") +
                      " along the edges of holes into the vertex at the same position");
  if (int removed = Clean::RemoveDegenerateFace(mesh))
    repairs.push_back("removed " + count(removed, "face", "faces") + " that used a vertex twice");
  if (int removed = Clean::RemoveDuplicateFace(mesh))
    repairs.push_back("removed " + count(removed, "doubled face", "doubled faces") +
                      " (on the same three vertices as another)");
  if (int removed = Clean::RemoveUnreferencedVertex(mesh))
    repairs.push_back("removed " + count(removed, "vertex", "vertices") +
                      " that belonged to no face");
  vcg::tri::Allocator<Mesh>::CompactEveryVector(mesh);

  vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
  // (Not Clean::CountNonManifoldEdgeFF: it never frees the three face flag bits it takes, so
  // a long-running host (MeshLab, Blender) would run out of them.)
  const bool edge_manifold = std::all_of(mesh.face.begin(), mesh.face.end(), [](MeshFace &face) {
    return face.IsD() || (vcg::face::IsManifold(face, 0) && vcg::face::IsManifold(face, 1) &&
                          vcg::face::IsManifold(face, 2));
  });
  if (edge_manifold && !Clean::IsCoherentlyOrientedMesh(mesh)) {
    bool oriented = false, orientable = true;
    Clean::OrientCoherentlyMesh(mesh, oriented, orientable);
    if (orientable) {
      // A closed surface faces outward: positive enclosed volume.
      bool flip_all = Clean::CountHoles(mesh) == 0 && enclosed_volume(mesh) < 0;
      if (flip_all) Clean::FlipMesh(mesh);
      vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
      repairs.push_back("oriented all faces consistently" +
                        std::string(flip_all ? ", facing outward" : ""));
    }
  }
  return repairs;
}

} // namespace meromorph
