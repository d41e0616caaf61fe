#include "repair.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/stat.h>

#include "validation.h"

namespace meromorph {
namespace {

std::string count(int n, const char *one, const char *many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

int remove_zero_area_faces(Mesh &mesh) {
  int removed = 0;
  for (MeshFace &face : mesh.face) {
    if (!face.IsD() && has_zero_area(face)) {
      vcg::tri::Allocator<Mesh>::DeleteFace(mesh, face);
      ++removed;
    }
  }
  return removed;
}

} // namespace

std::vector<std::string> repair_mesh(Mesh &mesh) {
  using Clean = vcg::tri::Clean<Mesh>;
  std::vector<std::string> repairs;

  if (int merged = Clean::RemoveDuplicateVertex(mesh, false))
    repairs.push_back("merged " + count(merged, "duplicate vertex", "duplicate vertices") +
                      " into the vertex at the same position");
  if (int removed = Clean::RemoveDegenerateFace(mesh))
    repairs.push_back("removed " + count(removed, "face", "faces") + " that used a vertex twice");
  if (int removed = remove_zero_area_faces(mesh))
    repairs.push_back("removed " + count(removed, "zero-area face", "zero-area faces"));
  if (int removed = Clean::RemoveUnreferencedVertex(mesh))
    repairs.push_back("removed " + count(removed, "vertex", "vertices") +
                      " that belonged to no face");
  vcg::tri::Allocator<Mesh>::CompactEveryVector(mesh);

  vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
  if (Clean::CountNonManifoldEdgeFF(mesh) == 0 && !Clean::IsCoherentlyOrientedMesh(mesh)) {
    bool oriented = false, orientable = true;
    Clean::OrientCoherentlyMesh(mesh, oriented, orientable);
    if (orientable) {
      // A closed surface faces outward: positive enclosed volume.
      bool flip_all =
          Clean::CountHoles(mesh) == 0 && vcg::tri::Stat<Mesh>::ComputeMeshVolume(mesh) < 0;
      if (flip_all) Clean::FlipMesh(mesh);
      vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
      repairs.push_back("oriented all faces consistently" +
                        std::string(flip_all ? ", facing outward" : ""));
    }
  }
  return repairs;
}

} // namespace meromorph
