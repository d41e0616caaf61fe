/* Map a torus onto the sphere through the C library (libmeromorph.so, meromorph.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "meromorph.h"

int main(void) {
  enum { AROUND = 48, TUBE = 24, V = AROUND * TUBE, F = 2 * V };
  double *xyz = malloc(sizeof(double) * 3 * V);
  int32_t *triangles = malloc(sizeof(int32_t) * 3 * F);
  for (int i = 0; i < AROUND; ++i)
    for (int j = 0; j < TUBE; ++j) { /* radii 2 and 1 */
      const double u = 2 * M_PI * i / AROUND, v = 2 * M_PI * j / TUBE;
      const int k = i * TUBE + j, a = k, b = ((i + 1) % AROUND) * TUBE + j,
                c = ((i + 1) % AROUND) * TUBE + (j + 1) % TUBE, d = i * TUBE + (j + 1) % TUBE;
      xyz[3 * k] = (2 + cos(v)) * cos(u);
      xyz[3 * k + 1] = (2 + cos(v)) * sin(u);
      xyz[3 * k + 2] = sin(v);
      int32_t *t = triangles + 6 * k; /* two triangles per quad, counter-clockwise from outside */
      t[0] = a, t[1] = b, t[2] = c, t[3] = a, t[4] = c, t[5] = d;
    }
  meromorph_options options;
  meromorph_default_options(&options);
  meromorph_result *result = NULL;
  if (meromorph_parameterize_d(xyz, V, triangles, F, &options, &result) != MEROMORPH_OK) {
    fprintf(stderr, "cannot map: %s\n", meromorph_last_error());
    return 1;
  }
  /* The surface as written: the input's vertices, then any the map needed added. */
  double *sphere = malloc(sizeof(double) * 3 * meromorph_vertex_count(result));
  meromorph_sphere_positions(result, sphere); /* vertex k on the unit sphere: sphere[3k..3k+2] */
  printf("genus %d, degree %d, %zu branch points, valid: %s\n", meromorph_genus(result),
         meromorph_degree(result), meromorph_branch_point_count(result),
         meromorph_map_valid(result) ? "yes" : "no");
  const int ok = meromorph_map_valid(result) && meromorph_degree(result) == 2;
  meromorph_result_free(result);
  free(xyz), free(sphere), free(triangles);
  return ok ? 0 : 1;
}
