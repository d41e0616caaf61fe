#include "remesh/layered_sphere_lift.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <iterator>
#include <limits>
#include <map>
#include <set>

#include <Eigen/Geometry>

#include "common/errors.h"
#include "mesh/face_vectors.h"

namespace meromorph {
namespace {

struct Lift {
  SurfacePoint point;
  Eigen::Vector3d position;
};

// Where the lift of a sphere edge runs off the surface's boundary: the sphere value there, the
// sphere vertex and lift the edge starts from, and how far along the edge (0 to 1).
struct Stop {
  Lift lift;
  Eigen::Vector3d value;
  int from = -1, from_lift = -1;
  double t = 0;
};

// The lifts of every sphere vertex, and for every directed sphere edge from a vertex that carries
// no branch value and each lift of its start, which lift of its end the edge's lift reaches.
class EdgeLifting {
public:
  EdgeLifting(const MappedSurface &surface, const GeodesicSphere &sphere, int degree)
      : surface_(surface), sphere_(sphere), degree_(degree), lifts_(sphere.vertices.size()) {
    first_edge_.push_back(0);
    for (const auto &around : sphere.neighbours)
      first_edge_.push_back(first_edge_.back() + int(around.size()));
    reached_.assign(size_t(first_edge_.back()) * degree, -1);
    stop_.assign(reached_.size(), -1);
    double extent = 0;
    for (const Eigen::Vector3d &p : surface.positions)
      extent = std::max(extent, p.cwiseAbs().maxCoeff());
    same_point_ = 1e-7 * std::max(extent, 1e-300);
    max_steps_ = int(surface.faces.size()) + 16;
  }

  void run(const Progress &progress) {
    std::deque<int> queue{seed()};
    std::vector<char> queued(sphere_.vertices.size(), 0);
    queued[queue.front()] = 1;
    size_t done = 0;
    while (!queue.empty()) {
      const int q = queue.front();
      queue.pop_front();
      walk_edges_from(q);
      for (int r : sphere_.neighbours[q])
        if (!queued[r] && sphere_.branch_value[r] < 0 && !lifts_[r].empty()) {
          queued[r] = 1;
          queue.push_back(r);
        }
      if (++done % 4096 == 0)
        progress.report(double(done) / double(sphere_.vertices.size()), "lifting the sphere");
    }
  }

  const std::vector<Lift> &lifts(int q) const { return lifts_[q]; }
  // The lift of r reached from lift i of q along edge q -> r, or -1.
  int reached(int q, int r, int i) const { return slot_value(reached_, q, r, i); }
  // Where the lift of edge q -> r from lift i of q runs off the surface's boundary (an index into
  // stops()), or -1.
  int stop(int q, int r, int i) const { return slot_value(stop_, q, r, i); }
  const std::vector<Stop> &stops() const { return stops_; }

private:
  // A vertex carrying no branch value over which exactly d points are found.
  int seed() {
    const int count = int(sphere_.vertices.size());
    for (int attempt = 0; attempt < 64; ++attempt) {
      const int q = int((long long)(attempt)*7919 % count);
      if (sphere_.branch_value[q] >= 0) continue;
      const std::vector<SurfacePoint> over = points_over(surface_, sphere_.vertices[q]);
      if (int(over.size()) != degree_) continue;
      for (const SurfacePoint &point : over)
        lifts_[q].push_back({point, position_of(surface_, point)});
      return q;
    }
    throw InternalError("remesh: no point of the sphere was found covered exactly " +
                        std::to_string(degree_) + " times by the map");
  }

  int match(int r, SurfacePoint point) {
    if (sphere_.branch_value[r] >= 0) point = at_corner_over(point, sphere_.vertices[r]);
    const Eigen::Vector3d p = position_of(surface_, point);
    auto &known = lifts_[r];
    for (size_t j = 0; j < known.size(); ++j)
      if ((known[j].position - p).norm() < same_point_) return int(j);
    known.push_back({point, p});
    return int(known.size()) - 1;
  }

