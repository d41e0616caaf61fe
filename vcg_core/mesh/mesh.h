// The core's triangle mesh: a vcglib TriMesh in double precision.
//
// In:  nothing (a type definition).
// Out: `meromorph::Mesh`, with per-vertex position, normal, quality, texture coordinate and
//      vertex-face adjacency, and per-face vertex references and face-face adjacency, and, where
//      enabled (enable_face_extras), per-face normal, quality, vertex-face adjacency and per-wedge
//      texture coordinates. Every later stage (validation, topology,
//      forms, maps) works on this type; adapters copy their own meshes into it and back.
#pragma once

#include <vcg/complex/algorithms/stat.h>
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

// Wedge texture coordinates in double precision (vcglib offers optional ones in float only).
template <class T>
class WedgeTexCoord2dOcf : public vcg::face::WedgeTexCoordOcf<vcg::TexCoord2<double, 1>, T> {};

// The face's normal, quality, vertex-face adjacency and wedge texture coordinates are optional
// (stored apart, allocated only once enabled: enable_face_extras): the map's stages use none of
// them, and at two million faces they were 270 MB of a 1.9 GB peak.
class MeshFace
    : public vcg::Face<MeshUsedTypes, vcg::face::InfoOcf, vcg::face::VertexRef, vcg::face::FFAdj,
                       vcg::face::Mark, vcg::face::BitFlags, vcg::face::Normal3dOcf,
                       vcg::face::QualityfOcf, vcg::face::VFAdjOcf, WedgeTexCoord2dOcf> {};

class Mesh : public vcg::tri::TriMesh<std::vector<MeshVertex>, vcg::face::vector_ocf<MeshFace>> {};

// Allocates the optional per-face components (for vcglib's algorithms that use them, and for
// writing wedge texture coordinates). Idempotent.
inline void enable_face_extras(Mesh &mesh) {
  if (!mesh.face.IsNormalEnabled()) mesh.face.EnableNormal();
  if (!mesh.face.IsQualityEnabled()) mesh.face.EnableQuality();
  if (!mesh.face.IsVFAdjacencyEnabled()) mesh.face.EnableVFAdjacency();
  if (!mesh.face.IsWedgeTexCoordEnabled()) mesh.face.EnableWedgeTexCoord();
}

using Point3 = vcg::Point3d;

// Index of a vertex or face of `mesh` from its pointer or reference.
inline int index_of(const Mesh &mesh, const MeshVertex *v) {
  return int(vcg::tri::Index(mesh, v));
}
inline int index_of(const Mesh &mesh, const MeshFace *f) {
  return int(vcg::tri::Index(mesh, f));
}

// The signed volume the surface encloses (vcglib's, which reads face normals: enabled for the
// call only where they were not).
inline double enclosed_volume(Mesh &mesh) {
  const bool had_normals = mesh.face.IsNormalEnabled();
  if (!had_normals) mesh.face.EnableNormal();
  const double volume = vcg::tri::Stat<Mesh>::ComputeMeshVolume(mesh);
  if (!had_normals) mesh.face.DisableNormal();
  return volume;
}

} // namespace meromorph
