#include "maps/branch_snapping.h"

#include <algorithm>
#include <map>
#include <memory_resource>
#include <queue>
#include <set>
#include <tuple>

#include "common/errors.h"
#include "common/parallel_for.h"
#include "common/stack_pool.h"
#include "maps/branch_star.h"
#include "mesh/local_numbers.h"
#include "mesh/mesh_edges.h"
#include "sphere/branch_points.h"
#include "sphere/map_quality.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {
namespace {

// Values by vertex over a spot's region, their nodes from the caller's memory resource.
using Coordinates = std::pmr::map<int, Complex>;

// A conformal coordinate on `region` (a disc): the integral of a holomorphic 1-form from
// `origin` along edges (path independent there: the form is closed).
Coordinates integrated_coordinate(const MeshEdges &edges, const IndexLists &edges_at,
                                  const Eigen::VectorXcd &form, int origin,
                                  const RingDistances &region, std::pmr::memory_resource *pool) {
  Coordinates z({{origin, Complex()}}, pool);
  std::queue<int> queue;
  queue.push(origin);
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop();
    for (int e : edges_at[v]) {
      const bool forward = edges.vertices[e][0] == v;
      const int w = edges.vertices[e][forward ? 1 : 0];
      if (!region.count(w) || z.count(w)) continue;
      z[w] = z[v] + (forward ? form[e] : -form[e]);
      queue.push(w);
    }
  }
  return z;
}

// Vertices that touch a folded or flat face, in spots connected through faces. (Those are all
// that can wind less than once: the corners of a star of faces all turned the right way add up
// to a positive multiple of a full turn.)
std::vector<std::vector<int>> trouble_spots(const FaceIncidence &in,
                                            const std::vector<Eigen::Vector3d> &sphere) {
  const int vertex_count = int(in.faces_of_vertex.size());
  std::vector<char> trouble(vertex_count, 0);
  for (int f : parallel_select(in.corners.size(),
                               [&](size_t f) { return folded_or_flat(in, sphere, int(f)); }))
    for (int v : in.corners[size_t(f)])
      trouble[size_t(v)] = 1;
  std::vector<std::vector<int>> spots;
  std::vector<char> done(vertex_count, 0);
  for (int seed = 0; seed < vertex_count; ++seed) {
    if (!trouble[seed] || done[seed]) continue;
    std::vector<int> spot{seed};
    done[seed] = 1;
    for (size_t i = 0; i < spot.size(); ++i)
      for (int f : in.faces_of_vertex[spot[i]])
        for (int w : in.corners[f])
          if (trouble[w] && !done[w]) {
            done[w] = 1;
            spot.push_back(w);
          }
    spots.push_back(spot);
  }
  return spots;
}

// Chart values of a branch vertex's one-ring (the vertex at `centre_value`, `corners` its corner
// angles between consecutive neighbours) placed so that the star winds twice with every image
// corner below 170 degrees: each neighbour keeps its distance from the centre, its direction
// follows the doubled corners (capped, the excess shared among the others in proportion to their
// size), starting from the first neighbour's direction. False if the star has fewer than five
// corners (two turns need them).
bool double_star(const std::vector<double> &corners, Complex centre_value,
                 std::vector<Complex> &ring_values) {
  const size_t n = corners.size();
  if (n < 5) return false;
  constexpr double cap = 170.0 * M_PI / 180.0;
  double total = 0;
  for (double a : corners)
    total += a;
  std::vector<double> turns(n);
  for (size_t k = 0; k < n; ++k)
    turns[k] = corners[k] * 4.0 * M_PI / total;
  for (int round = 0; round < 8; ++round) {
    double excess = 0, free = 0;
    for (size_t k = 0; k < n; ++k) {
      if (turns[k] > cap) {
        excess += turns[k] - cap;
        turns[k] = cap;
      } else if (turns[k] < cap) {
        free += turns[k];
      }
    }
    if (excess <= 0 || free <= 0) break;
    for (size_t k = 0; k < n; ++k)
      if (turns[k] < cap) turns[k] += excess * turns[k] / free;
  }
  double direction = std::arg(ring_values[0] - centre_value);
  for (size_t k = 0; k < n; ++k) {
    const double radius = std::abs(ring_values[k] - centre_value);
    ring_values[k] = centre_value + std::polar(radius, direction);
    direction += turns[k];
  }
  return true;
}

