#include "maps/genus1_branch_placement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_set>

#include "common/parallel_for.h"
#include "maps/branch_star.h"
#include "sphere/branch_points.h"

namespace meromorph {
namespace {

constexpr int candidates_per_half_period = 40;
constexpr double fade_factor = 4.0; // K: the fade spans K |s| beyond the one-ring

// 1 up to `inner`, 0 from `outer` on, smooth (C1) in between.
double fade(double distance, double inner, double outer) {
  if (distance <= inner) return 1.0;
  if (distance >= outer) return 0.0;
  const double x = (outer - distance) / (outer - inner);
  return x * x * (3 - 2 * x);
}

struct Shifted {
  std::vector<int> vertices; // those whose value changed
  std::vector<PlaneValue> new_values;
  // The faces where the shift is at full strength: those touching a vertex within the one-ring
  // distance plus |s| of c (they hold the critical point): none may fold.
  std::vector<int> faces;
  // The faces where it fades: no more may fold than before (faces folded already, next to a
  // double pole on a coarse mesh, are not this candidate's doing).
  std::vector<int> fading_faces;
};

// The values of the map composed with the shift that takes `c` onto the half period.
Shifted shift_onto(const FaceIncidence &in, const Genus1Map &map, int c, Complex half_period,
                   PlaneValue critical_value) {
  const WeierstrassP &p = map.p_function;
  const Complex s = p.shortest_representative(half_period - map.flat[size_t(c)]);
  double ring = 0;
  for (int f : in.faces_of_vertex[size_t(c)])
    for (int w : in.corners[size_t(f)])
      ring = std::max(
          ring, std::abs(p.shortest_representative(map.flat[size_t(w)] - map.flat[size_t(c)])));
  // The fade stays clear of the other branch points (the pole at 0, the other half periods):
  // within half the distance to the nearest; too steep a fade would shear faces over.
  double clearance = std::numeric_limits<double>::infinity();
  for (const Complex &other :
       {Complex(0, 0), p.half_periods()[0], p.half_periods()[1], p.half_periods()[2]})
    if (p.lattice_distance(other - half_period) > 1e-12)
      clearance = std::min(clearance, p.lattice_distance(other - map.flat[size_t(c)]) / 2);
  const double outer = std::min(ring * (1 + 1e-9) + fade_factor * std::abs(s), clearance);
  Shifted out;
  if (outer < ring * (1 + 1e-9) + 1.5 * std::abs(s)) return out; // no room: not a candidate
  std::unordered_set<int> seen{c};
  std::queue<int> queue;
  queue.push(c);
  std::vector<int> faces, fading;
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop();
    const double distance =
        std::abs(p.shortest_representative(map.flat[size_t(v)] - map.flat[size_t(c)]));
    if (distance >= outer) continue;
    out.vertices.push_back(v);
    const double t = v == c ? 1.0 : fade(distance, ring * (1 + 1e-9), outer);
    const Complex z = map.flat[size_t(v)] + t * s;
    out.new_values.push_back(v == c
                                 ? critical_value
                                 : (p.is_lattice_point(z, 1e-12) ? PlaneValue{Complex(), true}
                                                                 : PlaneValue{p.value(z), false}));
    for (int f : in.faces_of_vertex[size_t(v)]) {
      (distance <= ring * (1 + 1e-9) + std::abs(s) ? faces : fading).push_back(f);
      for (int w : in.corners[size_t(f)])
        if (seen.insert(w).second) queue.push(w);
    }
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  std::sort(fading.begin(), fading.end());
  fading.erase(std::unique(fading.begin(), fading.end()), fading.end());
  for (int f : fading)
    if (!std::binary_search(faces.begin(), faces.end(), f)) out.fading_faces.push_back(f);
  out.faces = std::move(faces);
  return out;
}

// A branch vertex doubles its corners (in the flat coordinate): a corner of 90 degrees or more
// turns its face over. Re-places c's one-ring in the chart centred at c's critical value: each
// neighbour keeps its distance, the doubled corners are capped at `cap` and the excess is shared
// among the others in proportion to their room, so the ring still winds exactly twice.
void reshape_ring(const FaceIncidence &in, const Genus1Map &map, int c, Shifted &shifted) {
  constexpr double cap = 170 * M_PI / 180;
  const std::vector<int> ring = ordered_ring(in, c);
  if (ring.size() < 3) return;
  const WeierstrassP &p = map.p_function;
  std::vector<double> doubled(ring.size());
  double excess = 0, room = 0;
  for (size_t j = 0; j < ring.size(); ++j) {
    const Complex a = p.shortest_representative(map.flat[size_t(ring[j])] - map.flat[size_t(c)]);
    const Complex b = p.shortest_representative(map.flat[size_t(ring[(j + 1) % ring.size()])] -
                                                map.flat[size_t(c)]);
    doubled[j] = 2 * std::abs(std::arg(b / a));
    excess += std::max(0.0, doubled[j] - cap);
    room += std::max(0.0, cap - doubled[j]);
  }
  if (excess == 0 || room <= excess) return;
  auto position = [&](int v) {
    return size_t(std::find(shifted.vertices.begin(), shifted.vertices.end(), v) -
                  shifted.vertices.begin());
  };
  // The chart centred at c's value: w - centre, or 1 / w at the pole.
  if (position(c) == shifted.vertices.size()) return;
  const PlaneValue centre = shifted.new_values[position(c)];
  auto chart = [&](Complex w) { return centre.infinite ? 1.0 / w : w - centre.w; };
  auto unchart = [&](Complex x) { return centre.infinite ? 1.0 / x : centre.w + x; };
  // Keep the ring's overall turn: start where the first neighbour's image is.
  std::vector<Complex> offsets;
  for (int v : ring) {
    const size_t i = position(v);
    if (i == shifted.vertices.size() || shifted.new_values[i].infinite ||
        std::abs(shifted.new_values[i].w) == 0)
      return;
    offsets.push_back(chart(shifted.new_values[i].w));
  }
  double angle = std::arg(offsets[0]);
  for (size_t j = 0; j < ring.size(); ++j) {
    shifted.new_values[position(ring[j])].w = unchart(std::polar(std::abs(offsets[j]), angle));
    const double corner =
        doubled[j] > cap ? cap : doubled[j] + excess * std::max(0.0, cap - doubled[j]) / room;
    angle += corner;
  }
}

} // namespace

std::vector<double> widest_flat_corners(const PreparedMesh &prepared, const Eigen::VectorXcd &psi) {
  const Mesh &mesh = prepared.mesh;
  const MeshEdges &edges = prepared.edges;
  const FaceIncidence &in = prepared.incidence;
  std::vector<std::array<double, 3>> corners(mesh.face.size());
  parallel_for(mesh.face.size(), [&](size_t f) {
    Complex side[3]; // side k: from corner k to corner k + 1
    for (int k = 0; k < 3; ++k)
      side[k] = double(edges.face_signs[f][k]) * psi[edges.face_edges[f][k]];
    for (int k = 0; k < 3; ++k)
      corners[f][size_t(k)] = std::abs(std::arg(-side[(k + 2) % 3] / side[k]));
  });
  std::vector<double> widest(mesh.vert.size(), 0.0);
  parallel_for(mesh.vert.size(), [&](size_t v) {
    for (int f : in.faces_of_vertex[v])
      for (size_t k = 0; k < 3; ++k)
        if (size_t(in.corners[size_t(f)][k]) == v)
          widest[v] = std::max(widest[v], corners[size_t(f)][k]);
  });
  return widest;
}

std::vector<double> flat_area_ratios(const PreparedMesh &prepared, const Eigen::VectorXcd &psi) {
  const Mesh &mesh = prepared.mesh;
  const MeshEdges &edges = prepared.edges;
  std::vector<double> flat(mesh.vert.size(), 0.0), surface(mesh.vert.size(), 0.0);
  for (size_t f = 0; f < mesh.face.size(); ++f) {
    const Complex first = double(edges.face_signs[f][0]) * psi[edges.face_edges[f][0]];
    const Complex second = double(edges.face_signs[f][1]) * psi[edges.face_edges[f][1]];
    for (int v : prepared.incidence.corners[f]) {
      flat[size_t(v)] += std::abs(std::imag(std::conj(first) * second)) / 2;
      surface[size_t(v)] += prepared.geometry.areas[f];
    }
  }
  for (size_t v = 0; v < flat.size(); ++v)
    flat[v] = surface[v] > 0 ? flat[v] / surface[v] : 0.0;
  return flat;
}

namespace {

// The double pole doubles the origin's corners too (in the chart 1 / w): where one is 90 degrees
// or more, the origin's one-ring is re-placed, if that folds fewer faces there.
void reshape_origin_ring(const FaceIncidence &in, const Genus1Map &map, const Mobius &centring,
                         std::vector<Eigen::Vector3d> &sphere, std::vector<PlaneValue> &values) {

  Shifted pole;
  pole.vertices.push_back(map.origin_vertex);
  pole.new_values.push_back(PlaneValue{Complex(), true});
  for (int w : ordered_ring(in, map.origin_vertex)) {
    pole.vertices.push_back(w);
    pole.new_values.push_back(PlaneValue{map.p_function.value(map.flat[size_t(w)]), false});
  }
  reshape_ring(in, map, map.origin_vertex, pole);
  std::vector<int> faces;
  for (int v : pole.vertices)
    faces.insert(faces.end(), in.faces_of_vertex[size_t(v)].begin(),
                 in.faces_of_vertex[size_t(v)].end());
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  auto folds = [&] {
    int count = 0;
    for (int f : faces)
      count += folded_or_flat(in, sphere, f);
    return count;
  };
  const int before = folds();
  std::vector<Eigen::Vector3d> saved;
  for (size_t j = 0; j < pole.vertices.size(); ++j) {
    saved.push_back(sphere[size_t(pole.vertices[j])]);
    sphere[size_t(pole.vertices[j])] = to_sphere(centring.apply(pole.new_values[j]));
  }
  if (folds() < before && vertex_winding(in, sphere, map.origin_vertex) == 2) {
    for (size_t j = 0; j < pole.vertices.size(); ++j)
      values[size_t(pole.vertices[j])] = centring.apply(pole.new_values[j]);
  } else {
    for (size_t j = 0; j < pole.vertices.size(); ++j)
      sphere[size_t(pole.vertices[j])] = saved[j];
  }
}

// A trial's score with its moves applied (the spot is left as it was): folded or flat faces,
// whether c winds other than twice, other vertices that start or stop branching (the pole next
// to a coarse torus's half period included).
std::tuple<int, int, int> score_trial(const FaceIncidence &in, const Shifted &trial, int c,
                                      std::vector<Eigen::Vector3d> &sphere) {
  int folded = 0, stray = 0;
  for (int f : trial.fading_faces)
    folded -= folded_or_flat(in, sphere, f);
  std::vector<int> winding_before;
  for (int v : trial.vertices)
    winding_before.push_back(vertex_winding(in, sphere, v));
  std::vector<Eigen::Vector3d> saved;
  for (size_t j = 0; j < trial.vertices.size(); ++j) {
    saved.push_back(sphere[size_t(trial.vertices[j])]);
    sphere[size_t(trial.vertices[j])] = to_sphere(trial.new_values[j]);
  }
  for (int f : trial.faces)
    folded += folded_or_flat(in, sphere, f);
  for (int f : trial.fading_faces)
    folded += folded_or_flat(in, sphere, f);
  // No other vertex may start or stop branching (the pole next to a coarse torus's half
  // period included).
  for (size_t j = 0; j < trial.vertices.size(); ++j)
    stray += trial.vertices[j] != c &&
             vertex_winding(in, sphere, trial.vertices[j]) != winding_before[j];
  const std::tuple<int, int, int> score{folded, vertex_winding(in, sphere, c) != 2, stray};
  for (size_t j = 0; j < trial.vertices.size(); ++j)
    sphere[size_t(trial.vertices[j])] = saved[j];
  return score;
}

} // namespace

Genus1Placement place_half_period_branch_points(const PreparedMesh &prepared, const Genus1Map &map,
                                                const Mobius &centring,
                                                std::vector<PlaneValue> &values) {
  const FaceIncidence &in = prepared.incidence;
  Genus1Placement out;
  std::vector<Eigen::Vector3d> sphere = to_sphere(values);
  reshape_origin_ring(in, map, centring, sphere, values);
  const auto half_periods = map.p_function.half_periods();
  for (int k = 0; k < 3; ++k) {
    const std::vector<std::pair<double, int>> by_distance =
        parallel_smallest(map.flat.size(), candidates_per_half_period, [&](size_t v) {
          return map.p_function.lattice_distance(map.flat[v] - half_periods[size_t(k)]);
        });
    const size_t count = by_distance.size();

    // Score: (folded or flat faces, winds other than twice at c, other vertices that branch).
    std::tuple<int, int, int> best_score{1 << 30, 1 << 30, 1 << 30};
    Shifted best;
    for (size_t i = 0; i < 2 * count; ++i) {
      // Each candidate as it is, then (second pass) with its one-ring re-placed.
      const int c = by_distance[i % count].second;
      ++out.candidates_tried;
      Shifted trial = shift_onto(in, map, c, half_periods[size_t(k)], map.branch_values[size_t(k)]);
      if (trial.vertices.empty()) continue; // no room for a fade there
      if (i >= count) reshape_ring(in, map, c, trial);
      for (PlaneValue &value : trial.new_values)
        value = centring.apply(value);
      const std::tuple<int, int, int> score = score_trial(in, trial, c, sphere);
      if (score < best_score) {
        best_score = score;
        best = std::move(trial);
        out.vertices[size_t(k)] = c;
      }
      if (best_score == std::tuple<int, int, int>{0, 0, 0}) break; // the nearest that works
    }
    out.fold_free[size_t(k)] = best_score == std::tuple<int, int, int>{0, 0, 0};
    for (size_t j = 0; j < best.vertices.size(); ++j) {
      values[size_t(best.vertices[j])] = best.new_values[j];
      sphere[size_t(best.vertices[j])] = to_sphere(best.new_values[j]);
    }
  }
  return out;
}

} // namespace meromorph
