#include "match/sheet_following.h"

#include <limits>
#include <queue>
#include <utility>

namespace meromorph {

namespace {

// How far apart a vertex's candidates are: its sheets told apart that clearly.
double separation(const std::vector<Eigen::Vector3d> &candidates) {
  double largest = 0;
  for (size_t i = 0; i < candidates.size(); ++i)
    for (size_t j = i + 1; j < candidates.size(); ++j)
      largest = std::max(largest, (candidates[i] - candidates[j]).norm());
  return largest;
}

} // namespace

std::vector<int> follow_sheets(const std::vector<std::vector<Eigen::Vector3d>> &candidates,
                               const std::vector<std::vector<int>> &neighbours, int seed,
                               int seed_choice) {
  std::vector<int> chosen(candidates.size(), -1);
  if (seed < 0 || size_t(seed_choice) >= candidates[size_t(seed)].size()) return chosen;
  // Clearest first: the vertex whose candidates are farthest apart among those next to a decided
  // one is decided next, by the mean of its decided neighbours' choices. Near a branch point,
  // where the sheets meet and one neighbour's choice could mislead, vertices come last, with all
  // their neighbours around them decided.
  std::vector<char> decided(candidates.size(), 0);
  std::priority_queue<std::pair<double, int>> frontier;
  const auto decide = [&](int v, int choice) {
    chosen[size_t(v)] = choice;
    decided[size_t(v)] = 1;
    for (int u : neighbours[size_t(v)])
      if (!decided[size_t(u)] && !candidates[size_t(u)].empty())
        frontier.push({separation(candidates[size_t(u)]), u});
  };
  decide(seed, seed_choice);
  while (!frontier.empty()) {
    const int u = frontier.top().second;
    frontier.pop();
    if (decided[size_t(u)]) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    int count = 0;
    for (int w : neighbours[size_t(u)])
      if (decided[size_t(w)] && chosen[size_t(w)] >= 0)
        mean += candidates[size_t(w)][size_t(chosen[size_t(w)])], ++count;
    mean /= std::max(count, 1);
    int best = -1;
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < candidates[size_t(u)].size(); ++k) {
      const double d = (candidates[size_t(u)][k] - mean).squaredNorm();
      if (d < nearest) nearest = d, best = int(k);
    }
    decide(u, best);
  }
  return chosen;
}

} // namespace meromorph
