#include "maps/form_pairs.h"

#include <cmath>
#include <complex>
#include <random>

#include "common/parallel_for.h"

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

std::array<Eigen::VectorXcd, 2> ratio_forms(const FormPair &pair,
                                            const std::vector<Eigen::VectorXcd> &normalized) {
  const Eigen::VectorXcd top = pair.first + pair.second, bottom = pair.first - pair.second;
  const long edge_count = normalized.front().size();
  std::array<Eigen::VectorXcd, 2> out{Eigen::VectorXcd(edge_count), Eigen::VectorXcd(edge_count)};
  parallel_for(size_t(edge_count), [&](size_t e) {
    std::complex<double> numerator = 0, denominator = 0;
    for (size_t k = 0; k < normalized.size(); ++k) {
      numerator += top[long(k)] * normalized[k][long(e)];
      denominator += bottom[long(k)] * normalized[k][long(e)];
    }
    out[0][long(e)] = numerator;
    out[1][long(e)] = denominator;
  });
  return out;
}

std::array<std::vector<std::complex<double>>, 2> ratio_dz(const FormPair &pair,
                                                          const Eigen::MatrixXcd &normalized_dz) {
  const Eigen::VectorXcd top = pair.first + pair.second, bottom = pair.first - pair.second;
  const size_t face_count = size_t(normalized_dz.cols());
  std::array<std::vector<std::complex<double>>, 2> out{
      std::vector<std::complex<double>>(face_count), std::vector<std::complex<double>>(face_count)};
  parallel_for(face_count, [&](size_t f) {
    std::complex<double> numerator = 0, denominator = 0;
    for (long k = 0; k < normalized_dz.rows(); ++k) {
      numerator += top[k] * normalized_dz(k, long(f));
      denominator += bottom[k] * normalized_dz(k, long(f));
    }
    out[0][f] = numerator;
    out[1][f] = denominator;
  });
  return out;
}

} // namespace meromorph
