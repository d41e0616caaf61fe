#include "maps/genus0_correction.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/parallel_for.h"
#include "forms/region_extension.h"
#include "maps/genus0_map.h"
#include "mesh/cotan_laplacian.h"
#include "solvers/leading_block_solve.h"
#include "sphere/plane_triangles.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {
namespace {

constexpr double outer_share = 0.1; // the vertices farthest out, left out of the shear's median
// A predicted cap is used where it holds at least this share of the map's own.
constexpr double least_cap_overlap = 0.5;

Eigen::Vector3d position(const MeshVertex &vertex) {
  return vertex.cP().ToEigenVector<Eigen::Vector3d>();
}

// The Beltrami ratio nu = z_conj(w) / conj(z_w) of the linear map from face f, in its own
// conformal coordinate w, to the values z at its corners.
Complex face_shear(const PreparedMesh &prepared, int f, const std::vector<PlaneValue> &values) {
  const MeshFace &face = prepared.mesh.face[size_t(f)];
  const std::array<int, 3> &corners = prepared.incidence.corners[size_t(f)];
  const Eigen::Vector3d p0 = position(*face.cV(0)), d1 = position(*face.cV(1)) - p0,
                        d2 = position(*face.cV(2)) - p0;
  const Eigen::Vector3d e1 = d1.normalized();
  const Eigen::Vector3d e2 = d1.cross(d2).cross(d1).normalized();
  const Complex w1(d1.dot(e1), 0), w2(d2.dot(e1), d2.dot(e2));
  const Complex z0 = values[size_t(corners[0])].w;
  const Complex z1 = values[size_t(corners[1])].w - z0;
  const Complex z2 = values[size_t(corners[2])].w - z0;
  // z = a w + b conj(w) on the face: two equations for a and b.
  const Complex determinant = w1 * std::conj(w2) - w2 * std::conj(w1);
  const Complex a = (z1 * std::conj(w2) - z2 * std::conj(w1)) / determinant;
  const Complex b = (w1 * z2 - w2 * z1) / determinant;
  return b / std::conj(a);
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + long(values.size() / 2), values.end());
  return values[values.size() / 2];
}

// The `count` vertices nearest `centre` (|z - centre|), in no particular order.
std::vector<int> nearest_to(const std::vector<PlaneValue> &values, Complex centre, size_t count) {
  std::vector<std::pair<double, int>> order(values.size());
  parallel_for(values.size(), [&](size_t v) {
    order[v] = {values[v].infinite ? INFINITY : std::abs(values[v].w - centre), int(v)};
  });
  count = std::min(count, order.size());
  std::nth_element(order.begin(), order.begin() + long(count), order.end());
  std::vector<int> out(count);
  for (size_t i = 0; i < count; ++i)
    out[i] = order[i].second;
  return out;
}

// The share of `exact` that `predicted` holds.
double overlap(const std::vector<int> &predicted, const std::vector<int> &exact, size_t n) {
  std::vector<char> in(n, 0);
  for (int v : predicted)
    in[size_t(v)] = 1;
  size_t common = 0;
  for (int v : exact)
    common += in[size_t(v)];
  return exact.empty() ? 0 : double(common) / double(exact.size());
}

// The median of the finite values, component by component.
Complex median_value(const std::vector<PlaneValue> &values) {
  std::vector<double> real, imag;
  for (const PlaneValue &value : values)
    if (!value.infinite) {
      real.push_back(value.w.real());
      imag.push_back(value.w.imag());
    }
  if (real.empty()) return {0, 0};
  return {median(real), median(imag)};
}

} // namespace

std::vector<int> south_cap(const std::vector<PlaneValue> &values) {
  return nearest_to(values, median_value(values),
                    size_t(std::max<double>(3, double(values.size()) * south_cap_share)));
}

