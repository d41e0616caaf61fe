#include "branch_snapping.h"

#include <algorithm>
#include <queue>
#include <set>

#include "branch_points.h"
#include "mesh_edges.h"
#include "sphere_geometry.h"

namespace meromorph {
namespace {

bool folded(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere, int f) {
  const auto &c = in.corners[f];
  return folded_image(sphere[c[0]], sphere[c[1]], sphere[c[2]]);
}

// Folded or flat: what a repair must not leave behind (a repair that copies a neighbour's image
// would flatten faces instead of folding them).
bool not_positive(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere, int f) {
  const auto &c = in.corners[f];
  const Eigen::Vector3d &a = sphere[c[0]], &b = sphere[c[1]], &d = sphere[c[2]];
  const double chord =
      std::max({(a - b).squaredNorm(), (b - d).squaredNorm(), (d - a).squaredNorm()});
  return !(signed_solid_angle(a, b, d) > 1e-9 * chord);
}

int winding(const FaceIncidence &in, const std::vector<Eigen::Vector3d> &sphere, int v,
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
  const FaceIncidence in = face_incidence(mesh);
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

namespace {

// The spot's vertices in a conformal coordinate of the surface: their projection on the plane
// through the first vertex, normal to the mean normal of its faces.
std::vector<Complex> local_coordinates(const Mesh &mesh, const FaceIncidence &in,
                                       const std::vector<int> &vertices) {
  const int centre = vertices.front();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (int f : in.faces_of_vertex[centre]) {
    const Point3 n = vcg::NormalizedTriangleNormal(mesh.face[f]);
    normal += Eigen::Vector3d(n[0], n[1], n[2]);
  }
  normal.normalize();
  const Eigen::Vector3d seed =
      std::abs(normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = normal.cross(seed).normalized(), e2 = normal.cross(e1);
  const Point3 &origin = mesh.vert[centre].cP();
  std::vector<Complex> z;
  for (int v : vertices) {
    const Point3 d = mesh.vert[v].cP() - origin;
    const Eigen::Vector3d offset(d[0], d[1], d[2]);
    z.emplace_back(offset.dot(e1), offset.dot(e2));
  }
  return z;
}

} // namespace

int snap_branch_points(const Mesh &mesh, std::vector<PlaneValue> &plane_values) {
  const FaceIncidence in = face_incidence(mesh);
  std::vector<Eigen::Vector3d> sphere;
  for (const PlaneValue &v : plane_values)
    sphere.push_back(to_sphere(v));
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
    // Two rings around the spot: where the model is fitted and orientation judged.
    std::set<int> ring(spot.begin(), spot.end());
    for (int pass = 0; pass < 2; ++pass) {
      const std::set<int> inner = ring;
      for (int v : inner)
        for (int f : in.faces_of_vertex[v])
          for (int w : in.corners[f])
            ring.insert(w);
    }
    std::set<int> nearby_faces;
    for (int v : spot)
      for (int f : in.faces_of_vertex[v])
        for (int w : in.corners[f])
          for (int g : in.faces_of_vertex[w])
            nearby_faces.insert(g);
    auto bad_nearby = [&] {
      int count = 0;
      for (int f : nearby_faces)
        count += not_positive(in, sphere, f);
      return count;
    };

    // Near a critical point p the map is F(z) = c + k (z - p)^2 = A + B z + C z^2: fit A, B, C
    // by least squares in a chart of the sphere centred at the spot's image, and read off
    // p = -B / 2C and the critical value c = A - B^2 / 4C.
    std::vector<int> vertices(spot.begin(), spot.end());
    for (int v : ring)
      if (std::find(spot.begin(), spot.end(), v) == spot.end()) vertices.push_back(v);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int v : vertices)
      centre += sphere[v];
    centre.normalize();
    const std::vector<Complex> z = local_coordinates(mesh, in, vertices);
    Eigen::MatrixXcd design(long(vertices.size()), 3);
    Eigen::VectorXcd image(long(vertices.size()));
    for (size_t i = 0; i < vertices.size(); ++i) {
      design.row(long(i)) << 1.0, z[i], z[i] * z[i];
      image[long(i)] = chart_at(centre, sphere[vertices[i]]);
    }
    const Eigen::VectorXcd abc = design.colPivHouseholderQr().solve(image);
    if (std::abs(abc[2]) == 0 || !abc.allFinite()) continue;
    const Complex p = -abc[1] / (2.0 * abc[2]);
    const Complex c = abc[0] - abc[1] * abc[1] / (4.0 * abc[2]);
    const Eigen::Vector3d critical = from_chart(centre, c);

    // The vertices nearest p are the candidates; the one that then winds twice with the fewest
    // folded or flat faces around wins, if it improves on leaving the spot alone.
    std::vector<std::pair<double, int>> by_distance;
    for (size_t i = 0; i < vertices.size(); ++i)
      by_distance.push_back({std::abs(z[i] - p), vertices[i]});
    std::sort(by_distance.begin(), by_distance.end());
    const std::pair<int, int> before{2, bad_nearby()};
    std::pair<int, int> best = before;
    int best_vertex = -1;
    for (size_t i = 0; i < std::min<size_t>(6, by_distance.size()); ++i) {
      const int v = by_distance[i].second;
      const Eigen::Vector3d original = sphere[v];
      sphere[v] = critical;
      const std::pair<int, int> score{winding(in, sphere, v) == 2 ? 0 : 1, bad_nearby()};
      if (score.second < best.second || (score.second == best.second && score.first < best.first)) {
        best = score;
        best_vertex = v;
      }
      sphere[v] = original;
    }
    if (best_vertex >= 0) {
      sphere[best_vertex] = critical;
      plane_values[best_vertex] = to_plane_value(critical);
      ++moved;
    }
  }
  return moved;
}

} // namespace meromorph