using Moves = std::vector<std::pair<int, Eigen::Vector3d>>;

// Folded faces, then flat ones (a corner of 90 degrees or more at a branch vertex is flat after
// doubling: not a fold), then winding not 2 at the branch vertex, then angle distortion.
using Score = std::tuple<int, int, int, double>;

struct ScoredFaces {}; // LocalNumbers' tag for a spot's region faces

// The map around one trouble spot, as it is changed and scored.
struct Spot {
  const Mesh &mesh;
  const FaceIncidence &in;
  std::vector<Eigen::Vector3d> &sphere;
  std::vector<int> vertices;
  RingDistances region; // ring distance from the spot, out to where the map may change
  std::vector<int> region_faces;

  // The faces' shares of the score at the spot's values as found (`region_faces`' order), their
  // sum, and the vertices moved since (once per move not yet restored): a score counts afresh
  // only the faces around moved vertices.
  std::vector<Score> found_shares;
  Score found_total{0, 0, 0, 0.0};
  std::vector<int> moved;
  std::vector<std::array<double, 3>> corner_angles;       // per region face, on the surface
  const LocalNumbers<ScoredFaces> *face_number = nullptr; // a region face's index, else -1
  mutable std::vector<char> changed;                      // per region face: the score's marks

  // The share of region face i (`region_faces`' order): its counts, then its distortion.
  Score face_counts(size_t i) const {
    const int f = region_faces[i];
    const bool folded = folded_face(in, sphere, f);
    return {folded, !folded && folded_or_flat(in, sphere, f), 0, 0.0};
  }
  double face_distortion(size_t i) const {
    return face_angle_error_degrees(corner_angles[i], mesh, sphere, region_faces[i]);
  }
  Score face_share(size_t i) const {
    Score share = face_counts(i);
    std::get<3>(share) = face_distortion(i);
    return share;
  }
  void measure_as_found() {
    corner_angles.resize(region_faces.size());
    for (size_t i = 0; i < region_faces.size(); ++i)
      corner_angles[i] = face_corner_angles(mesh, region_faces[i]);
    found_shares.resize(region_faces.size());
    for (size_t i = 0; i < region_faces.size(); ++i)
      found_shares[i] = face_share(i);
    found_total = {0, 0, 0, 0.0};
    for (const Score &share : found_shares)
      add(found_total, share, 1);
  }
  static void add(Score &total, const Score &share, int sign) {
    std::get<0>(total) += sign * std::get<0>(share);
    std::get<1>(total) += sign * std::get<1>(share);
    std::get<3>(total) += sign * std::get<3>(share);
  }
  static auto counts(const Score &score) {
    return std::make_tuple(std::get<0>(score), std::get<1>(score), std::get<2>(score));
  }
  // `bound` (optional): the score to beat. Where the counts alone are worse, the distortion
  // cannot make the score beat it and is not measured (the score's distortion is then infinite):
  // on raw marching cubes with needles, 98% of the changes tried.
  Score score(int branch_vertex, const Score *bound = nullptr) const {
    Score score = found_total;
    std::get<2>(score) = branch_vertex < 0 || vertex_winding(in, sphere, branch_vertex) != 2;
    // The faces around moved vertices (all among the region's), marked, then counted afresh in
    // the region's order.
    for (int v : moved)
      for (int f : in.faces_of_vertex[size_t(v)]) {
        const int i = (*face_number)(f);
        if (i < 0)
          throw InternalError("branch snapping changed face " + std::to_string(f) +
                              " outside the faces it scores");
        changed[size_t(i)] = 1;
      }
    for (size_t i = 0; i < changed.size(); ++i)
      if (changed[i]) {
        const Score now = face_counts(i);
        std::get<0>(score) += std::get<0>(now) - std::get<0>(found_shares[i]);
        std::get<1>(score) += std::get<1>(now) - std::get<1>(found_shares[i]);
      }
    const bool beaten = bound && counts(score) > counts(*bound);
    if (beaten) std::get<3>(score) = HUGE_VAL;
    for (size_t i = 0; i < changed.size(); ++i)
      if (changed[i]) {
        changed[i] = 0;
        if (beaten) continue;
        std::get<3>(score) -= std::get<3>(found_shares[i]);
        std::get<3>(score) += face_distortion(i);
      }
    return score;
  }
  // Moves applied (what they replace appended to `saved`), the spot scored.
  Score score_moved(const Moves &moves, Moves &saved, int branch_vertex, const Score *bound) {
    for (const auto &[w, point] : moves) {
      saved.push_back({w, sphere[size_t(w)]});
      sphere[size_t(w)] = point;
      moved.push_back(w);
    }
    return score(branch_vertex, bound);
  }
  void restore(const Moves &saved) {
    for (auto at = saved.rbegin(); at != saved.rend(); ++at) {
      sphere[size_t(at->first)] = at->second;
      moved.erase(std::find(moved.rbegin(), moved.rend(), at->first).base() - 1);
    }
  }
};

