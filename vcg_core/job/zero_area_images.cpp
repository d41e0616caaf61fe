#include "job/zero_area_images.h"

#include <algorithm>
#include <map>
#include <set>

#include "maps/floater_embedding.h"
#include "mesh/face_vectors.h"
#include "mesh/mesh_edges.h"
#include "sphere/branch_points.h"

namespace meromorph {
namespace {

// The vertices around `group` (its faces' corners) and the faces around it.
void surroundings(const FaceIncidence &in, const std::vector<int> &group, std::set<int> &vertices,
                  std::set<int> &faces) {
  for (int v : group)
    for (int f : in.faces_of_vertex[size_t(v)]) {
      faces.insert(f);
      vertices.insert(in.corners[size_t(f)].begin(), in.corners[size_t(f)].end());
    }
}

// Moves one group; false (nothing changed) where no step orients its faces.
bool orient_group(const FaceIncidence &in, const std::vector<int> &group,
                  std::vector<Eigen::Vector3d> &sphere) {
  std::set<int> vertices, faces;
  surroundings(in, group, vertices, faces);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int v : vertices)
    centre += sphere[size_t(v)];
  if (centre.norm() < 1e-12) return false;
  const GnomonicChart chart(centre.normalized());
  std::map<int, Eigen::Vector2d> start, tutte;
  for (int v : vertices)
    if (!chart.to_chart(sphere[size_t(v)], start[v])) return false;
  tutte = start;
  std::map<int, std::set<int>> neighbours;
  for (int v : group)
    for (int f : in.faces_of_vertex[size_t(v)])
      for (int w : in.corners[size_t(f)])
        if (w != v) neighbours[v].insert(w);
  for (int sweep = 0; sweep < 200; ++sweep)
    for (int v : group) {
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      for (int w : neighbours[v])
        sum += tutte[w];
      tutte[v] = sum / double(neighbours[v].size());
    }
  const std::vector<Eigen::Vector3d> before = sphere;
  for (const double step : {1e-3, 1e-2, 0.1, 0.3, 1.0}) {
    for (int v : group)
      sphere[size_t(v)] = chart.to_sphere((1 - step) * start[v] + step * tutte[v]);
    if (std::all_of(faces.begin(), faces.end(),
                    [&](int f) { return !folded_or_flat(in, sphere, f); }))
      return true;
  }
  for (int v : group)
    sphere[size_t(v)] = before[size_t(v)];
  return false;
}

} // namespace

std::vector<int> orient_zero_area_images(const Mesh &mesh, const std::vector<int> &zero_area_faces,
                                         const std::vector<char> &is_copy,
                                         const std::vector<char> &is_branch,
                                         std::vector<Eigen::Vector3d> &sphere) {
  const FaceIncidence in = face_incidence(mesh);
  // Per zero-area face, the corner that moves: a copy, else the widest corner; where a face
  // around it is not oriented.
  std::set<int> movable;
  for (int f : zero_area_faces) {
    const MeshFace &face = mesh.face[size_t(f)];
    int chosen = -1;
    double widest = -1;
    for (int k = 0; k < 3; ++k) {
      const int v = index_of(mesh, face.cV(k));
      if (is_branch[size_t(v)]) continue;
      const double angle = is_copy[size_t(v)] ? 10.0 : corner_angle(face, k);
      if (angle > widest) {
        widest = angle;
        chosen = v;
      }
    }
    if (chosen < 0) continue;
    const IndexRange around = in.faces_of_vertex[size_t(chosen)];
    if (!std::all_of(around.begin(), around.end(),
                     [&](int g) { return !folded_or_flat(in, sphere, g); }))
      movable.insert(chosen);
  }
  // A copy in line between two corners of a zero-area face (a T-junction's middle, merged into an
  // end) starts where it lies along them.
  std::vector<char> zero_area(mesh.face.size(), 0);
  for (int f : zero_area_faces)
    zero_area[size_t(f)] = 1;
  for (int v : movable) {
    if (!is_copy[size_t(v)]) continue;
    const Point3 &x = mesh.vert[size_t(v)].cP();
    for (int f : in.faces_of_vertex[size_t(v)]) {
      if (!zero_area[size_t(f)]) continue;
      const auto &c = in.corners[size_t(f)];
      const int k = int(std::find(c.begin(), c.end(), v) - c.begin());
      const int p = c[size_t((k + 1) % 3)], q = c[size_t((k + 2) % 3)];
      const Point3 from = mesh.vert[size_t(p)].cP(), along = mesh.vert[size_t(q)].cP() - from;
      if (along.SquaredNorm() == 0) continue;
      const double t = ((x - from) * along) / along.SquaredNorm();
      if (t <= 0 || t >= 1) continue;
      sphere[size_t(v)] = ((1 - t) * sphere[size_t(p)] + t * sphere[size_t(q)]).normalized();
      break;
    }
  }
  // Groups: movable vertices joined by an edge move together.
  std::vector<int> moved;
  std::set<int> left = movable;
  while (!left.empty()) {
    std::vector<int> group{*left.begin()};
    left.erase(left.begin());
    for (size_t k = 0; k < group.size(); ++k)
      for (int f : in.faces_of_vertex[size_t(group[k])])
        for (int w : in.corners[size_t(f)])
          if (left.erase(w)) group.push_back(w);
    // Where the faces around cannot be oriented by moving the group alone (their other corners
    // turned the wrong way round it), the ring around it moves too: twice at most.
    for (int grow = 0; grow < 3; ++grow) {
      if (orient_group(in, group, sphere)) {
        moved.insert(moved.end(), group.begin(), group.end());
        break;
      }
      std::set<int> vertices, faces;
      surroundings(in, group, vertices, faces);
      group.clear();
      for (int v : vertices)
        if (!is_branch[size_t(v)]) group.push_back(v);
    }
  }
  std::sort(moved.begin(), moved.end());
  return moved;
}

} // namespace meromorph
