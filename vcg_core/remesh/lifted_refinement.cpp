#include "remesh/lifted_refinement.h"

#include <algorithm>
#include <map>
#include <optional>

#include <Eigen/Geometry>

namespace meromorph {
namespace {

using Side = std::pair<int, int>;

Side side(int a, int b) {
  return a < b ? Side{a, b} : Side{b, a};
}

// The sides to split this round: those of every face over the limits, closed so that no face
// has exactly two.
std::map<Side, int> sides_to_split(const MappedSurface &surface, const LiftedSphere &lifted,
                                   const RefinementLimits &limits, SampleLocator *locator,
                                   std::map<Side, int> split) {
  std::vector<double> areas = lifted_face_areas(lifted);
  if (locator) {
    const std::vector<double> covered = locator->covered_areas(lifted);
    // Where the lifts of a face's corners have (nearly) met, the map has shrunk that part below
    // what double precision tells apart: splitting cannot reach it.
    for (size_t f = 0; f < areas.size(); ++f)
      if (areas[f] > 1e-4 * limits.face_area) areas[f] = std::max(areas[f], covered[f]);
  }
  for (size_t f = 0; f < lifted.faces.size(); ++f) {
    const auto &face = lifted.faces[f];
    // Faces along a hole's boundary are left as lifted (their sides' middles may lie off the
    // surface).
    if (lifted.on_boundary[size_t(face[0])] + lifted.on_boundary[size_t(face[1])] +
            lifted.on_boundary[size_t(face[2])] >=
        2)
      continue;
    if (areas[f] > limits.face_area || (limits.folded && lifted_face_folds(surface, lifted, face)))
      for (int k = 0; k < 3; ++k)
        split.emplace(side(face[k], face[(k + 1) % 3]), -1);
  }
  for (bool changed = !split.empty(); changed;) {
    changed = false;
    for (const auto &face : lifted.faces) {
      int count = 0;
      for (int k = 0; k < 3; ++k)
        count += split.count(side(face[k], face[(k + 1) % 3])) > 0;
      if (count != 2) continue;
      for (int k = 0; k < 3; ++k)
        split.emplace(side(face[k], face[(k + 1) % 3]), -1);
      changed = true;
    }
  }
  return split;
}

// The point halfway along the lift of side (a, b), measured on the surface (a conformal map's
// scale changes fast where it shrinks the surface, so the sphere's midpoint would lift far off
// the middle), walked from an end that is no branch vertex (nor on the boundary, where the other is
// not).
void add_midpoint(const MappedSurface &surface, const Side &ends, int opposite, int max_steps,
                  LiftedSphere &lifted) {
  int from = ends.first, to = ends.second;
  // From an end that is no branch vertex, and inside the surface where an end is on its boundary.
  if (lifted.local_degree[from] >= 2 ||
      (lifted.on_boundary[from] && !lifted.on_boundary[to] && lifted.local_degree[to] < 2))
    std::swap(from, to);
  const Eigen::Vector3d &a = lifted.sphere[from], &b = lifted.sphere[to];
  std::vector<PathPoint> path{{lifted.surface_point[from], 0.0}};
  const bool walked = bool(lift_arc(surface, path.front().point, a, b, max_steps, &path));
  double t = 0.5;
  if (walked) {
    std::vector<double> length{0.0};
    for (size_t k = 1; k < path.size(); ++k)
      length.push_back(
          length.back() +
          (position_of(surface, path[k].point) - position_of(surface, path[k - 1].point)).norm());
    size_t k = 1;
    while (k + 1 < path.size() && length[k] < 0.5 * length.back())
      ++k;
    const double span = length[k] - length[k - 1];
    const double along = span > 0 ? (0.5 * length.back() - length[k - 1]) / span : 0.5;
    t = path[k - 1].t + std::clamp(along, 0.0, 1.0) * (path[k].t - path[k - 1].t);
  }
  Eigen::Vector3d middle = ((1 - t) * a + t * b).normalized();
  // A side with both ends on the boundary: its lift from either end may leave the surface at once;
  // the middle is reached from the face's third corner inside instead (or where that walk leaves
  // the surface, on the boundary near the middle).
  const bool along_boundary = lifted.on_boundary[from] && lifted.on_boundary[to] && opposite >= 0 &&
                              !lifted.on_boundary[size_t(opposite)] &&
                              lifted.local_degree[size_t(opposite)] < 2;
  const int walker = along_boundary ? opposite : from;
  const Eigen::Vector3d &start = lifted.sphere[size_t(walker)];
  PathPoint exit;
  const std::optional<SurfacePoint> point = lift_arc(surface, lifted.surface_point[size_t(walker)],
                                                     start, middle, max_steps, nullptr, &exit);
  SurfacePoint at = point ? *point : lifted.surface_point[from];
  Eigen::Vector3d position = 0.5 * (lifted.positions[from] + lifted.positions[to]);
  // A side along the boundary whose middle lies off the surface: its middle goes where the lift
  // leaves the surface, on the boundary.
  const bool on_boundary = !point && exit.point.face >= 0;
  if (point) position = position_of(surface, at);
  if (on_boundary) {
    at = exit.point;
    position = position_of(surface, at);
    middle = ((1 - exit.t) * start + exit.t * middle).normalized();
  }
  lifted.positions.push_back(position);
  lifted.sphere.push_back(middle);
  lifted.layer.push_back(lifted.layer[from]);
  lifted.local_degree.push_back(0);
  lifted.surface_point.push_back(at);
  lifted.on_boundary.push_back(on_boundary);
}

// A face halved through the midpoint of one side: the halves, until the next round puts the face
// back whole (halves are never split again, so no angle is halved twice).
struct Halved {
  std::array<int, 3> face; // the side from corner 0 to corner 1 is the one split
  int middle = -1;
};

// Face `face` split along every side in `split`, down to faces none of whose sides is split:
// 1-to-4 when all three sides are, halved through the midpoint of one, cut in three with two
// (after the closure of sides_to_split only where an earlier round's halves left a side split).
void emit_split(const std::array<int, 3> &face, const std::map<Side, int> &split,
                std::vector<std::array<int, 3>> &faces) {
  std::array<int, 3> middle{};
  int count = 0;
  for (int k = 0; k < 3; ++k) {
    const auto found = split.find(side(face[k], face[(k + 1) % 3]));
    middle[k] = found == split.end() ? -1 : found->second;
    count += middle[k] >= 0;
  }
  if (count == 0) {
    faces.push_back(face);
    return;
  }
  if (count == 3) {
    emit_split({face[0], middle[0], middle[2]}, split, faces);
    emit_split({face[1], middle[1], middle[0]}, split, faces);
    emit_split({face[2], middle[2], middle[1]}, split, faces);
    emit_split({middle[0], middle[1], middle[2]}, split, faces);
    return;
  }
  int k = 0; // a split side
  while (middle[k] < 0)
    ++k;
  const int a = face[k], b = face[(k + 1) % 3], c = face[(k + 2) % 3];
  emit_split({a, middle[k], c}, split, faces);
  emit_split({middle[k], b, c}, split, faces);
}

void split_faces(LiftedSphere &lifted, const std::map<Side, int> &split,
                 std::vector<Halved> &halved) {
  std::vector<std::array<int, 3>> faces;
  for (const auto &face : lifted.faces) {
    int count = 0, alone = -1;
    for (int k = 0; k < 3; ++k)
      if (split.count(side(face[k], face[(k + 1) % 3]))) {
        ++count;
        alone = k;
      }
    if (count != 1) {
      emit_split(face, split, faces);
      continue;
    }
    const Halved h{{face[alone], face[(alone + 1) % 3], face[(alone + 2) % 3]},
                   split.at(side(face[alone], face[(alone + 1) % 3]))};
    // Halves none of whose own sides is split are kept apart, to be made whole next round.
    if (split.count(side(h.face[0], h.middle)) || split.count(side(h.middle, h.face[1]))) {
      emit_split(face, split, faces);
      continue;
    }
    halved.push_back(h);
  }
  lifted.faces = std::move(faces);
}

void add_halves(const std::vector<Halved> &halved, LiftedSphere &lifted) {
  for (const Halved &h : halved) {
    lifted.faces.push_back({h.face[0], h.middle, h.face[2]});
    lifted.faces.push_back({h.middle, h.face[1], h.face[2]});
  }
}

} // namespace

std::vector<double> lifted_face_areas(const LiftedSphere &lifted) {
  std::vector<double> areas;
  areas.reserve(lifted.faces.size());
  for (const auto &face : lifted.faces) {
    const Eigen::Vector3d &p = lifted.positions[face[0]], &q = lifted.positions[face[1]],
                          &r = lifted.positions[face[2]];
    areas.push_back(0.5 * (q - p).cross(r - p).norm());
  }
  return areas;
}

void refine_lifted_sphere(const MappedSurface &surface, const RefinementLimits &limits, int rounds,
                          LiftedSphere &lifted) {
  const int max_steps = int(surface.faces.size()) + 16;
  std::vector<Halved> halved;
  std::optional<SampleLocator> locator;
  if (limits.samples) locator = *limits.samples;
  for (int round = 0; round < rounds; ++round) {
    std::map<Side, int> known; // the halved faces whole again, their midpoints kept
    for (const Halved &h : halved) {
      lifted.faces.push_back(h.face);
      known[side(h.face[0], h.face[1])] = h.middle;
    }
    halved.clear();
    std::map<Side, int> split =
        sides_to_split(surface, lifted, limits, locator ? &*locator : nullptr, known);
    std::map<Side, int> opposite; // sides with both ends on the boundary: a face's third corner
    for (const auto &face : lifted.faces)
      for (int k = 0; k < 3; ++k)
        if (lifted.on_boundary[size_t(face[k])] && lifted.on_boundary[size_t(face[(k + 1) % 3])])
          opposite[side(face[k], face[(k + 1) % 3])] = face[(k + 2) % 3];
    for (auto &[ends, middle] : split)
      if (middle < 0) {
        middle = int(lifted.positions.size());
        const auto third = opposite.find(ends);
        add_midpoint(surface, ends, third == opposite.end() ? -1 : third->second, max_steps,
                     lifted);
      }
    split_faces(lifted, split, halved);
    if (split.size() == known.size()) break; // nothing new to split
  }
  add_halves(halved, lifted);
  lifted.folded_lifts = count_folded_lifts(surface, lifted);
}

} // namespace meromorph
