#include "branch_star.h"

#include <algorithm>
#include <utility>

namespace meromorph {

std::vector<int> ordered_ring(const FaceIncidence &in, int vertex) {
  std::vector<std::pair<int, int>> next; // (a, b) for each face (vertex, a, b)
  for (int f : in.faces_of_vertex[size_t(vertex)]) {
    const auto &corners = in.corners[size_t(f)];
    const int k = int(std::find(corners.begin(), corners.end(), vertex) - corners.begin());
    next.push_back({corners[size_t((k + 1) % 3)], corners[size_t((k + 2) % 3)]});
  }
  if (next.empty()) return {};
  std::vector<int> ring{next.front().first};
  while (ring.size() <= next.size()) {
    auto step = std::find_if(next.begin(), next.end(),
                             [&](const std::pair<int, int> &n) { return n.first == ring.back(); });
    if (step == next.end()) return {};
    if (step->second == ring.front()) break;
    ring.push_back(step->second);
  }
  return ring.size() == next.size() ? ring : std::vector<int>{};
}

} // namespace meromorph