  void walk_edges_from(int q) {
    const auto &around = sphere_.neighbours[q];
    const int lifts = std::min<int>(int(lifts_[q].size()), degree_);
    for (size_t n = 0; n < around.size(); ++n) {
      const int r = around[n];
      for (int i = 0; i < lifts; ++i) {
        PathPoint exit;
        const std::optional<SurfacePoint> end =
            lift_arc(surface_, lifts_[q][i].point, sphere_.vertices[q], sphere_.vertices[r],
                     max_steps_, nullptr, &exit);
        const size_t slot = (size_t(first_edge_[q]) + n) * degree_ + i;
        if (end) {
          reached_[slot] = match(r, *end);
        } else if (exit.point.face >= 0) {
          stop_[slot] = int(stops_.size());
          const Eigen::Vector3d value =
              ((1 - exit.t) * sphere_.vertices[q] + exit.t * sphere_.vertices[r]).normalized();
          stops_.push_back({{exit.point, position_of(surface_, exit.point)}, value, q, i, exit.t});
        }
      }
    }
  }

  // A walk that ends over a branch value ends at the corner of its face (or of a face one or two
  // sides away) whose image that value is (within its face the map takes the value nowhere else).
  // Near a branch point the surface position moves as the square root of the value, so an end a
  // rounding away from the corner would lie farther from it than lifts are matched by (seen on two
  // branch points of one pair of sheets 1.6e-4 apart on the sphere: the branch point found three
  // times).
  SurfacePoint at_corner_over(const SurfacePoint &point, const Eigen::Vector3d &value) const {
    // The face itself, then the faces across its sides and theirs (a walk may stop a rounding
    // short, in a face next to the branch vertex's own where the image is tiny).
    std::vector<int> faces{point.face};
    for (size_t next = 0; next < faces.size() && faces.size() < 16; ++next) {
      const int f = faces[next];
      for (int k = 0; k < 3; ++k)
        if ((surface_.image[size_t(surface_.faces[size_t(f)][k])] - value).norm() < 1e-12) {
          SurfacePoint corner{f, Eigen::Vector3d::Zero()};
          corner.weights[k] = 1;
          return corner;
        }
      if (next < 4)
        for (int across : surface_.across[size_t(f)])
          if (across >= 0 && std::find(faces.begin(), faces.end(), across) == faces.end())
            faces.push_back(across);
    }
    return point;
  }

  int slot_value(const std::vector<int> &values, int q, int r, int i) const {
    if (i < 0 || i >= degree_) return -1; // a lift beyond the degree (a vertex over more points)
    const auto &around = sphere_.neighbours[q];
    for (size_t n = 0; n < around.size(); ++n)
      if (around[n] == r) return values[(size_t(first_edge_[q]) + n) * degree_ + i];
    return -1;
  }

