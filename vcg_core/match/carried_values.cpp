#include "match/carried_values.h"

#include <algorithm>
#include <cmath>

namespace meromorph {

std::vector<VertexValues> carried_values(const std::vector<VertexValues> &target_values,
                                         const std::vector<std::array<int, 3>> &target_triangles,
                                         const MatchedPoints &points) {
  std::vector<VertexValues> out;
  const size_t n = points.target_face.size();
  for (const VertexValues &from : target_values) {
    VertexValues to{from.name, from.integer, from.byte, std::vector<double>(n, 0.0)};
    for (size_t v = 0; v < n; ++v) {
      const int face = points.target_face[v];
      if (face < 0) continue;
      const auto &corners = target_triangles[size_t(face)];
      const double w[3] = {1 - points.weights[v][0] - points.weights[v][1], points.weights[v][0],
                           points.weights[v][1]};
      if (from.integer && !from.byte) {
        const int nearest = int(std::max_element(w, w + 3) - w);
        to.values[v] = from.values[size_t(corners[size_t(nearest)])];
        continue;
      }
      double value = 0;
      for (int k = 0; k < 3; ++k)
        value += w[k] * from.values[size_t(corners[size_t(k)])];
      to.values[v] = from.byte ? std::clamp(std::round(value), 0.0, 255.0) : value;
    }
    out.push_back(std::move(to));
  }
  return out;
}

} // namespace meromorph