std::vector<int> folded_plane_faces(const FaceIncidence &in,
                                    const std::vector<PlaneValue> &values) {
  // As the written map is judged: the chord triangle of the images on the sphere. (A plane
  // triangle's orientation says nothing there once its circumcircle holds the south pole's
  // antipode; straight edges in a chart of 1 / z are no image of the map's.)
  return parallel_select(in.corners.size(), [&](size_t f) {
    Eigen::Vector3d s[3];
    for (int k = 0; k < 3; ++k)
      s[k] = to_sphere(values[size_t(in.corners[f][k])]);
    return !collapsed_image(s[0], s[1], s[2]) && chord_turned_over(s[0], s[1], s[2], 0);
  });
}

namespace {

// The median per-face Beltrami ratio nu of the pinned map, over the faces away from the pole
// (z = A f + B conj(f): a global shear); none where it cannot be measured or is not small.
std::optional<Complex> median_shear(const PreparedMesh &prepared, int pole_face,
                                    const std::vector<PlaneValue> &pinned_map) {
  const FaceIncidence &in = prepared.incidence;
  const size_t n = pinned_map.size();
  std::vector<char> outer(n, 1);
  for (int v : nearest_to(pinned_map, Complex(0, 0), n - size_t(double(n) * outer_share)))
    outer[size_t(v)] = 0;
  std::vector<Complex> face_nu(in.corners.size(), Complex(NAN, NAN));
  parallel_for(in.corners.size(), [&](size_t f) {
    if (int(f) == pole_face) return;
    for (int k = 0; k < 3; ++k)
      if (outer[size_t(in.corners[f][k])]) return;
    face_nu[f] = face_shear(prepared, int(f), pinned_map);
  });
  std::vector<double> nu_real, nu_imag;
  for (const Complex &nu : face_nu)
    if (std::isfinite(nu.real()) && std::isfinite(nu.imag())) {
      nu_real.push_back(nu.real());
      nu_imag.push_back(nu.imag());
    }
  if (nu_real.empty()) return {};
  const Complex nu(median(nu_real), median(nu_imag));
  if (!(std::abs(nu) < 0.5)) return {}; // not a small shear: not this model's case
  return nu;
}

// The south-pole step's chart zeta = 1 / (z - z_s): the cap around z_s pinned at its values there.
struct SouthPoleChart {
  Complex south;
  std::vector<int> pinned;
  std::vector<char> is_pinned;
  Eigen::VectorXcd fixed;

  SouthPoleChart(const std::vector<PlaneValue> &values, std::vector<int> cap)
      : south(median_value(values)), pinned(std::move(cap)), is_pinned(values.size(), 0),
        fixed(Eigen::VectorXcd::Zero(long(values.size()))) {
    for (int v : pinned) {
      is_pinned[size_t(v)] = 1;
      const Complex d = values[size_t(v)].w - south;
      fixed[v] = std::abs(d) > 0 ? 1.0 / d : Complex(0, 0);
    }
  }
  // The free vertices' values taken back from the chart; the pinned ones' kept.
  std::vector<PlaneValue> mapped_back(const std::vector<PlaneValue> &values,
                                      const Eigen::VectorXcd &zeta) const {
    std::vector<PlaneValue> candidate = values;
    for (size_t v = 0; v < values.size(); ++v) {
      if (is_pinned[v]) continue;
      if (zeta[long(v)] == Complex(0, 0)) // (as std::abs == 0, without hypot)
        candidate[v] = {Complex(0, 0), true};
      else
        candidate[v] = {south + 1.0 / zeta[long(v)], false};
    }
    return candidate;
  }
};

// The south-pole step with the pinned-pole map's factor, whose weights are the map's before any
// were raised: the region around the raised ones (as the map itself was, genus0_best_map.cpp)
// and around faces the result folds solved again with the map's weights, those near the folds
// raised too. `folded_count`: the result's folded faces where known.
std::vector<PlaneValue>
south_pole_step_by_cap_last(const PreparedMesh &prepared, const std::vector<double> &weights,
                            const CapLastFactor &cap_last, const SouthPoleChart &chart,
                            const std::vector<PlaneValue> &values, size_t folded_before,
                            std::optional<size_t> &folded_count) {
  const MeshEdges &edges = prepared.edges;
  const size_t n = values.size();
  const LeadingBlockSolve solve(*cap_last.solver, *cap_last.laplacian, int(cap_last.cap.size()),
                                cap_last.corners);
  const Eigen::VectorXcd zeta =
      harmonic_extension_by([&](const Eigen::MatrixXd &b) { return solve.solve_columns(b); },
                            *cap_last.laplacian, edges, cap_last.weights, chart.fixed, 1);
  std::vector<PlaneValue> candidate = chart.mapped_back(values, zeta);
  std::vector<char> region(n, 0), raise;
  for (int e = 0; e < edges.edge_count(); ++e)
    if (weights[size_t(e)] != cap_last.weights[size_t(e)])
      for (int v : edges.vertices[size_t(e)])
        region[size_t(v)] = 1;
  grow_by_rings(prepared, region, local_rings);
  const std::vector<int> folded = folded_plane_faces(prepared.incidence, candidate);
  folded_count = folded.size();
  if (folded.size() > folded_before) {
    std::vector<char> around_folds;
    region_around_folds(prepared, folded, raise, around_folds);
    for (size_t v = 0; v < n; ++v)
      region[v] |= around_folds[v];
  }
  std::vector<char> free(n, 0);
  for (size_t v = 0; v < n; ++v)
    free[v] = region[v] && !chart.is_pinned[v];
  if (std::find(free.begin(), free.end(), 1) != free.end()) {
    int raised = 0;
    const std::vector<double> region_weights =
        raise.empty() ? weights : positive_weights(weights, raise, raised);
    candidate = chart.mapped_back(
        values, harmonic_extension_in_region(prepared, region_weights, free, zeta));
    folded_count.reset();
  }
  return candidate;
}

} // namespace