  const MappedSurface &surface_;
  const GeodesicSphere &sphere_;
  int degree_;
  std::vector<std::vector<Lift>> lifts_;
  std::vector<int> first_edge_, reached_, stop_;
  std::vector<Stop> stops_;
  double same_point_ = 0;
  int max_steps_ = 0;
};

Eigen::Vector3d surface_normal_at(const MappedSurface &surface, const SurfacePoint &point) {
  const auto &c = surface.faces[point.face];
  const Eigen::Vector3d &a = surface.positions[c[0]], &b = surface.positions[c[1]],
                        &d = surface.positions[c[2]];
  const Eigen::Vector3d normal = (b - a).cross(d - a);
  const double norm = normal.norm();
  return norm > 0 ? Eigen::Vector3d(normal / norm) : Eigen::Vector3d::Zero();
}

int local_degree_at(const MappedSurface &surface, const SurfacePoint &point,
                    const std::vector<int> &local_degree) {
  for (int k = 0; k < 3; ++k)
    if (point.weights[k] > 1 - 1e-9) {
      const int e = local_degree[surface.faces[point.face][k]];
      return e >= 2 ? e : 0;
    }
  return 0;
}

} // namespace

bool lifted_face_folds(const MappedSurface &surface, const LiftedSphere &lifted,
                       const std::array<int, 3> &face) {
  const Eigen::Vector3d &p = lifted.positions[face[0]], &q = lifted.positions[face[1]],
                        &r = lifted.positions[face[2]];
  const Eigen::Vector3d normal = (q - p).cross(r - p).normalized();
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  for (int corner : face) {
    const Eigen::Vector3d at_corner = surface_normal_at(surface, lifted.surface_point[corner]);
    // Across a thin part's rim (an ear's edge), a face can agree with the surface at two corners
    // and be turned over at the third.
    if (normal.dot(at_corner) < -0.5 * at_corner.norm()) return true;
    reference += at_corner;
  }
  return normal.dot(reference) < 0;
}

double smallest_corner_angle(const LiftedSphere &lifted, const std::array<int, 3> &face) {
  double smallest = M_PI;
  for (int k = 0; k < 3; ++k)
    smallest = std::min(smallest,
                        corner_angle(lifted.positions[face[k]], lifted.positions[face[(k + 1) % 3]],
                                     lifted.positions[face[(k + 2) % 3]]));
  return smallest;
}

bool positive_on_sphere(const LiftedSphere &lifted, const std::array<int, 3> &face) {
  return lifted.sphere[face[0]].dot(lifted.sphere[face[1]].cross(lifted.sphere[face[2]])) > 0;
}

int count_folded_lifts(const MappedSurface &surface, const LiftedSphere &lifted) {
  int folded = 0;
  for (const auto &face : lifted.faces)
    folded += lifted_face_folds(surface, lifted, face);
  return folded;
}

namespace {

// One pass of join_near_boundary_vertices; returns whether anything was joined.
bool join_near_boundary_vertices_once(LiftedSphere &out) {
  std::vector<std::set<int>> around(out.positions.size());
  for (const auto &face : out.faces)
    for (int k = 0; k < 3; ++k) {
      around[size_t(face[k])].insert(face[(k + 1) % 3]);
      around[size_t(face[k])].insert(face[(k + 2) % 3]);
    }
  std::vector<int> into(out.positions.size(), -1);
  std::vector<char> touched(out.positions.size(), 0);
  for (const auto &face : out.faces) {
    double longest = 0;
    for (int k = 0; k < 3; ++k)
      longest = std::max(
          longest,
          (out.positions[size_t(face[k])] - out.positions[size_t(face[(k + 1) % 3])]).norm());
    for (int k = 0; k < 3; ++k) {
      const int a = face[k], b = face[(k + 1) % 3], c = face[(k + 2) % 3];
      if (!out.on_boundary[size_t(a)] || !out.on_boundary[size_t(b)] || touched[size_t(a)] ||
          touched[size_t(b)] || touched[size_t(c)])
        continue;
      if ((out.positions[size_t(a)] - out.positions[size_t(b)]).norm() >= 0.1 * longest) continue;
      std::vector<int> common;
      std::set_intersection(around[size_t(a)].begin(), around[size_t(a)].end(),
                            around[size_t(b)].begin(), around[size_t(b)].end(),
                            std::back_inserter(common));
      if (common != std::vector<int>{c}) continue;
      into[size_t(b)] = a;
      touched[size_t(a)] = touched[size_t(b)] = touched[size_t(c)] = 1;
      break;
    }
  }
  if (std::find_if(into.begin(), into.end(), [](int v) { return v >= 0; }) == into.end())
    return false;
  std::vector<std::array<int, 3>> kept;
  for (auto face : out.faces) {
    for (int &corner : face)
      if (into[size_t(corner)] >= 0) corner = into[size_t(corner)];
    if (face[0] != face[1] && face[1] != face[2] && face[2] != face[0]) kept.push_back(face);
  }
  out.faces = std::move(kept);
  return true;
}

} // namespace

void join_near_boundary_vertices(const MappedSurface &surface, LiftedSphere &lifted) {
  if (std::find(lifted.on_boundary.begin(), lifted.on_boundary.end(), 1) ==
      lifted.on_boundary.end())
    return;
  bool joined = false;
  for (int pass = 0; pass < 3; ++pass)
    if (join_near_boundary_vertices_once(lifted))
      joined = true;
    else
      break;
  if (joined) lifted.folded_lifts = count_folded_lifts(surface, lifted);
}

int drop_folded_boundary_faces(const MappedSurface &surface, LiftedSphere &lifted) {
  int dropped = 0;
  for (bool changed = true; changed;) {
    changed = false;
    std::map<std::pair<int, int>, int> faces_on; // per side
    auto side = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
    for (const auto &face : lifted.faces)
      for (int k = 0; k < 3; ++k)
        ++faces_on[side(face[k], face[(k + 1) % 3])];
    std::vector<char> open_fan(lifted.positions.size(), 0), touched(lifted.positions.size(), 0);
    for (const auto &[ends, count] : faces_on)
      if (count == 1) open_fan[size_t(ends.first)] = open_fan[size_t(ends.second)] = 1;
    std::vector<std::array<int, 3>> kept;
    for (const auto &face : lifted.faces) {
      bool drop = false;
      if (!touched[size_t(face[0])] && !touched[size_t(face[1])] && !touched[size_t(face[2])] &&
          lifted_face_folds(surface, lifted, face))
        for (int k = 0; k < 3; ++k)
          drop |= faces_on[side(face[k], face[(k + 1) % 3])] == 1 &&
                  !open_fan[size_t(face[(k + 2) % 3])];
      if (!drop) {
        kept.push_back(face);
        continue;
      }
      for (int corner : face)
        touched[size_t(corner)] = 1;
      ++dropped;
      changed = true;
    }
    lifted.faces = std::move(kept);
  }
  lifted.folded_lifts = count_folded_lifts(surface, lifted);
  return dropped;
}

namespace {

// The lifted sphere made from the lifts of the sphere's vertices and edges: its vertices (every
// lift of every sphere vertex, then the stops where lifts leave the surface, as they are used)
// and the copies of each sphere face.
class LiftedFaces {
public:
  LiftedFaces(const MappedSurface &surface, const std::vector<int> &face_layer,
              const std::vector<int> &local_degree, int degree, const GeodesicSphere &sphere,
              const EdgeLifting &lifting, LiftedSphere &out)
      : surface_(surface), face_layer_(face_layer), degree_(degree), sphere_(sphere),
        lifting_(lifting), out_(out) {
    first_.assign(sphere.vertices.size() + 1, 0);
    for (size_t q = 0; q < sphere.vertices.size(); ++q) {
      first_[q + 1] = first_[q] + int(lifting.lifts(int(q)).size());
      for (const Lift &lift : lifting.lifts(int(q)))
        add_vertex(lift.position, sphere.vertices[q], lift.point,
                   local_degree_at(surface, lift.point, local_degree), 0);
    }
    // A stop very near the lift its edge starts from would make a sliver: the nearest such stop
    // of each lift is that lift itself (the boundary passes a few hundredths of a side from it;
    // faces made degenerate go).
    stop_vertex_.assign(lifting.stops().size(), -1);
    std::vector<int> nearest_stop(out.positions.size(), -1);
    for (size_t s = 0; s < lifting.stops().size(); ++s) {
      const Stop &stop = lifting.stops()[s];
      int &nearest = nearest_stop[size_t(first_[stop.from] + stop.from_lift)];
      if (stop.t < 0.15 && (nearest < 0 || stop.t < lifting.stops()[size_t(nearest)].t))
        nearest = int(s);
    }
    for (size_t v = 0; v < nearest_stop.size(); ++v)
      if (nearest_stop[v] >= 0) stop_vertex_[size_t(nearest_stop[v])] = int(v);
  }