// How many critical points the spot holds: each folded face around it stands for a turn that its
// vertices' windings miss (over a closed surface, the sum of e - 1 plus the folded faces is
// 2d - chi).
int critical_points_in(const Spot &spot) {
  int count = 0;
  std::set<int> spot_faces;
  for (int v : spot.vertices) {
    count += vertex_winding(spot.in, spot.sphere, v) - 1;
    spot_faces.insert(spot.in.faces_of_vertex[size_t(v)].begin(),
                      spot.in.faces_of_vertex[size_t(v)].end());
  }
  for (int f : spot_faces)
    count += folded_face(spot.in, spot.sphere, f);
  return count;
}

// No critical point: a vertex value strays (next to needle-shaped faces, say); the spot's values
// smoothed towards their neighbours'. Returns the new values if that scores better, else none;
// the spot is left as it was.
Moves smooth_stray_values(Spot &spot) {
  Moves original;
  for (int v : spot.vertices)
    original.push_back({v, spot.sphere[size_t(v)]});
  const Score before = spot.score(-1);
  for (int round = 0; round < 4; ++round)
    for (int v : spot.vertices) {
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (int f : spot.in.faces_of_vertex[size_t(v)])
        for (int w : spot.in.corners[size_t(f)])
          if (w != v) mean += spot.sphere[size_t(w)];
      spot.sphere[size_t(v)] = mean.normalized();
    }
  spot.moved.insert(spot.moved.end(), spot.vertices.begin(), spot.vertices.end());
  Moves smoothed;
  if (spot.score(-1) < before)
    for (int v : spot.vertices)
      smoothed.push_back({v, spot.sphere[size_t(v)]});
  spot.restore(original);
  return smoothed;
}

// Near a critical point p the map is Q(z) = c + k (z - p)^2 = A + B z + C z^2 in a chart of the
// sphere centred at the spot's image, z the integral of the coordinate form; a spot that holds
// two critical points close together gets a cubic instead, whose derivative's two roots are both
// tried (the next pass takes the other one).
struct CriticalModel {
  Eigen::Vector3d centre;
  Eigen::VectorXcd coefficients; // A, B, C (, D)
  std::vector<int> fitted;       // the vertices it is fitted on
  std::vector<Complex> critical_points;
  Complex operator()(Complex x) const {
    Complex value = 0;
    for (long k = coefficients.size() - 1; k >= 0; --k)
      value = value * x + coefficients[k];
    return value;
  }
};

