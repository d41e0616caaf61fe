#include "remesh/sample_coverage.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace meromorph {
namespace {

int root(std::vector<int> &parent, int f) {
  while (parent[f] != f)
    f = parent[f] = parent[parent[f]];
  return f;
}

} // namespace

std::vector<SparseRegion> sparsely_sampled_regions(const Mesh &mesh,
                                                   const std::vector<double> &shares,
                                                   double sparse_below, double min_area_share) {
  const int count = int(mesh.face.size());
  std::vector<int> parent(count);
  std::iota(parent.begin(), parent.end(), 0);
  std::map<std::pair<int, int>, int> side_owner; // a sparse face on each side
  std::vector<double> area(count);
  double total_area = 0;
  for (int f = 0; f < count; ++f) {
    area[f] = vcg::DoubleArea(mesh.face[f]) / 2;
    total_area += area[f];
    if (!(shares[f] < sparse_below)) continue;
    for (int k = 0; k < 3; ++k) {
      int a = index_of(mesh, mesh.face[f].cV(k)), b = index_of(mesh, mesh.face[f].cV((k + 1) % 3));
      if (a > b) std::swap(a, b);
      auto [slot, added] = side_owner.try_emplace({a, b}, f);
      if (!added) parent[root(parent, f)] = root(parent, slot->second);
    }
  }
  std::map<int, SparseRegion> regions;
  std::map<int, double> sparsest;
  for (int f = 0; f < count; ++f) {
    if (!(shares[f] < sparse_below)) continue;
    const int r = root(parent, f);
    SparseRegion &region = regions[r];
    ++region.faces;
    region.area_share += area[f];
    region.sample_share += shares[f] * area[f];
    auto [slot, added] = sparsest.try_emplace(r, shares[f]);
    if (added || shares[f] <= slot->second) {
      slot->second = shares[f];
      region.vertex = index_of(mesh, mesh.face[f].cV(0));
    }
  }
  std::vector<SparseRegion> out;
  for (auto &[r, region] : regions) {
    if (region.area_share > 0) region.sample_share /= region.area_share;
    region.area_share /= std::max(total_area, 1e-300);
    if (region.area_share >= min_area_share) out.push_back(region);
  }
  std::sort(out.begin(), out.end(), [](const SparseRegion &a, const SparseRegion &b) {
    return a.area_share > b.area_share;
  });
  return out;
}

} // namespace meromorph
