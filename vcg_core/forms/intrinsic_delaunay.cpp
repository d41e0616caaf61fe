#include "forms/intrinsic_delaunay.h"

#include <algorithm>
#include <cmath>

namespace meromorph {
namespace {

// The angle opposite side a in a triangle with sides a, b, c (law of cosines, clamped).
double opposite_angle(double a, double b, double c) {
  const double cosine = (b * b + c * c - a * a) / (2 * b * c);
  return std::acos(std::clamp(cosine, -1.0, 1.0));
}

// Twice the area of a triangle from its sides (Kahan's stable form of Heron's formula).
double double_area(double a, double b, double c) {
  std::array<double, 3> s{a, b, c};
  std::sort(s.begin(), s.end(), std::greater<double>());
  const double x = s[0], y = s[1], z = s[2];
  const double product = (x + (y + z)) * (z - (x - y)) * (z + (x - y)) * (x + (y - z));
  return 0.5 * std::sqrt(std::max(product, 0.0));
}

// Corner 2 of a triangle laid out with corner 0 at the origin and corner 1 at (side0, 0).
Eigen::Vector2d third_corner(double side0, double side1, double side2) {
  const double x = (side0 * side0 + side2 * side2 - side1 * side1) / (2 * side0);
  return {x, std::sqrt(std::max(side2 * side2 - x * x, 0.0))};
}

} // namespace

IntrinsicDelaunay::IntrinsicDelaunay(const Mesh &mesh, const MeshEdges &mesh_edges)
    : edges_(mesh_edges), mesh_edge_count_(mesh_edges.edge_count()) {
  const int edge_count = edges_.edge_count();
  corners_.resize(mesh.face.size());
  for (size_t f = 0; f < mesh.face.size(); ++f)
    for (int k = 0; k < 3; ++k)
      corners_[f][k] = index_of(mesh, mesh.face[f].cV(k));
  lengths_.resize(size_t(edge_count));
  version_.resize(size_t(edge_count));
  for (int e = 0; e < edge_count; ++e) {
    lengths_[size_t(e)] = (mesh.vert[size_t(edges_.vertices[e][0])].cP() -
                           mesh.vert[size_t(edges_.vertices[e][1])].cP())
                              .Norm();
    version_[size_t(e)] = e;
  }
  next_version_ = edge_count;

  // Flip until Delaunay: every flip shrinks a bounded energy, so this ends (O(n) flips in
  // practice); the four sides of a flipped quad are looked at again.
  std::vector<int> stack(static_cast<size_t>(edge_count));
  std::vector<char> queued(size_t(edge_count), 1);
  for (int e = 0; e < edge_count; ++e)
    stack[size_t(e)] = edge_count - 1 - e;
  while (!stack.empty()) {
    const int e = stack.back();
    stack.pop_back();
    queued[size_t(e)] = 0;
    if (!flip_if_not_delaunay(e)) continue;
    for (int f : edges_.faces[size_t(e)])
      for (int side : edges_.face_edges[size_t(f)])
        if (side != e && !queued[size_t(side)]) {
          queued[size_t(side)] = 1;
          stack.push_back(side);
        }
  }
}

bool IntrinsicDelaunay::flip_if_not_delaunay(int e) {
  const int left = edges_.faces[size_t(e)][0], right = edges_.faces[size_t(e)][1];
  if (left == right) return false;
  const auto side_in = [&](int face) {
    for (int k = 0; k < 3; ++k)
      if (edges_.face_edges[size_t(face)][k] == e) return k;
    return -1;
  };
  const int kl = side_in(left), kr = side_in(right);
  // Left face (a, b, c) traverses e from a to b, right face (b, a, d) from b to a.
  const int a = corners_[size_t(left)][kl], b = corners_[size_t(left)][(kl + 1) % 3];
  const int c = corners_[size_t(left)][(kl + 2) % 3], d = corners_[size_t(right)][(kr + 2) % 3];
  if (c == d) return false;
  const int bc = edges_.face_edges[size_t(left)][(kl + 1) % 3];
  const int ca = edges_.face_edges[size_t(left)][(kl + 2) % 3];
  const int ad = edges_.face_edges[size_t(right)][(kr + 1) % 3];
  const int db = edges_.face_edges[size_t(right)][(kr + 2) % 3];
  const double l_ab = lengths_[size_t(e)], l_bc = lengths_[size_t(bc)], l_ca = lengths_[size_t(ca)];
  const double l_ad = lengths_[size_t(ad)], l_db = lengths_[size_t(db)];
  const double at_c = opposite_angle(l_ab, l_bc, l_ca), at_d = opposite_angle(l_ab, l_ad, l_db);
  if (at_c + at_d <= M_PI * (1 + 1e-12)) return false;

  // The new edge c -> d, from the two triangles laid out on either side of a -> b.
  const Eigen::Vector2d pc = third_corner(l_ab, l_bc, l_ca);
  Eigen::Vector2d pd = third_corner(l_ab, l_db, l_ad);
  pd.y() = -pd.y();
  const double l_cd = (pc - pd).norm();
  if (!(l_cd > 0)) return false;

  // The old edge a -> b is the path a -> c -> b of its left triangle.
  const auto sign_along = [&](int edge, int from) {
    return edges_.vertices[size_t(edge)][0] == from ? 1.0 : -1.0;
  };
  retired_.push_back(Retired{version_[size_t(e)],
                             {version_[size_t(ca)], version_[size_t(bc)]},
                             {sign_along(ca, a), sign_along(bc, c)}});
  version_[size_t(e)] = next_version_++;

  // Faces after the flip: left = (c, a, d), right = (d, b, c); the new edge runs c -> d, so the
  // right face traverses it forwards.
  corners_[size_t(left)] = {c, a, d};
  corners_[size_t(right)] = {d, b, c};
  edges_.face_edges[size_t(left)] = {ca, ad, e};
  edges_.face_edges[size_t(right)] = {db, bc, e};
  edges_.vertices[size_t(e)] = {c, d};
  edges_.faces[size_t(e)] = {right, left};
  lengths_[size_t(e)] = l_cd;
  for (int moved : {ad, bc}) {
    const int from = moved == ad ? right : left, to = moved == ad ? left : right;
    for (int &face : edges_.faces[size_t(moved)])
      if (face == from) face = to;
  }
  for (int face : {left, right})
    for (int k = 0; k < 3; ++k)
      edges_.face_signs[size_t(face)][k] = static_cast<signed char>(
          sign_along(edges_.face_edges[size_t(face)][k], corners_[size_t(face)][k]));
  return true;
}

FaceCorners IntrinsicDelaunay::laid_out_flat() const {
  FaceCorners flat(corners_.size());
  for (size_t f = 0; f < corners_.size(); ++f) {
    const auto &side = edges_.face_edges[f];
    const double l0 = lengths_[size_t(side[0])], l1 = lengths_[size_t(side[1])],
                 l2 = lengths_[size_t(side[2])];
    const Eigen::Vector2d apex = third_corner(l0, l1, l2);
    flat[f] = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(l0, 0, 0),
               Eigen::Vector3d(apex.x(), apex.y(), 0)};
  }
  return flat;
}