// The model fitted by least squares on the vertices within `fit_rings` of the spot; false where
// the fit is not finite.
bool fit_critical_model(const Spot &spot, const Coordinates &z, int critical_points, int fit_rings,
                        CriticalModel &model) {
  for (const auto &[v, ring] : spot.region)
    if (ring <= fit_rings) model.fitted.push_back(v);
  model.centre = Eigen::Vector3d::Zero();
  for (int v : model.fitted)
    model.centre += spot.sphere[size_t(v)];
  model.centre.normalize();
  const int terms = critical_points >= 2 ? 4 : 3;
  Eigen::MatrixXcd design(long(model.fitted.size()), terms);
  Eigen::VectorXcd image(long(model.fitted.size()));
  for (size_t i = 0; i < model.fitted.size(); ++i) {
    Complex power = 1.0;
    for (int k = 0; k < terms; ++k, power *= z.at(model.fitted[i]))
      design(long(i), k) = power;
    image[long(i)] = chart_at(model.centre, spot.sphere[size_t(model.fitted[i])]);
  }
  model.coefficients = design.colPivHouseholderQr().solve(image);
  if (!model.coefficients.allFinite()) return false;
  const Eigen::VectorXcd &abc = model.coefficients;
  if (terms == 4 && std::abs(abc[3]) > 0) {
    const Complex root = std::sqrt(abc[2] * abc[2] - 3.0 * abc[1] * abc[3]);
    model.critical_points = {(-abc[2] + root) / (3.0 * abc[3]), (-abc[2] - root) / (3.0 * abc[3])};
  } else if (std::abs(abc[2]) > 0) {
    model.critical_points = {-abc[1] / (2.0 * abc[2])};
  }
  return true;
}

// The best of the changes tried so far and its score.
struct BestChange {
  Score score;
  Moves moves;
  void offer(const Score &candidate, const Moves &candidate_moves) {

    if (candidate < score) {
      score = candidate;
      moves = candidate_moves;
    }
  }
};

// Vertex v made the branch point with critical value c: the map composed with the shift
// z -> z + t (p - z_v), t = 1 - ring / R at the vertices R - 1 rings or less from v (v itself
// takes c); then the same with v's one-ring re-placed around c (double_star), for stars whose
// corners would reach 180 degrees or more when doubled; and the rings beyond re-embedded between
// the new star and the rest, where the moved one-ring folds the faces next to it. Each scored;
// the spot is left as it was. `rings_around_v`: the ring distances from v, out to the widest
// shift.
void try_branch_vertex(Spot &spot, const CriticalModel &model, const Coordinates &z, Complex p,
                       int v, const RingDistances &rings_around_v, int shift_rings,
                       BestChange &best) {
  const Complex c = model(p);
  const Complex shift = p - z.at(v);
  Moves change, original;
  change.reserve(rings_around_v.size());
  original.reserve(2 * rings_around_v.size());
  for (const auto &[w, ring] : rings_around_v) {
    if (ring > shift_rings - 1) continue;
    const double t = 1.0 - double(ring) / shift_rings;
    const Complex value = w == v ? c
                                 : chart_at(model.centre, spot.sphere[size_t(w)]) +
                                       model(z.at(w) + t * shift) - model(z.at(w));
    change.push_back({w, from_chart(model.centre, value)});
  }
  best.offer(spot.score_moved(change, original, v, &best.score), change);

  // From the neighbour of lowest index: the star's overall turn keeps that one's direction.
  std::vector<int> ring = ordered_ring(spot.in, v);
  std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end()), ring.end());
  std::vector<Complex> ring_values;
  std::vector<double> corners;
  const Point3 &at = spot.mesh.vert[size_t(v)].cP();
  for (size_t k = 0; k < ring.size(); ++k) {
    ring_values.push_back(chart_at(model.centre, spot.sphere[size_t(ring[k])]));
    corners.push_back(vcg::Angle(spot.mesh.vert[size_t(ring[k])].cP() - at,
                                 spot.mesh.vert[size_t(ring[(k + 1) % ring.size()])].cP() - at));
  }
  if (double_star(corners, c, ring_values)) {
    Moves replaced = change, star;
    for (size_t k = 0; k < ring.size(); ++k)
      star.push_back({ring[k], from_chart(model.centre, ring_values[k])});
    replaced.insert(replaced.end(), star.begin(), star.end());
    best.offer(spot.score_moved(star, original, v, &best.score), replaced);
    for (int rings = 2; rings <= 3 && std::get<0>(best.score) > 0; ++rings) {
      const auto around = reembed_around_branch(spot.mesh, spot.in, spot.sphere, v, rings);
      if (!around) continue;
      Moves kept;
      Moves wider = replaced;
      wider.insert(wider.end(), around->begin(), around->end());
      best.offer(spot.score_moved(*around, kept, v, &best.score), wider);
      spot.restore(kept);
    }
  }
  spot.restore(original);
}