  // Each corner that carries no branch value starts the copies its lifts are in and no earlier
  // corner's lift reached (a corner in a hole's gap in one sheet has fewer lifts).
  void lift_face(const std::array<int, 3> &face) {
    std::array<std::vector<char>, 3> covered;
    for (int m = 0; m < 3; ++m)
      covered[size_t(m)].assign(lifting_.lifts(face[size_t(m)]).size(), 0);
    int copies = 0;
    for (int m = 0; m < 3; ++m) {
      const int x0 = face[size_t(m)], x1 = face[size_t((m + 1) % 3)],
                x2 = face[size_t((m + 2) % 3)];
      if (sphere_.branch_value[x0] >= 0) continue;
      const int lifts = std::min<int>(int(lifting_.lifts(x0).size()), degree_);
      for (int i = 0; i < lifts; ++i) {
        if (covered[size_t(m)][size_t(i)]) continue;
        std::array<int, 2> reached_lifts{};
        if (!lift_copy(x0, x1, x2, i, reached_lifts)) continue;
        ++copies;
        covered[size_t(m)][size_t(i)] = 1;
        for (int n = 0; n < 2; ++n) {
          auto &other = covered[size_t((m + 1 + n) % 3)];
          const int lift = reached_lifts[size_t(n)];
          if (lift >= 0 && size_t(lift) < other.size()) other[size_t(lift)] = 1;
        }
      }
    }
    out_.unlifted_faces += std::max(0, degree_ - copies);
  }

private:
  void add_vertex(const Eigen::Vector3d &position, const Eigen::Vector3d &value,
                  const SurfacePoint &point, int local_degree, char on_boundary) {
    out_.positions.push_back(position);
    out_.sphere.push_back(value);
    out_.layer.push_back(face_layer_.empty() ? 0 : face_layer_[point.face]);
    out_.local_degree.push_back(local_degree);
    out_.surface_point.push_back(point);
    out_.on_boundary.push_back(on_boundary);
  }
  // The lifted vertex of a boundary stop, added when first used.
  int stop_at(int stop) {
    if (stop_vertex_[size_t(stop)] < 0) {
      const Stop &where = lifting_.stops()[size_t(stop)];
      stop_vertex_[size_t(stop)] = int(out_.positions.size());
      add_vertex(where.lift.position, where.value, where.lift.point, 0, 1);
    }
    return stop_vertex_[size_t(stop)];
  }
  void add_cut_face(const std::array<int, 3> &corners) { // a stop merged into a corner
    if (corners[0] != corners[1] && corners[1] != corners[2] && corners[2] != corners[0])
      out_.faces.push_back(corners);
  }
  // One copy of a face: from lift i of corner x0 (no branch value) along its sides to x1 and x2
  // (counter-clockwise); which lifts of x1 and x2 it reached go into `reached_lifts` (-1: none).
  bool lift_copy(int x0, int x1, int x2, int i, std::array<int, 2> &reached_lifts) {
    const int j = lifting_.reached(x0, x1, i), k = lifting_.reached(x0, x2, i);
    reached_lifts = {j, k};
    const int l0 = first_[x0] + i;
    if (j >= 0 && k >= 0) {
      if (sphere_.branch_value[x1] < 0 && lifting_.reached(x1, x2, j) != k) {
        ++out_.unclosed_faces;
        out_.unclosed_at.push_back(
            (sphere_.vertices[x0] + sphere_.vertices[x1] + sphere_.vertices[x2]).normalized());
        return true;
      }
      out_.faces.push_back({l0, first_[x1] + j, first_[x2] + k});
      return true;
    }
    // The lift runs off a hole: the face is cut where its sides' lifts leave the surface.
    const int s01 = j < 0 ? lifting_.stop(x0, x1, i) : -1,
              s02 = k < 0 ? lifting_.stop(x0, x2, i) : -1;
    if ((j < 0 && s01 < 0) || (k < 0 && s02 < 0)) return false;
    if (j < 0 && k < 0) {
      add_cut_face({l0, stop_at(s01), stop_at(s02)});
    } else if (j >= 0) { // x1 lifted, x2 not: cut along x1 -> x2 too
      const int s12 = sphere_.branch_value[x1] < 0 ? lifting_.stop(x1, x2, j) : -1;
      if (s12 < 0) return false;
      add_cut_face({l0, first_[x1] + j, stop_at(s12)});
      add_cut_face({l0, stop_at(s12), stop_at(s02)});
    } else { // x2 lifted, x1 not: cut along x2 -> x1 too
      const int s21 = sphere_.branch_value[x2] < 0 ? lifting_.stop(x2, x1, k) : -1;
      if (s21 < 0) return false;
      add_cut_face({l0, stop_at(s01), stop_at(s21)});
      add_cut_face({l0, stop_at(s21), first_[x2] + k});
    }
    return true;
  }

  const MappedSurface &surface_;
  const std::vector<int> &face_layer_;
  const int degree_;
  const GeodesicSphere &sphere_;
  const EdgeLifting &lifting_;
  LiftedSphere &out_;
  std::vector<int> first_;       // per sphere vertex, its first lift's lifted vertex
  std::vector<int> stop_vertex_; // per stop, its lifted vertex (-1: not yet made)
};

} // namespace

LiftedSphere lift_sphere(const MappedSurface &surface, const std::vector<int> &face_layer,
                         const std::vector<int> &local_degree, int degree,
                         const GeodesicSphere &sphere, const Progress &progress) {
  EdgeLifting lifting(surface, sphere, degree);
  lifting.run(progress.range(0.0, 0.9));
  LiftedSphere out;
  LiftedFaces faces(surface, face_layer, local_degree, degree, sphere, lifting, out);
  progress.report(0.9, "joining the lifted faces");
  for (const auto &face : sphere.faces)
    faces.lift_face(face);
  out.folded_lifts = count_folded_lifts(surface, out);
  join_near_boundary_vertices(surface, out);
  progress.report(1.0, "lifted");
  return out;
}

} // namespace meromorph
