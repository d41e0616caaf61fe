#include "mesh/edge_splitting.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace meromorph {
namespace {

uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(uint32_t(a)) << 32) | uint32_t(b);
}

// The pieces of triangle (a, b, c) whose edges ab, bc, ca are cut at m[0], m[1], m[2] (-1: not
// cut), the first at corner a.
std::vector<std::array<int, 3>> pieces(const std::array<int, 3> &corner,
                                       const std::array<int, 3> &m,
                                       const std::vector<Point3> &positions) {
  const int cuts = (m[0] >= 0) + (m[1] >= 0) + (m[2] >= 0);
  const int a = corner[0], b = corner[1], c = corner[2];
  if (cuts == 3) return {{a, m[0], m[2]}, {m[0], b, m[1]}, {m[2], m[1], c}, {m[0], m[1], m[2]}};
  if (cuts == 1) {
    if (m[0] >= 0) return {{a, m[0], c}, {m[0], b, c}};
    if (m[1] >= 0) return {{a, b, m[1]}, {a, m[1], c}};
    return {{a, b, m[2]}, {m[2], b, c}};
  }
  // Two cuts: the corner between them is cut off; the quadrilateral left by its shorter diagonal.
  const int uncut = m[0] < 0 ? 0 : m[1] < 0 ? 1 : 2;
  const int p = corner[size_t(uncut)], q = corner[size_t((uncut + 1) % 3)],
            r = corner[size_t((uncut + 2) % 3)];
  const int mq = m[size_t((uncut + 1) % 3)], mr = m[size_t((uncut + 2) % 3)]; // on qr and rp
  std::vector<std::array<int, 3>> out{{mq, r, mr}};
  if ((positions[size_t(p)] - positions[size_t(mq)]).SquaredNorm() <=
      (positions[size_t(q)] - positions[size_t(mr)]).SquaredNorm())
    out.insert(out.end(), {{p, q, mq}, {p, mq, mr}});
  else
    out.insert(out.end(), {{p, q, mr}, {q, mq, mr}});
  // The piece at the first corner goes first.
  std::rotate(out.begin(),
              std::find_if(out.begin(), out.end(),
                           [&](const std::array<int, 3> &t) {
                             return std::count(t.begin(), t.end(), a) > 0;
                           }),
              out.end());
  return out;
}

} // namespace

SplitEdges split_edges(const MeshArrays &arrays, const std::vector<std::array<int, 2>> &edges) {
  std::unordered_map<uint64_t, int> chosen; // edge -> midpoint vertex (-1 until made)
  for (const auto &e : edges)
    chosen.emplace(edge_key(e[0], e[1]), -1);
  SplitEdges out;
  out.arrays.positions = arrays.positions;
  out.arrays.triangles = arrays.triangles;
  out.face_source.resize(arrays.triangles.size());
  for (size_t f = 0; f < arrays.triangles.size(); ++f)
    out.face_source[f] = int(f);
  for (size_t f = 0; f < arrays.triangles.size(); ++f) {
    const std::array<int, 3> corner = arrays.triangles[f];
    std::array<int, 3> m{-1, -1, -1};
    for (int k = 0; k < 3; ++k) {
      const int u = corner[size_t(k)], v = corner[size_t((k + 1) % 3)];
      const auto it = u == v ? chosen.end() : chosen.find(edge_key(u, v));
      if (it == chosen.end()) continue;
      if (it->second < 0) {
        it->second = int(out.arrays.positions.size());
        out.arrays.positions.push_back((arrays.positions[size_t(u)] + arrays.positions[size_t(v)]) *
                                       0.5);
      }
      m[size_t(k)] = it->second;
    }
    if (m == std::array<int, 3>{-1, -1, -1}) continue;
    const auto cut = pieces(corner, m, out.arrays.positions);
    out.arrays.triangles[f] = cut.front();
    for (size_t k = 1; k < cut.size(); ++k) {
      out.arrays.triangles.push_back(cut[k]);
      out.face_source.push_back(int(f));
    }
  }
  return out;
}

void cut_sides(SplitEdges &refined, const std::vector<std::array<int, 2>> &sides) {
  SplitEdges finer = split_edges(refined.arrays, sides);
  for (int &source : finer.face_source)
    source = refined.face_source[size_t(source)];
  refined = std::move(finer);
}

std::optional<SplitEdges> split_long_edges(const MeshArrays &arrays, double max_length,
                                           size_t face_budget) {
  const auto &p = arrays.positions;
  // About how many faces it makes: each face its area over an even triangle's of side
  // max_length, or at least its longest side over max_length; beyond the budget, none is cut.
  double estimate = 0;
  for (const auto &t : arrays.triangles) {
    const Point3 a = p[size_t(t[0])], b = p[size_t(t[1])], c = p[size_t(t[2])];
    const double longest = std::max({(b - a).Norm(), (c - b).Norm(), (a - c).Norm()});
    estimate += std::max(((b - a) ^ (c - a)).Norm() / 2 / (0.433 * max_length * max_length),
                         longest / max_length);
  }
  if (!(estimate <= double(face_budget))) return std::nullopt;
  SplitEdges out = split_edges(arrays, {}); // nothing cut yet: each face its own source
  const double squared = max_length * max_length;
  for (;;) {
    std::vector<std::array<int, 2>> sides;
    for (const auto &t : out.arrays.triangles)
      for (int k = 0; k < 3; ++k) {
        const int u = t[size_t(k)], v = t[size_t((k + 1) % 3)];
        if ((out.arrays.positions[size_t(u)] - out.arrays.positions[size_t(v)]).SquaredNorm() >
            squared)
          sides.push_back({u, v});
      }
    if (sides.empty()) return out;
    // A cut side adds a face to each face on it.
    if (out.arrays.triangles.size() + sides.size() > face_budget) return std::nullopt;
    cut_sides(out, sides);
  }
}

} // namespace meromorph
