// The core's triangle mesh: a vcglib TriMesh in double precision.
//
// In:  nothing (a type definition).
// Out: `meromorph::Mesh`, with per-vertex position, normal, quality, texture coordinate and
//      vertex-face adjacency, and per-face vertex references, normal, face-face and vertex-face
//      adjacency and per-wedge texture coordinates. Every later stage (validation, topology,
//      forms, maps) works on this type; adapters copy their own meshes into it and back.
#pragma once

#include <vcg/complex/complex.h>

namespace meromorph {

class MeshVertex;
class MeshFace;

struct MeshUsedTypes
    : public vcg::UsedTypes<vcg::Use<MeshVertex>::AsVertexType, vcg::Use<MeshFace>::AsFaceType> {};

class MeshVertex
    : public vcg::Vertex<MeshUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d,
                         vcg::vertex::Qualityd, vcg::vertex::TexCoord2d, vcg::vertex::VFAdj,
                         vcg::vertex::Mark, vcg::vertex::BitFlags> {};

class MeshFace
    : public vcg::Face<MeshUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d,
                       vcg::face::Qualityd, vcg::face::FFAdj, vcg::face::VFAdj,
                       vcg::face::WedgeTexCoord2d, vcg::face::Mark, vcg::face::BitFlags> {};

class Mesh : public vcg::tri::TriMesh<std::vector<MeshVertex>, std::vector<MeshFace>> {};

using Point3 = vcg::Point3d;

// Index of a vertex or face of `mesh` from its pointer or reference.
inline int index_of(const Mesh &mesh, const MeshVertex *v) {
  return int(vcg::tri::Index(mesh, v));
}
inline int index_of(const Mesh &mesh, const MeshFace *f) {
  return int(vcg::tri::Index(mesh, f));
}

} // namespace meromorph