std::vector<double> IntrinsicDelaunay::cotan_weights() const {
  std::vector<double> weights(size_t(edges_.edge_count()), 0.0);
  for (size_t f = 0; f < corners_.size(); ++f) {
    const auto &side = edges_.face_edges[f];
    const double l[3] = {lengths_[size_t(side[0])], lengths_[size_t(side[1])],
                         lengths_[size_t(side[2])]};
    const double area2 = double_area(l[0], l[1], l[2]);
    if (!(area2 > 0)) continue;
    for (int k = 0; k < 3; ++k) {
      // cot of the angle opposite side k = (b^2 + c^2 - a^2) / (4 area).
      const double a = l[k], b = l[(k + 1) % 3], c = l[(k + 2) % 3];
      weights[size_t(side[k])] += 0.5 * (b * b + c * c - a * a) / (2 * area2);
    }
  }
  return weights;
}

Eigen::VectorXcd IntrinsicDelaunay::integrate_along_mesh_edges(const Eigen::VectorXcd &form) const {
  std::vector<std::complex<double>> value(static_cast<size_t>(next_version_));
  for (int e = 0; e < edges_.edge_count(); ++e)
    value[size_t(version_[size_t(e)])] = form[e];
  for (auto r = retired_.rbegin(); r != retired_.rend(); ++r)
    value[size_t(r->version)] =
        r->signs[0] * value[size_t(r->sides[0])] + r->signs[1] * value[size_t(r->sides[1])];
  Eigen::VectorXcd out(mesh_edge_count_);
  for (int e = 0; e < mesh_edge_count_; ++e)
    out[e] = value[size_t(e)];
  return out;
}

PreparedMesh prepared_on_intrinsic_delaunay(const PreparedMesh &prepared) {
  const IntrinsicDelaunay intrinsic(prepared.mesh, prepared.edges);
  std::vector<double> weights = intrinsic.cotan_weights();
  for (double &weight : weights)
    weight = std::max(weight, 0.0);
  IndexLists at_vertex = edges_at_vertices(intrinsic.edges(), int(prepared.mesh.vert.size()));
  return PreparedMesh{prepared.mesh,        intrinsic.edges(),    std::move(weights),
                      prepared.incidence,   std::move(at_vertex), prepared.geometry,
                      prepared.vertex_areas};
}

} // namespace meromorph