Genus0Correction correct_genus0_map(const PreparedMesh &prepared,
                                    const std::vector<double> &weights, SolverKind solver,
                                    int pole_face, const std::vector<PlaneValue> &pinned_map,
                                    const std::vector<int> &elimination_order,
                                    const CapLastFactor &cap_last) {
  const FaceIncidence &in = prepared.incidence;
  Genus0Correction out;
  out.values = pinned_map;
  const size_t n = pinned_map.size();
  for (const PlaneValue &value : pinned_map)
    if (value.infinite) return out;
  const size_t folded_before = folded_plane_faces(in, pinned_map).size();
  // A candidate is taken if it folds no more faces than the pinned map (`folded`: its count,
  // where already known).
  auto accept = [&](const std::vector<PlaneValue> &candidate, std::optional<size_t> folded = {}) {
    if ((folded ? *folded : folded_plane_faces(in, candidate).size()) > folded_before) return false;
    out.values = candidate;
    ++out.steps_taken;
    return true;
  };

  // 1. The shear.
  const std::optional<Complex> nu = median_shear(prepared, pole_face, pinned_map);
  if (!nu) return out;
  std::vector<PlaneValue> unsheared = pinned_map;
  for (PlaneValue &value : unsheared)
    value.w -= *nu * std::conj(value.w);
  if (accept(unsheared)) out.shear = *nu;

  // 2. The south-pole step, in the chart zeta = 1 / (z - z_s).
  std::vector<int> cap = south_cap(out.values);
  const bool by_cap_last = cap_last.solver && overlap(cap_last.cap, cap, n) >= least_cap_overlap;
  const SouthPoleChart chart(out.values, by_cap_last ? cap_last.cap : std::move(cap));
  auto by_new_factorization = [&] {
    const MeshEdges &edges = prepared.edges;
    return chart.mapped_back(out.values, harmonic_extension(cotan_laplacian(int(n), edges, weights),
                                                            edges, weights, solver, chart.pinned,
                                                            chart.fixed, 1, elimination_order));
  };
  if (!by_cap_last) {
    accept(by_new_factorization());
    return out;
  }
  // A new factorization where the step with the cap-last factor still folds.
  std::optional<size_t> folded_count;
  const std::vector<PlaneValue> candidate = south_pole_step_by_cap_last(
      prepared, weights, cap_last, chart, out.values, folded_before, folded_count);
  if (!accept(candidate, folded_count)) accept(by_new_factorization());
  return out;
}

} // namespace meromorph
