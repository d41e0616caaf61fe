#include "maps/form_pairs.h"

#include <cmath>
#include <complex>
#include <random>

namespace meromorph {

std::vector<FormPair> generic_form_pairs(int genus) {
  using Complex = std::complex<double>;
  constexpr int random_pairs = 4;
  std::vector<FormPair> pairs(2 + random_pairs, {Eigen::VectorXcd(genus), Eigen::VectorXcd(genus)});
  std::mt19937 generator(20070101); // mt19937's sequence is fixed by the standard
  auto unit = [&] { return std::polar(1.0, 2 * M_PI * double(generator()) / 4294967296.0); };
  for (int k = 0; k < genus; ++k) {
    pairs[0].first[k] = std::polar(1.0, 2 * M_PI * k / genus);
    pairs[0].second[k] = std::polar(1.0, 4 * M_PI * k / genus + 0.7);
    pairs[1].first[k] = 1.0;
    pairs[1].second[k] = Complex(double(k + 1) / (genus + 1));
  }
  for (int pair = 2; pair < 2 + random_pairs; ++pair)
    for (int k = 0; k < genus; ++k) {
      pairs[size_t(pair)].first[k] = unit();
      pairs[size_t(pair)].second[k] = unit();
    }
  return pairs;
}

} // namespace meromorph
