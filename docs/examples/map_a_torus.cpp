// Map a torus onto the sphere with the C++ API on arrays (job/surface_map.h).
#include <cmath>
#include <cstdio>

#include <Eigen/Core>

#include "job/surface_map.h"

int main() {
  const int around = 48, tube = 24;
  Eigen::MatrixXd V(around * tube, 3);     // vertex positions, one row each
  Eigen::MatrixXi F(2 * around * tube, 3); // triangles, counter-clockwise from outside
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) { // radii 2 and 1
      const double u = 2 * M_PI * i / around, v = 2 * M_PI * j / tube;
      const int k = i * tube + j, b = ((i + 1) % around) * tube + j,
                c = ((i + 1) % around) * tube + (j + 1) % tube, d = i * tube + (j + 1) % tube;
      V.row(k) << (2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v);
      F.row(2 * k) << k, b, c;
      F.row(2 * k + 1) << k, c, d;
    }
  meromorph::ParameterizeOptions options; // the defaults: spherical uvs, Moebius-centred
  const meromorph::Parameterization map = meromorph::parameterize_arrays(V, F, options);
  // map.sphere[k]: vertex k on the unit sphere; map.uv.vertex[k]: its texture coordinates;
  // map.sheets.vertex_layer[k]: its layer; map.branch_points: vertex and local degree.
  std::printf("genus %d, degree %d, %zu branch points, valid: %s\n", map.genus, map.degree,
              map.branch_points.size(), map.valid ? "yes" : "no");
  return map.valid && map.degree == 2 ? 0 : 1;
}
