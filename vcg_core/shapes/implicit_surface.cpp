#include "shapes/implicit_surface.h"

#include <cmath>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/create/marching_cubes.h>
#include <vcg/complex/algorithms/create/mc_trivial_walker.h>
#include <vcg/complex/algorithms/isotropic_remeshing.h>
#include <vcg/complex/algorithms/stat.h>

namespace meromorph {
namespace {

using Volume = vcg::SimpleVolume<vcg::SimpleVoxel<double>>;

// vcglib's walker allocates its five slice buffers and never frees them.
struct Walker : vcg::tri::TrivialWalker<Mesh, Volume> {
  ~Walker() {
    if (_slice_dimension == 0) return;
    for (VertexIndexPointer buffer : {_x_cs, _y_cs, _z_cs, _x_ns, _z_ns})
      delete[] buffer;
  }
  using VertexIndexPointer = decltype(_x_cs);
};

} // namespace

void extract_isosurface(const ScalarField &field, const vcg::Box3d &box, double voxel, Mesh &mesh,
                        bool remesh) {
  using MarchingCubes = vcg::tri::MarchingCubes<Mesh, Walker>;

  // Two voxels of margin on every side: the walker skips the last layer of cells.
  vcg::Box3d grown = box;
  grown.Offset(2 * voxel);
  const vcg::Point3i cells(int(std::ceil(grown.DimX() / voxel)),
                           int(std::ceil(grown.DimY() / voxel)),
                           int(std::ceil(grown.DimZ() / voxel)));
  grown.max = grown.min + Point3(cells[0] * voxel, cells[1] * voxel, cells[2] * voxel);

  Volume volume;
  volume.Init(cells, grown);
  for (int i = 0; i < cells[0]; ++i)
    for (int j = 0; j < cells[1]; ++j)
      for (int k = 0; k < cells[2]; ++k) {
        Point3 p;
        volume.IPiToPf(vcg::Point3i(i, j, k), p);
        volume.Val(i, j, k) = field(p);
      }

  mesh.Clear();
  Walker walker;
  MarchingCubes marching_cubes(mesh, walker);
  walker.BuildMesh<MarchingCubes>(mesh, volume, marching_cubes, 0.0);

  using Clean = vcg::tri::Clean<Mesh>;
  enable_face_extras(mesh); // remeshing and normals use them
  Clean::RemoveDuplicateVertex(mesh);
  Clean::RemoveUnreferencedVertex(mesh);
  vcg::tri::Allocator<Mesh>::CompactEveryVector(mesh);
  if (enclosed_volume(mesh) < 0) Clean::FlipMesh(mesh);

  if (remesh) {
    vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
    vcg::tri::UpdateTopology<Mesh>::VertexFace(mesh);
    vcg::tri::IsotropicRemeshing<Mesh>::Params params;
    params.SetTargetLen(voxel);
    params.SetFeatureAngleDeg(180.0); // a smooth surface: no crease to keep
    params.maxSurfDist = voxel / 2;
    params.iter = 8;
    // As vcglib's two-argument Do, with the projection copy's optional face components enabled.
    Mesh projection;
    enable_face_extras(projection);
    vcg::tri::UpdateBounding<Mesh>::Box(mesh);
    vcg::tri::UpdateNormal<Mesh>::PerVertexNormalizedPerFaceNormalized(mesh);
    vcg::tri::Append<Mesh, Mesh>::MeshCopy(projection, mesh);
    vcg::tri::IsotropicRemeshing<Mesh>::Do(mesh, projection, params);
    Clean::RemoveUnreferencedVertex(mesh);
    vcg::tri::Allocator<Mesh>::CompactEveryVector(mesh);
  }
  vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
  vcg::tri::UpdateBounding<Mesh>::Box(mesh);
  vcg::tri::UpdateNormal<Mesh>::PerVertexNormalizedPerFaceNormalized(mesh);
}

} // namespace meromorph
