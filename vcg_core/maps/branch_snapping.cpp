#include "maps/branch_snapping.h"

#include <algorithm>
#include <map>
#include <queue>
#include <set>
#include <tuple>

#include "maps/branch_star.h"
#include "mesh/mesh_edges.h"
#include "sphere/branch_points.h"
#include "sphere/map_quality.h"
#include "sphere/sphere_geometry.h"

namespace meromorph {
namespace {

// A conformal coordinate on `region` (a disc): the integral of a holomorphic 1-form from
// `origin` along edges (path independent there: the form is closed).
std::map<int, Complex> integrated_coordinate(const MeshEdges &edges,
                                             const std::vector<std::vector<int>> &edges_at,
                                             const Eigen::VectorXcd &form, int origin,
                                             const std::map<int, int> &region) {
  std::map<int, Complex> z{{origin, Complex()}};
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

// Vertices that touch a folded or flat face or wind less than once, in spots connected through
// faces.
std::vector<std::vector<int>> trouble_spots(const FaceIncidence &in,
                                            const std::vector<Eigen::Vector3d> &sphere) {
  const int vertex_count = int(in.faces_of_vertex.size());
  std::vector<char> trouble(vertex_count, 0);
  for (size_t f = 0; f < in.corners.size(); ++f)
    if (folded_or_flat(in, sphere, int(f)))
      for (int v : in.corners[f])
        trouble[v] = 1;
  for (int v = 0; v < vertex_count; ++v)
    if (!trouble[v] && vertex_winding(in, sphere, v) < 1) trouble[v] = 1;
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

} // namespace

int snap_branch_points(const PreparedMesh &prepared,
                       const std::vector<const Eigen::VectorXcd *> &coordinate_forms,
                       std::vector<PlaneValue> &plane_values) {
  const Mesh &mesh = prepared.mesh;
  const MeshEdges &edges = prepared.edges;
  constexpr int fit_rings = 2;       // around the spot, where the model is fitted
  constexpr int max_shift_rings = 5; // around the chosen vertex, where the map is changed
  const FaceIncidence &in = prepared.incidence;
  const std::vector<std::vector<int>> &edges_at = prepared.edges_at_vertex;
  std::vector<Eigen::Vector3d> sphere;
  for (const PlaneValue &v : plane_values)
    sphere.push_back(to_sphere(v));

  int repaired = 0;
  for (const std::vector<int> &spot : trouble_spots(in, sphere)) {
    if (spot.size() > 64) continue; // not a lone critical point: leave it as measured
    const std::map<int, int> region = ring_distances(in, spot, fit_rings + max_shift_rings + 1);
    std::vector<int> region_faces;
    {
      std::set<int> faces;
      for (const auto &[v, ring] : region)
        faces.insert(in.faces_of_vertex[v].begin(), in.faces_of_vertex[v].end());
      region_faces.assign(faces.begin(), faces.end());
    }
    // Folded faces, then flat ones (a corner of 90 degrees or more at a branch vertex is flat
    // after doubling: not a fold), then winding not 2 at the branch vertex, then angle distortion.
    using Score = std::tuple<int, int, int, double>;
    auto score_region = [&](int branch_vertex) {
      Score score{0, 0, branch_vertex < 0 || vertex_winding(in, sphere, branch_vertex) != 2, 0.0};
      for (int f : region_faces) {
        const auto &c = in.corners[f];
        const bool folded = folded_image(sphere[c[0]], sphere[c[1]], sphere[c[2]]);
        std::get<0>(score) += folded;
        std::get<1>(score) += !folded && folded_or_flat(in, sphere, f);
        std::get<3>(score) += face_angle_error_degrees(mesh, sphere, f);
      }
      return score;
    };

    // How many critical points the spot holds: each folded face around it stands for a turn that
    // its vertices' windings miss (over a closed surface, the sum of e - 1 plus the folded faces
    // is 2d - chi). None: a vertex value strays (next to needle-shaped faces, say); smooth the
    // spot's values towards their neighbours' instead.
    int critical_points = 0;
    {
      std::set<int> spot_faces;
      for (int v : spot) {
        critical_points += vertex_winding(in, sphere, v) - 1;
        spot_faces.insert(in.faces_of_vertex[v].begin(), in.faces_of_vertex[v].end());
      }
      for (int f : spot_faces) {
        const auto &c = in.corners[f];
        critical_points += folded_image(sphere[c[0]], sphere[c[1]], sphere[c[2]]);
      }
    }
    if (critical_points <= 0) {
      std::vector<std::pair<int, Eigen::Vector3d>> original;
      for (int v : spot)
        original.push_back({v, sphere[v]});
      const Score before = score_region(-1);
      for (int round = 0; round < 4; ++round)
        for (int v : spot) {
          Eigen::Vector3d mean = Eigen::Vector3d::Zero();
          for (int f : in.faces_of_vertex[v])
            for (int w : in.corners[f])
              if (w != v) mean += sphere[w];
          sphere[v] = mean.normalized();
        }
      if (score_region(-1) < before) {
        for (int v : spot)
          plane_values[v] = to_plane_value(sphere[v]);
        ++repaired;
      } else {
        for (const auto &[v, point] : original)
          sphere[v] = point;
      }
      continue;
    }

    // The coordinate: the integral of the form that is larger near the spot (far from its zeros).
    const Eigen::VectorXcd *form = coordinate_forms.front();
    double largest = -1;
    for (const Eigen::VectorXcd *candidate : coordinate_forms) {
      double size = 0;
      for (const auto &[v, ring] : region)
        if (ring <= fit_rings)
          for (int e : edges_at[v])
            size += std::abs((*candidate)[e]);
      if (size > largest) {
        largest = size;
        form = candidate;
      }
    }
    std::map<int, Complex> z = integrated_coordinate(edges, edges_at, *form, spot.front(), region);

    // Near a critical point p the map is Q(z) = c + k (z - p)^2 = A + B z + C z^2: fit A, B, C by
    // least squares in a chart of the sphere centred at the spot's image, and read off
    // p = -B / 2C and the critical value c = Q(p). A spot that holds two critical points close
    // together gets a cubic instead, whose derivative's two roots are both tried (the next pass
    // takes the other one).
    std::vector<int> fitted;
    for (const auto &[v, ring] : region)
      if (ring <= fit_rings) fitted.push_back(v);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int v : fitted)
      centre += sphere[v];
    centre.normalize();
    const int terms = critical_points >= 2 ? 4 : 3;
    Eigen::MatrixXcd design(long(fitted.size()), terms);
    Eigen::VectorXcd image(long(fitted.size()));
    for (size_t i = 0; i < fitted.size(); ++i) {
      Complex power = 1.0;
      for (int k = 0; k < terms; ++k, power *= z[fitted[i]])
        design(long(i), k) = power;
      image[long(i)] = chart_at(centre, sphere[fitted[i]]);
    }
    const Eigen::VectorXcd abc = design.colPivHouseholderQr().solve(image);
    if (!abc.allFinite()) continue;
    auto model = [&](Complex x) {
      Complex value = 0;
      for (int k = terms - 1; k >= 0; --k)
        value = value * x + abc[k];
      return value;
    };
    std::vector<Complex> targets;
    if (terms == 4 && std::abs(abc[3]) > 0) {
      const Complex root = std::sqrt(abc[2] * abc[2] - 3.0 * abc[1] * abc[3]);
      targets = {(-abc[2] + root) / (3.0 * abc[3]), (-abc[2] - root) / (3.0 * abc[3])};
    } else if (std::abs(abc[2]) > 0) {
      targets = {-abc[1] / (2.0 * abc[2])};
    }

    // Candidates: the 6 vertices nearest p, then, if none of them winds twice without folding a
    // face (a corner of 90 degrees or more at a branch vertex turns its face over), the next 6.
    // Each is tried with the map composed with the shift z -> z + t (p - z_v), t = 1 - ring / R at
    // the vertices R - 1 rings or less from v (R = 1: v alone takes c); the fold-free one that
    // distorts angles least wins (farther candidates distort more, so they come second).
    Score best = score_region(-1);
    std::vector<std::pair<int, Eigen::Vector3d>> best_change;
    for (const Complex p : targets) {
      const Complex c = model(p);
      std::vector<std::pair<double, int>> by_distance;
      for (int v : fitted)
        by_distance.push_back({std::abs(z[v] - p), v});
      std::sort(by_distance.begin(), by_distance.end());
      for (const size_t first : {size_t(0), size_t(6)}) {
        if (first > 0 && std::get<0>(best) == 0 && std::get<2>(best) == 0) break;
        for (int shift_rings = 1; shift_rings <= max_shift_rings; ++shift_rings)
          for (size_t i = first; i < std::min<size_t>(first + 6, by_distance.size()); ++i) {
            const int v = by_distance[i].second;
            const Complex shift = p - z[v];
            std::vector<std::pair<int, Eigen::Vector3d>> change, original;
            for (const auto &[w, ring] : ring_distances(in, {v}, shift_rings - 1)) {
              const double t = 1.0 - double(ring) / shift_rings;
              const Complex value =
                  w == v ? c : chart_at(centre, sphere[w]) + model(z[w] + t * shift) - model(z[w]);
              change.push_back({w, from_chart(centre, value)});
            }
            // Moves applied (what they replace saved), the spot scored.
            auto score_moved = [&](const std::vector<std::pair<int, Eigen::Vector3d>> &moves,
                                   std::vector<std::pair<int, Eigen::Vector3d>> &saved) {
              for (const auto &[w, point] : moves) {
                saved.push_back({w, sphere[w]});
                sphere[w] = point;
              }
              return score_region(v);
            };
            const Score score = score_moved(change, original);
            if (score < best) {
              best = score;
              best_change = change;
            }
            // The same with the one-ring re-placed around the critical value, for stars whose
            // corners would reach 180 degrees or more when doubled.
            // From the neighbour of lowest index: the star's overall turn keeps that one's
            // direction.
            std::vector<int> ring = ordered_ring(in, v);
            std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end()), ring.end());
            std::vector<Complex> ring_values;
            std::vector<double> corners;
            for (size_t k = 0; k < ring.size(); ++k) {
              ring_values.push_back(chart_at(centre, sphere[ring[k]]));
              const Point3 &at = mesh.vert[size_t(v)].cP();
              corners.push_back(
                  vcg::Angle(mesh.vert[size_t(ring[k])].cP() - at,
                             mesh.vert[size_t(ring[(k + 1) % ring.size()])].cP() - at));
            }
            if (double_star(corners, c, ring_values)) {
              std::vector<std::pair<int, Eigen::Vector3d>> replaced = change;
              for (size_t k = 0; k < ring.size(); ++k) {
                const int w = ring[k];
                if (!std::any_of(original.begin(), original.end(),
                                 [&](const auto &o) { return o.first == w; }))
                  original.push_back({w, sphere[w]});
                sphere[w] = from_chart(centre, ring_values[k]);
                replaced.push_back({w, sphere[w]});
              }
              const Score doubled = score_region(v);
              if (doubled < best) {
                best = doubled;
                best_change = replaced;
              }
              // And the rings beyond re-embedded between the new star and the rest, where the
              // moved one-ring folds the faces next to it.
              for (int rings = 2; rings <= 3 && std::get<0>(best) > 0; ++rings) {
                const auto around = reembed_around_branch(mesh, in, sphere, v, rings);
                if (!around) continue;
                std::vector<std::pair<int, Eigen::Vector3d>> kept;
                const Score wider = score_moved(*around, kept);
                if (wider < best) {
                  best = wider;
                  best_change = replaced;
                  best_change.insert(best_change.end(), around->begin(), around->end());
                }
                for (const auto &[w, point] : kept)
                  sphere[w] = point;
              }
            }
            for (const auto &[w, point] : original)
              sphere[w] = point;
          }
      }
    }
    if (best_change.empty()) continue;
    for (const auto &[w, point] : best_change) {
      sphere[w] = point;
      plane_values[w] = to_plane_value(point);
    }
    ++repaired;
  }
  return repaired;
}

} // namespace meromorph
