#include "remesh/remesh_quality.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/point_sampling.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

namespace meromorph {
namespace {

struct OneWay {
  double max = 0, mean = 0;
};

// Distances from the samples of `from` (every vertex, two random points per face) to `to`.
// Where `to` is a speck beside `from` (a remesh collapsed to a spot: under 1e-6 of the other's
// size), vcglib's grid over `to` would count its cells past what an int holds: the distances are
// then those of `from`'s vertices to the speck's centre.
OneWay distances(Mesh &from, Mesh &to, double diagonal) {
  if (!(to.bbox.Diag() >= 1e-6 * std::max(from.bbox.Diag(), diagonal))) {
    OneWay speck;
    const Point3 centre = to.bbox.Center();
    for (const MeshVertex &vertex : from.vert) {
      const double distance = (vertex.cP() - centre).Norm();
      speck.max = std::max(speck.max, distance);
      speck.mean += distance / double(from.vert.size());
    }
    return speck;
  }
  vcg::tri::HausdorffSampler<Mesh> sampler(&to);
  sampler.dist_upper_bound = diagonal;
  vcg::tri::SurfaceSampling<Mesh, vcg::tri::HausdorffSampler<Mesh>>::AllVertex(from, sampler);
  vcg::tri::SurfaceSampling<Mesh, vcg::tri::HausdorffSampler<Mesh>>::Montecarlo(
      from, sampler, 2 * int(from.face.size()));
  return {sampler.getMaxDist(), sampler.getMeanDist()};
}

double corner_angle(const Point3 &at, const Point3 &a, const Point3 &b) {
  const Point3 u = a - at, v = b - at;
  return std::atan2((u ^ v).Norm(), u * v) * 180 / M_PI;
}

void measure_angles(const Mesh &mesh, const std::vector<int> &local_degree, RemeshQuality &out) {
  double sum = 0, min_all = 180, min_away = 180;
  for (const auto &face : mesh.face) {
    bool at_branch = false;
    for (int k = 0; k < 3; ++k)
      at_branch |= local_degree[index_of(mesh, face.cV(k))] >= 2;
    for (int k = 0; k < 3; ++k) {
      const double angle = corner_angle(face.cP(k), face.cP((k + 1) % 3), face.cP((k + 2) % 3));
      sum += angle;
      min_all = std::min(min_all, angle);
      if (!at_branch) min_away = std::min(min_away, angle);
    }
  }
  out.min_angle_degrees = mesh.face.empty() ? 0 : min_all;
  out.min_angle_away_from_branch_degrees = mesh.face.empty() ? 0 : min_away;
  out.mean_angle_degrees = mesh.face.empty() ? 0 : sum / (3.0 * double(mesh.face.size()));
}

} // namespace

RemeshQuality measure_remesh(const Mesh &input, const Mesh &remeshed,
                             const std::vector<int> &local_degree) {
  RemeshQuality out;
  Mesh source, result; // the samplers update normals, bounding boxes and marks
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(source, const_cast<Mesh &>(input));
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(result, const_cast<Mesh &>(remeshed));
  for (Mesh *mesh : {&source, &result}) {
    enable_face_extras(*mesh); // the samplers use face normals
    vcg::tri::UpdateBounding<Mesh>::Box(*mesh);
    vcg::tri::UpdateNormal<Mesh>::PerVertexNormalizedPerFace(*mesh);
    vcg::tri::UpdateTopology<Mesh>::FaceFace(*mesh);
  }
  out.vertices = int(result.vert.size());
  out.faces = int(result.face.size());
  vcg::tri::Clean<Mesh>::CountEdgeNum(result, out.edges, out.boundary_edges, out.nonmanifold_edges);
  out.euler = out.vertices - out.edges + out.faces;
  out.nonmanifold_vertices = vcg::tri::Clean<Mesh>::CountNonManifoldVertexFF(result, false, false);

  const double diagonal = std::max(source.bbox.Diag(), 1e-300);
  if (!result.face.empty() && !source.face.empty()) {
    const OneWay to_input = distances(result, source, diagonal);
    const OneWay from_input = distances(source, result, diagonal);
    out.hausdorff_to_input = to_input.max / diagonal;
    out.mean_distance_to_input = to_input.mean / diagonal;
    out.hausdorff_from_input = from_input.max / diagonal;
    out.mean_distance_from_input = from_input.mean / diagonal;
  }
  measure_angles(remeshed, local_degree, out);

  std::vector<int> valence(remeshed.vert.size(), 0);
  for (const auto &face : remeshed.face)
    for (int k = 0; k < 3; ++k)
      ++valence[index_of(remeshed, face.cV(k))]; // faces at a vertex: its valence when closed
  std::map<int, int> histogram;
  for (int count : valence)
    ++histogram[count];
  out.valence_histogram.assign(histogram.begin(), histogram.end());
  return out;
}

} // namespace meromorph