// One trouble spot repaired on `sphere` (left as it was): the values to change (none where
// nothing improves on the spot as it is), and the vertices whose values that decision read.
struct SpotRepair {
  Moves moves;
  std::vector<int> read;
};

constexpr int fit_rings = 2;       // around the spot, where the model is fitted
constexpr int max_shift_rings = 5; // around the chosen vertex, where the map is changed

// The faces a change can reach: those at the vertices it can move (a candidate is within
// fit_rings of the spot, and moves vertices up to max_shift_rings - 1 rings from itself; the
// star and its re-embedding stay within 3). Faces beyond add the same to every score.
std::vector<int> faces_a_change_reaches(const FaceIncidence &in, const RingDistances &region) {
  std::vector<int> faces;
  for (const auto &[v, ring] : region)
    if (ring <= fit_rings + max_shift_rings - 1)
      faces.insert(faces.end(), in.faces_of_vertex[size_t(v)].begin(),
                   in.faces_of_vertex[size_t(v)].end());
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

// The coordinate's form: the one that is larger near the spot (far from its zeros).
const Eigen::VectorXcd *coordinate_form(const PreparedMesh &prepared, const Spot &spot,
                                        const std::vector<const Eigen::VectorXcd *> &forms) {
  const Eigen::VectorXcd *form = forms.front();
  double largest = -1;
  for (const Eigen::VectorXcd *candidate : forms) {
    double size = 0;
    for (const auto &[v, ring] : spot.region)
      if (ring <= fit_rings)
        for (int e : prepared.edges_at_vertex[size_t(v)])
          size += std::abs((*candidate)[e]);
    if (size > largest) {
      largest = size;
      form = candidate;
    }
  }
  return form;
}

// Candidates: the 6 vertices nearest each critical point p, then, if none of them winds twice
// without folding a face (a corner of 90 degrees or more at a branch vertex turns its face over),
// the next 6, each with the shift fading over 1 to max_shift_rings rings; the fold-free one that
// distorts angles least wins (farther candidates distort more, so they come second).
Moves best_branch_vertex(Spot &spot, const CriticalModel &model, const Coordinates &z) {
  BestChange best{spot.score(-1), {}};
  std::map<int, RingDistances> rings_of_candidate; // each candidate's, to the widest shift
  auto rings_around = [&](int v) -> const RingDistances & {
    auto at = rings_of_candidate.find(v);
    if (at == rings_of_candidate.end())
      at = rings_of_candidate.emplace(v, ring_distances(spot.in, {v}, max_shift_rings - 1)).first;
    return at->second;
  };
  for (const Complex p : model.critical_points) {
    std::vector<std::pair<double, int>> by_distance;
    for (int v : model.fitted)
      by_distance.push_back({std::abs(z.at(v) - p), v});
    std::sort(by_distance.begin(), by_distance.end());
    for (const size_t first : {size_t(0), size_t(6)}) {
      if (first > 0 && std::get<0>(best.score) == 0 && std::get<2>(best.score) == 0) break;
      for (int shift_rings = 1; shift_rings <= max_shift_rings; ++shift_rings)
        for (size_t i = first; i < std::min<size_t>(first + 6, by_distance.size()); ++i)
          try_branch_vertex(spot, model, z, p, by_distance[i].second,
                            rings_around(by_distance[i].second), shift_rings, best);
    }
  }
  return std::move(best.moves);
}

SpotRepair repair_spot(const PreparedMesh &prepared,
                       const std::vector<const Eigen::VectorXcd *> &coordinate_forms,
                       std::vector<Eigen::Vector3d> &sphere, const std::vector<int> &vertices) {
  const FaceIncidence &in = prepared.incidence;
  SpotRepair out;
  Spot spot{prepared.mesh,
            in,
            sphere,
            vertices,
            ring_distances(in, vertices, fit_rings + max_shift_rings + 1),
            {},
            {},
            {0, 0, 0, 0.0},
            {},
            {},
            nullptr,
            {}};
  spot.region_faces = faces_a_change_reaches(in, spot.region);
  const LocalNumbers<ScoredFaces> face_numbers(spot.region_faces, in.corners.size());
  spot.face_number = &face_numbers;
  spot.changed.assign(spot.region_faces.size(), 0);
  spot.measure_as_found();
  // Everything below reads values at the corners of these faces only (and the fit's vertices
  // and the re-embedding's rings, which are among them).
  for (int f : spot.region_faces)
    out.read.insert(out.read.end(), in.corners[size_t(f)].begin(), in.corners[size_t(f)].end());

  const int critical_points = critical_points_in(spot);
  if (critical_points <= 0) {
    out.moves = smooth_stray_values(spot);
    return out;
  }
  // The coordinate: the integral of the form that is larger near the spot.
  StackPool pool; // (the coordinate's nodes: common/stack_pool.h)
  const Coordinates z = integrated_coordinate(prepared.edges, prepared.edges_at_vertex,
                                              *coordinate_form(prepared, spot, coordinate_forms),
                                              vertices.front(), spot.region, &pool);
  CriticalModel model;
  if (!fit_critical_model(spot, z, critical_points, fit_rings, model)) return out;
  out.moves = best_branch_vertex(spot, model, z);
  return out;
}

} // namespace

