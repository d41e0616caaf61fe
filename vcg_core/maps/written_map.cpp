#include "maps/written_map.h"

#include <algorithm>
#include <optional>

#include "common/errors.h"
#include "maps/fold_untangling.h"
#include "maps/genus1_branch_placement.h"

namespace meromorph {
namespace {

// Faces whose written image is turned over.
int folded_face_count(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere) {
  int count = 0;
  for (size_t f = 0; f < in.corners.size(); ++f)
    count += folded_face(in, sphere, int(f));
  return count;
}

} // namespace

void finish_on_sphere(const PreparedMesh &prepared, bool mobius, const Genus1Map *torus_map,
                      int euler, std::vector<PlaneValue> values, const Branching *measured,
                      const CentredValues *centred, WrittenSphere &out, const Progress &progress,
                      StageClock &clock) {
  const Mesh &mesh = prepared.mesh;
  const std::vector<double> &areas = prepared.vertex_areas;
  const bool centred_here = mobius && euler >= 0;
  if (centred_here) { // genus 0 and 1
    progress.report(0.7, "Moebius normalisation");
    if (centred) {
      values = centred->values;
      out.mobius = centred->centring;
    } else {
      out.mobius = center_on_sphere(values, areas);
    }
    out.mobius_applied = true;
    clock.done("mobius");
  }
  if (torus_map) {
    // A piecewise-linear map branches only at vertices: the half periods go onto vertices,
    // decided on the centred map as it will be written (genus1_branch_placement.h).
    const Genus1Placement placed =
        place_half_period_branch_points(prepared, *torus_map, out.mobius.transformation, values);
    out.snapped_branch_points =
        int(std::count(placed.fold_free.begin(), placed.fold_free.end(), true));
    clock.done("branch_placement");
  }
  out.sphere = to_sphere(values);

  progress.report(0.8, "branch points and layers");
  // Everything below is measured on the map as written: vertex values, linear on each face.
  out.branching = measured && !centred_here && !torus_map
                      ? *measured
                      : analyse_branching(mesh, out.sphere, euler);
  out.untangled_vertices += untangle_folds(prepared, out.sphere, out.branching.branch_vertices);
  if (mobius && (out.untangled_vertices || out.snapped_branch_points)) {
    // The vertices moved above shift the centroid a little: centre once more.
    for (size_t v = 0; v < values.size(); ++v)
      if (!values[v].infinite && (to_sphere(values[v]) - out.sphere[v]).norm() > 1e-15)
        values[v] = to_plane_value(out.sphere[v]);
    const MobiusCentering again = center_on_sphere(values, areas);
    out.mobius.transformation = again.transformation.after(out.mobius.transformation);
    out.mobius.centroid_after = again.centroid_after;
    out.mobius.steps += again.steps;
    for (size_t v = 0; v < values.size(); ++v)
      out.sphere[v] = to_sphere(values[v]);
  }
  // Measured again only where vertices moved after the first measurement.
  if (out.untangled_vertices || (mobius && out.snapped_branch_points))
    out.branching = analyse_branching(mesh, out.sphere, euler);
}

WrittenSphere written_genus1_map(const PreparedMesh &prepared, const HolomorphicForms &forms,
                                 const std::vector<int> &origins, bool mobius,
                                 const Progress &progress, StageClock &clock) {
  if (origins.empty()) throw InternalError("genus 1: no vertex to place the double pole on");
  std::optional<WrittenSphere> first;
  for (size_t k = 0; k < std::min<size_t>(4, origins.size()); ++k) {
    const Genus1Map map = genus1_map(prepared, forms.normalized[0], Complex(1, 0),
                                     forms.riemann_matrix(0, 0), origins[k]);
    WrittenSphere written;
    finish_on_sphere(prepared, mobius, &map, 0, map.values, nullptr, nullptr, written, progress,
                     clock);
    written.origin_vertex = map.origin_vertex;
    written.flat = map.flat;
    const bool valid = written.branching.degree == 2 && written.branching.riemann_hurwitz_ok &&
                       folded_face_count(prepared.incidence, written.sphere) == 0;
    if (valid || k == 0) first = std::move(written);
    first->origin_attempts = int(k) + 1;
    if (valid) break;
  }
  return std::move(*first);
}

} // namespace meromorph
