#include "maps/floater_embedding.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

namespace meromorph {
namespace {

// tan of half the angle at corner i of `face`, on the surface: sin / (1 + cos), |a x b| / (|a|
// |b| + a . b) (no arctangent and tangent; NaN where a side has no length).
double tan_half_angle(const Mesh &mesh, const std::array<int, 3> &face, int i) {
  const Point3 &p = mesh.vert[size_t(face[size_t(i)])].cP(),
               &q = mesh.vert[size_t(face[size_t((i + 1) % 3)])].cP(),
               &r = mesh.vert[size_t(face[size_t((i + 2) % 3)])].cP();
  const Point3 a = q - p, b = r - p;
  return (a ^ b).Norm() / (a.Norm() * b.Norm() + a * b);
}

// Up to this many free vertices the system is solved as a dense matrix (partial pivoting LU):
// branch snapping's re-embeddings have 1 to 30 (3 on average on raw marching cubes with needles,
// thousands of them), where the sparse LU's analysis took 7 microseconds a system.
constexpr long dense_unknowns = 64;

} // namespace

bool floater_embedding(const Mesh &mesh, const FaceIncidence &incidence,
                       const std::vector<int> &free, PlanePositions &chart) {
  // The free vertices numbered densely; the weights to each one's neighbours.
  std::vector<int> sorted_free = free;
  std::sort(sorted_free.begin(), sorted_free.end());
  sorted_free.erase(std::unique(sorted_free.begin(), sorted_free.end()), sorted_free.end());
  auto number = [&](int v) {
    const auto at = std::lower_bound(sorted_free.begin(), sorted_free.end(), v);
    return at != sorted_free.end() && *at == v ? long(at - sorted_free.begin()) : -1L;
  };
  const long m = long(sorted_free.size());
  if (m == 0) return true;
  // total_i x_i - sum over free j of w_ij x_j = sum over fixed j of w_ij chart_j, solved at once
  // (the system is small: a region of a few rings). Row by row: each neighbour's weight, its
  // faces' shares added in face order, the neighbours by index.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX2d right = Eigen::MatrixX2d::Zero(m, 2);
  std::vector<std::pair<int, double>> shares, weight; // (neighbour, share), then summed
  for (long i = 0; i < m; ++i) {
    const int v = sorted_free[size_t(i)];
    shares.clear();
    for (int g : incidence.faces_of_vertex[size_t(v)]) {
      const auto &t = incidence.corners[size_t(g)];
      const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      const int ahead = t[size_t((k + 1) % 3)], behind = t[size_t((k + 2) % 3)];
      const double w = tan_half_angle(mesh, t, k);
      const double to_ahead = (mesh.vert[size_t(v)].cP() - mesh.vert[size_t(ahead)].cP()).Norm(),
                   to_behind = (mesh.vert[size_t(v)].cP() - mesh.vert[size_t(behind)].cP()).Norm();
      if (!(to_ahead > 0 && to_behind > 0 && std::isfinite(w))) return false;
      shares.push_back({ahead, w / to_ahead});
      shares.push_back({behind, w / to_behind});
    }
    std::stable_sort(shares.begin(), shares.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
    weight.clear();
    for (const auto &[w, share] : shares)
      if (!weight.empty() && weight.back().first == w)
        weight.back().second += share;
      else
        weight.push_back({w, 0.0 + share});
    double total = 0;
    for (const auto &[w, value] : weight) {
      total += value;
      const long j = number(w);
      if (j >= 0) {
        entries.emplace_back(i, j, -value);
        continue;
      }
      const auto fixed = chart.find(w); // a fixed neighbour, which must have its position
      if (fixed == chart.end()) return false;
      right.row(i) += value * fixed->second.transpose();
    }
    entries.emplace_back(i, i, total);
  }
  Eigen::MatrixX2d placed;
  if (m <= dense_unknowns) {
    Eigen::MatrixXd system = Eigen::MatrixXd::Zero(m, m);
    for (const Eigen::Triplet<double> &entry : entries)
      system(entry.row(), entry.col()) += entry.value();
    // (a singular system leaves a pivot of 0: not finite then)
    placed = system.partialPivLu().solve(right);
  } else {
    Eigen::SparseMatrix<double> system(m, m);
    system.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(system);
    if (solver.info() != Eigen::Success) return false;
    placed = solver.solve(right);
    if (solver.info() != Eigen::Success) return false;
  }
  if (!placed.allFinite()) return false;
  for (long i = 0; i < m; ++i)
    chart[sorted_free[size_t(i)]] = placed.row(i).transpose();
  return true;
}

GnomonicChart::GnomonicChart(const Eigen::Vector3d &centre_)
    : centre(centre_.normalized()), u1(centre.unitOrthogonal()), u2(centre.cross(u1)) {}

bool GnomonicChart::to_chart(const Eigen::Vector3d &p, Eigen::Vector2d &x) const {
  const double height = p.dot(centre);
  if (!(height > 0.1)) return false;
  x = {p.dot(u1) / height, p.dot(u2) / height};
  return true;
}

Eigen::Vector3d GnomonicChart::to_sphere(const Eigen::Vector2d &x) const {
  return (centre + x.x() * u1 + x.y() * u2).normalized();
}

} // namespace meromorph