int snap_branch_points(const PreparedMesh &prepared,
                       const std::vector<const Eigen::VectorXcd *> &coordinate_forms,
                       std::vector<PlaneValue> &plane_values, SpotsLeftAlone *left_alone) {
  std::vector<Eigen::Vector3d> sphere = to_sphere(plane_values);
  std::vector<std::vector<int>> spots;
  for (std::vector<int> &vertices : trouble_spots(prepared.incidence, sphere))
    if (vertices.size() <= 64) spots.push_back(std::move(vertices)); // else not a lone point
  // A spot an earlier pass left alone, its values unchanged since: left alone again.
  auto known = [&](size_t i) -> const std::vector<int> * {
    if (!left_alone) return nullptr;
    const auto at = left_alone->find(spots[i]);
    return at == left_alone->end() ? nullptr : &at->second;
  };
  // The spots are repaired one after the other. Each is first worked out over the cores on the
  // map as it is now (a scratch copy per thread); one whose values an earlier repair has changed
  // since is worked out again when its turn comes: the same result as in turn throughout.
  std::vector<SpotRepair> repairs(spots.size());
  parallel_for_with(
      spots.size(), [&] { return sphere; },
      [&](size_t i, std::vector<Eigen::Vector3d> &scratch) {
        if (const std::vector<int> *read = known(i))
          repairs[i].read = *read;
        else
          repairs[i] = repair_spot(prepared, coordinate_forms, scratch, spots[i]);
      });
  std::vector<char> changed(sphere.size(), 0);
  auto any_changed = [&](const std::vector<int> &read) {
    return std::any_of(read.begin(), read.end(), [&](int v) { return changed[size_t(v)]; });
  };
  int repaired = 0;
  for (size_t i = 0; i < spots.size(); ++i) {
    SpotRepair &repair = repairs[i];
    if (any_changed(repair.read)) {
      repair = repair_spot(prepared, coordinate_forms, sphere, spots[i]);
    }
    if (repair.moves.empty()) continue;
    for (const auto &[w, point] : repair.moves) {
      sphere[size_t(w)] = point;
      plane_values[size_t(w)] = to_plane_value(point);
      changed[size_t(w)] = 1;
    }
    ++repaired;
  }
  if (left_alone) {
    // What this pass left alone, and what earlier passes did, as long as no value it read has
    // changed in this pass (since its decision or before it: either way, not reused).
    for (size_t i = 0; i < spots.size(); ++i)
      if (repairs[i].moves.empty()) left_alone->emplace(spots[i], std::move(repairs[i].read));
    for (auto at = left_alone->begin(); at != left_alone->end();)
      at = any_changed(at->second) ? left_alone->erase(at) : std::next(at);
  }
  return repaired;
}

} // namespace meromorph
