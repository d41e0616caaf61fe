#include "branch_snapping.h"

#include <algorithm>
#include <queue>
#include <set>

#include "branch_points.h"
#include "sphere_geometry.h"

namespace meromorph {
namespace {

struct Incidence {
  std::vector<std::vector<int>> faces_of_vertex;
  std::vector<std::array<int, 3>> corners;
};

Incidence incidence(const Mesh &mesh) {
  Incidence in;
  in.faces_of_vertex.resize(mesh.vert.size());
  for (size_t f = 0; f < mesh.face.size(); ++f) {
    std::array<int, 3> c;
    for (int k = 0; k < 3; ++k) {
      c[k] = index_of(mesh, mesh.face[f].cV(k));
      in.faces_of_vertex[c[k]].push_back(int(f));
    }
    in.corners.push_back(c);
  }
  return in;
}

bool folded(const Incidence &in, const std::vector<Eigen::Vector3d> &sphere, int f) {
  const auto &c = in.corners[f];
  return folded_image(sphere[c[0]], sphere[c[1]], sphere[c[2]]);
}

// Folded or flat: what a repair must not leave behind (a repair that copies a neighbour's image
// would flatten faces instead of folding them).
bool not_positive(const Incidence &in, const std::vector<Eigen::Vector3d> &sphere, int f) {
  const auto &c = in.corners[f];
  const Eigen::Vector3d &a = sphere[c[0]], &b = sphere[c[1]], &d = sphere[c[2]];
  const double chord =
      std::max({(a - b).squaredNorm(), (b - d).squaredNorm(), (d - a).squaredNorm()});
  return !(signed_solid_angle(a, b, d) > 1e-9 * chord);
}

int winding(const Incidence &in, const std::vector<Eigen::Vector3d> &sphere, int v,
            const std::vector<Eigen::Vector3d> &side_midpoints = {}) {
  double total = 0;
  for (int f : in.faces_of_vertex[v]) {
    const auto &c = in.corners[f];
    const int k = int(std::find(c.begin(), c.end(), v) - c.begin());
    total += corner_sweep(sphere, c, k, side_midpoints, f);
  }
  return int(std::lround(total / (2 * M_PI)));
}

} // namespace

int place_critical_value(const Mesh &mesh, std::vector<PlaneValue> &values,
                         const std::vector<int> &candidates, const PlaneValue &critical_value,
                         const std::vector<Eigen::Vector3d> &side_midpoints) {
  const Incidence in = incidence(mesh);
  std::vector<Eigen::Vector3d> sphere;
  for (const PlaneValue &v : values)
    sphere.push_back(to_sphere(v));
  const Eigen::Vector3d target = to_sphere(critical_value);
  int best = candidates.front();
  std::pair<int, int> best_score{1 << 30, 1 << 30};
  for (int v : candidates) {
    const Eigen::Vector3d original = sphere[v];
    sphere[v] = target;
    std::set<int> nearby;
    for (int f : in.faces_of_vertex[v])
      for (int w : in.corners[f])
        for (int g : in.faces_of_vertex[w])
          nearby.insert(g);
    int bad = 0;
    for (int f : nearby)
      bad += not_positive(in, sphere, f);
    const std::pair<int, int> score{winding(in, sphere, v, side_midpoints) == 2 ? 0 : 1, bad};
    if (score < best_score) {
      best_score = score;
      best = v;
    }
    sphere[v] = original;
  }
  values[best] = critical_value;
  return best;
}

int snap_branch_points(const Mesh &mesh, std::vector<PlaneValue> &plane_values,
                       const std::vector<PlaneValue> &critical_plane_values) {
  const Incidence in = incidence(mesh);
  std::vector<Eigen::Vector3d> sphere;
  for (const PlaneValue &v : plane_values)
    sphere.push_back(to_sphere(v));
  std::vector<Eigen::Vector3d> critical_values;
  for (const PlaneValue &v : critical_plane_values)
    critical_values.push_back(to_sphere(v));
  const int vertex_count = int(mesh.vert.size());
  std::vector<char> trouble(vertex_count, 0);
  for (size_t f = 0; f < in.corners.size(); ++f)
    if (folded(in, sphere, int(f)))
      for (int v : in.corners[f])
        trouble[v] = 1;
  for (int v = 0; v < vertex_count; ++v)
    if (!trouble[v] && winding(in, sphere, v) < 1) trouble[v] = 1;

  int moved = 0;
  std::vector<char> done(vertex_count, 0);
  for (int seed = 0; seed < vertex_count; ++seed) {
    if (!trouble[seed] || done[seed]) continue;
    // The spot: trouble vertices connected through faces.
    std::vector<int> spot;
    std::queue<int> queue;
    queue.push(seed);
    done[seed] = 1;
    while (!queue.empty()) {
      const int v = queue.front();
      queue.pop();
      spot.push_back(v);
      for (int f : in.faces_of_vertex[v])
        for (int w : in.corners[f])
          if (trouble[w] && !done[w]) {
            done[w] = 1;
            queue.push(w);
          }
    }
    if (spot.size() > 64) continue; // not a lone critical point: leave it as measured
    // Faces near the spot, whose orientation is judged.
    std::set<int> nearby_vertices(spot.begin(), spot.end());
    for (int v : spot)
      for (int f : in.faces_of_vertex[v])
        for (int w : in.corners[f])
          nearby_vertices.insert(w);
    std::set<int> nearby_faces;
    for (int v : nearby_vertices)
      for (int f : in.faces_of_vertex[v])
        nearby_faces.insert(f);
    auto folded_nearby = [&] {
      int count = 0;
      for (int f : nearby_faces)
        count += not_positive(in, sphere, f);
      return count;
    };

    std::vector<Eigen::Vector3d> values = critical_values;
    std::vector<PlaneValue> exact = critical_plane_values;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int v : nearby_vertices) {
      values.push_back(sphere[v]);
      exact.push_back(plane_values[v]);
      mean += sphere[v];
    }
    if (mean.norm() > 0) {
      values.push_back(mean.normalized());
      exact.push_back(to_plane_value(mean.normalized()));
    }
    // Exact critical values only count when they lie near the spot.
    const double reach = [&] {
      double r = 0;
      for (int v : nearby_vertices)
        r = std::max(r, (sphere[v] - mean.normalized()).norm());
      return 3 * r;
    }();

    int best_folded = folded_nearby(), best_vertex = -1;
    size_t best_value = 0;
    for (int v : spot) {
      const Eigen::Vector3d original = sphere[v];
      for (size_t i = 0; i < values.size(); ++i) {
        if (i < critical_values.size() && (values[i] - mean.normalized()).norm() > reach) continue;
        sphere[v] = values[i];
        const int count = folded_nearby();
        if (count < best_folded ||
            (count == best_folded && best_vertex >= 0 && i < critical_values.size())) {
          best_folded = count;
          best_vertex = v;
          best_value = i;
        }
      }
      sphere[v] = original;
    }
    if (best_vertex >= 0) {
      sphere[best_vertex] = values[best_value];
      plane_values[best_vertex] = exact[best_value];
      ++moved;
    }
  }
  return moved;
}

} // namespace meromorph
