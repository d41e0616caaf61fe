/* The C ABI from plain C99: a torus of revolution, and every kind of misuse. Exits non-zero on
 * the first failed check; prints "N passed, 0 failed" at the end. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "meromorph.h"

static int passed = 0;

#define CHECK(condition)                                                                           \
  do {                                                                                             \
    if (!(condition)) {                                                                            \
      printf("FAILED line %d: %s (last error: %s)\n", __LINE__, #condition,                        \
             meromorph_last_error());                                                              \
      printf("%d passed, 1 failed\n", passed);                                                     \
      exit(1);                                                                                     \
    }                                                                                              \
    ++passed;                                                                                      \
  } while (0)

enum { MAJOR = 48, MINOR = 24, V = MAJOR * MINOR, F = 2 * V };
static double positions[3 * V];
static int32_t triangles[3 * F];

/* A torus of revolution with radii 2 and 1 on a major x minor grid: 3 doubles per vertex, two
   triangles per grid cell. */
static void fill_torus(int major, int minor, double *p, int32_t *t) {
  const double pi = 3.14159265358979323846;
  int i, j;
  for (i = 0; i < major; ++i)
    for (j = 0; j < minor; ++j) {
      const double u = 2 * pi * i / major, v = 2 * pi * j / minor, ring = 2.0 + cos(v);
      double *q = p + 3 * (i * minor + j);
      const int32_t a = i * minor + j, b = ((i + 1) % major) * minor + j;
      const int32_t c = ((i + 1) % major) * minor + (j + 1) % minor,
                    d = i * minor + (j + 1) % minor;
      int32_t *f = t + 6 * a;
      q[0] = ring * cos(u);
      q[1] = ring * sin(u);
      q[2] = sin(v);
      f[0] = a;
      f[1] = b;
      f[2] = c;
      f[3] = a;
      f[4] = c;
      f[5] = d;
    }
}

static void make_torus(void) {
  fill_torus(MAJOR, MINOR, positions, triangles);
}

/* A washer as a CAD program exports it (outer radius 10, inner 6, height 2, 32 segments): each
   cylinder and each annulus a strip of two long triangles per segment. Its triangles cannot
   carry a map to the sphere without turning some over. */
enum { WASHER_SEGMENTS = 32, WASHER_V = 4 * WASHER_SEGMENTS, WASHER_F = 8 * WASHER_SEGMENTS };
static void fill_washer(double *p, int32_t *t) {
  const double pi = 3.14159265358979323846, radius[4] = {10, 10, 6, 6}, z[4] = {0, 2, 0, 2};
  const int n = WASHER_SEGMENTS;
  int ring, i;
  for (ring = 0; ring < 4; ++ring) /* outer bottom, outer top, inner bottom, inner top */
    for (i = 0; i < n; ++i) {
      double *q = p + 3 * (ring * n + i);
      q[0] = radius[ring] * cos(2 * pi * i / n);
      q[1] = radius[ring] * sin(2 * pi * i / n);
      q[2] = z[ring];
    }
  for (i = 0; i < n; ++i) {
    const int32_t j = (i + 1) % n, ob = 0, ot = n, ib = 2 * n, it = 3 * n;
    const int32_t faces[8][3] = {{ob + i, ob + j, ot + j}, {ob + i, ot + j, ot + i},
                                 {ib + i, it + j, ib + j}, {ib + i, it + i, it + j},
                                 {ot + i, ot + j, it + j}, {ot + i, it + j, it + i},
                                 {ob + i, ib + j, ob + j}, {ob + i, ib + i, ib + j}};
    memcpy(t + 24 * i, faces, sizeof(faces));
  }
}

/* Four threads map tori of different sizes at once; each checks its own result. */
typedef struct job {
  int major, minor, ok;
} job;

static void *map_torus_in_thread(void *argument) {
  job *work = (job *)argument;
  const int n = work->major * work->minor;
  double *p = malloc(sizeof(double) * 3 * (size_t)n);
  int32_t *t = malloc(sizeof(int32_t) * 6 * (size_t)n);
  meromorph_result *r = NULL;
  fill_torus(work->major, work->minor, p, t);
  work->ok = meromorph_parameterize_d(p, (size_t)n, t, 2 * (size_t)n, NULL, &r) == MEROMORPH_OK &&
             meromorph_degree(r) == 2 && meromorph_vertex_count(r) == (size_t)n &&
             meromorph_branch_point_count(r) == 4;
  meromorph_result_free(r);
  free(p);
  free(t);
  return NULL;
}

/* Called every quarter second and at the end: a job shorter than that is cancelled at its end. */
static int calls = 0;
static int cancel_at_first_call(double fraction, const char *stage, void *user) {
  (void)fraction;
  (void)stage;
  (void)user;
  ++calls;
  return 0;
}

int main(void) {
  meromorph_options options;
  meromorph_result *result = NULL;
  double *sphere, *uv, *corners;
  int32_t *layers, branch_vertices[8], branch_degrees[8];
  meromorph_distortion distortion;
  size_t v, branch_count;
  float *float_positions;

  CHECK(meromorph_abi_version() == MEROMORPH_ABI_VERSION);
  CHECK(strlen(meromorph_version()) > 0);
  make_torus();
  meromorph_default_options(&options);
  options.layer_gap = 0.5;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) == MEROMORPH_OK);
  CHECK(result != NULL);
  CHECK(meromorph_genus(result) == 1);
  CHECK(meromorph_degree(result) == 2);
  CHECK(meromorph_riemann_hurwitz_ok(result) == 1);
  CHECK(meromorph_map_valid(result) == 1);
  CHECK(meromorph_invalid_reasons(result) != NULL && meromorph_invalid_reasons(result)[0] == '\0');
  CHECK(meromorph_map_valid(NULL) == 0 && meromorph_invalid_reasons(NULL) != NULL);
  CHECK(meromorph_advice(result) != NULL && meromorph_advice(result)[0] == '\0');
  CHECK(meromorph_advice(NULL) != NULL);
  CHECK(meromorph_advice_count(result) == 0 && meromorph_advice_count(NULL) == 0);
  CHECK(meromorph_advice_cause(result, 0)[0] == '\0' && meromorph_advice_remedy(result, 0) == 0);
  CHECK(meromorph_advice_cause(NULL, -1)[0] == '\0' && meromorph_advice_remedy(NULL, 3) == 0);
  CHECK(meromorph_vertex_count(result) == V);
  CHECK(meromorph_triangle_count(result) == F);

  sphere = malloc(sizeof(double) * 3 * V);
  uv = malloc(sizeof(double) * 2 * V);
  corners = malloc(sizeof(double) * 6 * F);
  layers = malloc(sizeof(int32_t) * V);
  CHECK(meromorph_sphere_positions(result, sphere) == MEROMORPH_OK);
  for (v = 0; v < V; ++v)
    CHECK(fabs(sqrt(sphere[3 * v] * sphere[3 * v] + sphere[3 * v + 1] * sphere[3 * v + 1] +
                    sphere[3 * v + 2] * sphere[3 * v + 2]) -
               1.0) < 1e-9);
  CHECK(meromorph_vertex_uvs(result, uv) == MEROMORPH_OK);
  for (v = 0; v < V; ++v)
    CHECK(uv[2 * v] >= 0 && uv[2 * v] <= 1 && uv[2 * v + 1] >= 0 && uv[2 * v + 1] <= 1);
  CHECK(meromorph_corner_uvs(result, corners) == MEROMORPH_OK);
  CHECK(meromorph_layers(result, layers) == MEROMORPH_OK);
  for (v = 0; v < V; ++v)
    CHECK(layers[v] == 0 || layers[v] == 1);
  CHECK(meromorph_layered_positions(result, sphere) == MEROMORPH_OK);
  for (v = 0; v < V; ++v) {
    const double r = sqrt(sphere[3 * v] * sphere[3 * v] + sphere[3 * v + 1] * sphere[3 * v + 1] +
                          sphere[3 * v + 2] * sphere[3 * v + 2]);
    CHECK(fabs(r - (1.0 + 0.5 * layers[v])) < 1e-9);
  }
  branch_count = meromorph_branch_point_count(result);
  CHECK(branch_count == 4);
  CHECK(meromorph_branch_points(result, branch_vertices, branch_degrees) == MEROMORPH_OK);
  for (v = 0; v < branch_count; ++v)
    CHECK(branch_degrees[v] == 2 && branch_vertices[v] < V);
  CHECK(meromorph_map_distortion(result, &distortion) == MEROMORPH_OK);
  CHECK(distortion.folded_faces_away_from_branch_points == 0);
  {
    /* The old name gives the same figures (kept for one release). */
    meromorph_distortion old_name;
    CHECK(meromorph_get_distortion(result, &old_name) == MEROMORPH_OK);
    CHECK(old_name.angle_error_mean_degrees == distortion.angle_error_mean_degrees);
  }
  CHECK(distortion.quasi_conformal_mean >= 1.0);
  {
    /* Away from the four branch points (where the map cannot be conformal): less distortion,
       the worst faces left out. */
    meromorph_distortion away;
    CHECK(meromorph_map_distortion_away_from_branch_points(result, &away) == MEROMORPH_OK);
    CHECK(away.folded_faces == 0 && away.folded_faces_away_from_branch_points == 0);
    CHECK(away.quasi_conformal_mean >= 1.0 &&
          away.quasi_conformal_mean < distortion.quasi_conformal_mean);
    CHECK(away.quasi_conformal_max < distortion.quasi_conformal_max);
    CHECK(meromorph_map_distortion_away_from_branch_points(NULL, &away) ==
          MEROMORPH_ERROR_ARGUMENT);
  }
  CHECK(strstr(meromorph_report_json(result), "\"degree\": 2") != NULL);
  meromorph_result_free(result);
  result = NULL;

  /* The same mesh in single precision, without options. */
  float_positions = malloc(sizeof(float) * 3 * V);
  for (v = 0; v < 3 * V; ++v)
    float_positions[v] = (float)positions[v];
  CHECK(meromorph_parameterize_f(float_positions, V, triangles, F, NULL, &result) == MEROMORPH_OK);
  CHECK(meromorph_degree(result) == 2);
  meromorph_result_free(result);
  result = NULL;

  /* Misuse: a clear status and message, never a crash. */
  CHECK(meromorph_parameterize_d(NULL, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  CHECK(strstr(meromorph_last_error(), "positions") != NULL);
  CHECK(meromorph_parameterize_d(positions, V, NULL, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, NULL) ==
        MEROMORPH_ERROR_ARGUMENT);
  CHECK(meromorph_parameterize_d(positions, V, triangles, 0, &options, &result) ==
        MEROMORPH_ERROR_INPUT);
  CHECK(strstr(meromorph_last_error(), "no faces") != NULL);
  CHECK(result == NULL);
  triangles[3 * 7 + 1] = V + 5;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_INPUT);
  CHECK(strstr(meromorph_last_error(), "face 7 refers to vertex") != NULL);
  triangles[3 * 7 + 1] = -1;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_INPUT);
  make_torus();
  /* By default holes are closed and non-manifold spots taken apart; strict refuses them. */
  CHECK(options.close_holes == 1 && options.split_nonmanifold == 1 && options.strict == 0);
  options.strict = 1;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F - 1, &options, &result) ==
        MEROMORPH_ERROR_INPUT);
  CHECK(strstr(meromorph_last_error(), "boundary loop") != NULL);
  /* The remedy as a code (the caller words it), the message naming no tool or option. */
  {
    int32_t remedies[4] = {0, 0, 0, 0};
    CHECK(meromorph_last_error_remedies(NULL, 0) == 1);
    CHECK(meromorph_last_error_remedies(remedies, 4) == 1);
    CHECK(remedies[0] == MEROMORPH_REMEDY_CLOSE_HOLES && remedies[1] == 0);
    CHECK(strstr(meromorph_last_error(), "--") == NULL);
    CHECK(strstr(meromorph_last_error(), "MeshLab") == NULL);
  }
  /* The same torus with one face missing: its hole closed for the computation only. */
  options.strict = 0;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F - 1, &options, &result) ==
        MEROMORPH_OK);
  CHECK(meromorph_vertex_count(result) == V && meromorph_triangle_count(result) == F - 1);
  CHECK(meromorph_genus(result) == 1 && meromorph_degree(result) == 2);
  CHECK(meromorph_map_valid(result) == 1);
  CHECK(strstr(meromorph_report_json(result), "holes_closed") != NULL);
  {
    static int32_t components[V];
    CHECK(meromorph_vertex_components(result, components) == MEROMORPH_OK);
    CHECK(components[0] == 0 && components[V - 1] == 0);
    CHECK(meromorph_vertex_components(result, NULL) == MEROMORPH_ERROR_ARGUMENT);
  }
  meromorph_result_free(result);
  result = NULL;
  options.close_holes = 2;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  CHECK(strstr(meromorph_last_error(), "close_holes") != NULL);
  /* The torus with a doubled face and a vertex on no face: both left out of the computation by
     default, the result still has every input vertex and triangle; strict refuses. */
  {
    static double p[3 * (V + 1)];
    static int32_t t[3 * (F + 1)];
    memcpy(p, positions, sizeof positions);
    p[3 * V] = p[3 * V + 1] = p[3 * V + 2] = 10.0;
    memcpy(t, triangles, sizeof triangles);
    memcpy(t + 3 * F, triangles + 3 * 5, 3 * sizeof(int32_t));
    meromorph_default_options(&options);
    CHECK(meromorph_parameterize_d(p, V + 1, t, F + 1, &options, &result) == MEROMORPH_OK);
    CHECK(meromorph_vertex_count(result) == V + 1 && meromorph_triangle_count(result) == F + 1);
    CHECK(meromorph_genus(result) == 1 && meromorph_degree(result) == 2);
    CHECK(meromorph_map_valid(result) == 1);
    CHECK(strstr(meromorph_report_json(result), "doubled face") != NULL);
    CHECK(strstr(meromorph_report_json(result), "on no face") != NULL);
    meromorph_result_free(result);
    result = NULL;
    options.strict = 1;
    CHECK(meromorph_parameterize_d(p, V + 1, t, F + 1, &options, &result) == MEROMORPH_ERROR_INPUT);
    CHECK(result == NULL);
  }
  /* Two tori touching at one vertex (a non-manifold vertex): refused when strict, naming the
     option; by default each is mapped on its own and the layered sphere gets a copy
     of the shared vertex. */
  {
    const size_t n = 2 * V - 1;
    const int32_t shared = (MAJOR / 2) * MINOR; /* (-3, 0, 0) on the first torus */
    double *p = malloc(sizeof(double) * 3 * n);
    int32_t *t = malloc(sizeof(int32_t) * 6 * F),
            *sphere_triangles = malloc(sizeof(int32_t) * 6 * F);
    int32_t *source = malloc(sizeof(int32_t) * (n + 1));
    size_t k, copies = 0;
    fill_torus(MAJOR, MINOR, p, t);
    fill_torus(MAJOR, MINOR, p + 3 * (V - 1), t + 3 * F);
    for (k = 0; k < (size_t)V; ++k) /* the second torus: its vertex 0 at (-3, 0, 0) */
      p[3 * (V - 1 + k)] -= 6.0;
    for (k = 3 * F; k < 6 * (size_t)F; ++k) /* its vertex k is the array's V - 1 + k; 0: shared */
      t[k] = t[k] == 0 ? shared : t[k] + V - 1;
    meromorph_default_options(&options);
    options.strict = 1;
    CHECK(meromorph_parameterize_d(p, n, t, 2 * F, &options, &result) == MEROMORPH_ERROR_INPUT);
    CHECK(strstr(meromorph_last_error(), "non-manifold") != NULL);
    {
      int32_t remedy = 0;
      CHECK(meromorph_last_error_remedies(&remedy, 1) >= 1);
      CHECK(remedy == MEROMORPH_REMEDY_SPLIT_NONMANIFOLD);
    }
    options.strict = 0;
    CHECK(meromorph_parameterize_d(p, n, t, 2 * F, &options, &result) == MEROMORPH_OK);
    CHECK(meromorph_vertex_count(result) == n && meromorph_sphere_vertex_count(result) == n + 1);
    CHECK(meromorph_genus(result) == 2 && meromorph_degree(result) == 4);
    CHECK(meromorph_map_valid(result) == 1);
    CHECK(meromorph_sphere_mesh(result, NULL, sphere_triangles, source, NULL, NULL, NULL) ==
          MEROMORPH_OK);
    CHECK(source[n] == shared);
    for (k = 0; k < 6 * (size_t)F; ++k) {
      CHECK(source[sphere_triangles[k]] == t[k]);
      copies += sphere_triangles[k] == (int32_t)n;
    }
    CHECK(copies == 6); /* the copy has the one fan of six triangles of one torus */
    CHECK(strstr(meromorph_report_json(result), "nonmanifold_split") != NULL);
    meromorph_result_free(result);
    result = NULL;
    options.split_nonmanifold = 3;
    CHECK(meromorph_parameterize_d(p, n, t, 2 * F, &options, &result) == MEROMORPH_ERROR_ARGUMENT);
    CHECK(strstr(meromorph_last_error(), "split_nonmanifold") != NULL);
    free(p);
    free(t);
    free(sphere_triangles);
    free(source);
  }
  /* Callers compiled against ABI version 1 (no close_holes) or 2 (no split_nonmanifold) are
     still served. */
  meromorph_default_options(&options);
  options.struct_size = offsetof(meromorph_options, split_nonmanifold);
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) == MEROMORPH_OK);
  meromorph_result_free(result);
  result = NULL;
  meromorph_default_options(&options);
  options.struct_size = offsetof(meromorph_options, close_holes);
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) == MEROMORPH_OK);
  meromorph_result_free(result);
  result = NULL;
  /* A caller of meromorph 0.1 (ABI 5 without area_correct): its struct is read up to pack_uv,
     whatever follows it in memory; area_correct 1 changes the report's area_correction. */
  meromorph_default_options(&options);
  options.struct_size = offsetof(meromorph_options, area_correct);
  options.area_correct = 7; /* beyond the old struct: never read */
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) == MEROMORPH_OK);
  CHECK(strstr(meromorph_report_json(result), "\"area_correction\"") == NULL);
  meromorph_result_free(result);
  result = NULL;
  meromorph_default_options(&options);
  options.area_correct = 1;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) == MEROMORPH_OK);
  CHECK(strstr(meromorph_report_json(result), "\"area_correction\"") != NULL);
  meromorph_result_free(result);
  result = NULL;
  options.area_correct = 2;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  CHECK(strstr(meromorph_last_error(), "area_correct") != NULL);
  meromorph_default_options(&options);
  options.origin_vertex = V + 100;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  CHECK(strstr(meromorph_last_error(), "origin_vertex") != NULL);
  options.origin_vertex = -2;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  meromorph_default_options(&options);
  options.pole_face = -3;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  CHECK(strstr(meromorph_last_error(), "pole_face") != NULL);
  options.pole_face = F;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  meromorph_default_options(&options);
  options.uv_kind = 7;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  CHECK(strstr(meromorph_last_error(), "uv_kind") != NULL);
  meromorph_default_options(&options);
  options.form_pair[1] = -9;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  meromorph_default_options(&options);
  options.layer_gap = NAN;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  CHECK(strstr(meromorph_last_error(), "layer_gap") != NULL);
  options.layer_gap = INFINITY;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  options.layer_gap = 1e308;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  options.layer_gap = -0.5;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  meromorph_default_options(&options);
  options.struct_size = 4;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  options.struct_size = 100000;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  CHECK(strstr(meromorph_last_error(), "struct_size") != NULL);
  meromorph_default_options(&options);
  CHECK(meromorph_parameterize_d(positions, (size_t)1 << 40, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_ARGUMENT);
  positions[3 * 17 + 2] = NAN;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_INPUT);
  CHECK(strstr(meromorph_last_error(), "vertices 17") != NULL);
  positions[3 * 17 + 2] = INFINITY;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_INPUT);
  CHECK(result == NULL);
  make_torus();
  CHECK(meromorph_corner_uvs(NULL, corners) == MEROMORPH_ERROR_ARGUMENT);
  CHECK(meromorph_get_distortion(NULL, &distortion) == MEROMORPH_ERROR_ARGUMENT);
  CHECK(meromorph_branch_points(NULL, branch_vertices, NULL) == MEROMORPH_ERROR_ARGUMENT);
  CHECK(meromorph_report_json(NULL) != NULL && meromorph_advice(NULL) != NULL);
  CHECK(meromorph_vertex_count(NULL) == 0 && meromorph_genus(NULL) == -1);
  meromorph_default_options(NULL);
  {
    pthread_t threads[4];
    job jobs[4] = {{40, 20, 0}, {44, 22, 0}, {48, 24, 0}, {52, 26, 0}};
    int k;
    for (k = 0; k < 4; ++k)
      CHECK(pthread_create(&threads[k], NULL, map_torus_in_thread, &jobs[k]) == 0);
    for (k = 0; k < 4; ++k)
      CHECK(pthread_join(threads[k], NULL) == 0);
    for (k = 0; k < 4; ++k)
      CHECK(jobs[k].ok);
  }
  meromorph_default_options(&options);
  options.progress = cancel_at_first_call;
  CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) ==
        MEROMORPH_ERROR_CANCELLED);
  CHECK(result == NULL && calls == 1);
  CHECK(meromorph_sphere_positions(NULL, sphere) == MEROMORPH_ERROR_ARGUMENT);
  CHECK(meromorph_degree(NULL) == -1);
  meromorph_result_free(NULL);

  free(sphere);
  free(uv);
  free(corners);
  free(layers);
  free(float_positions);
  /* Remeshing through the layered sphere: a closed surface of the same genus, about as many
     vertices as asked, every vertex on one of the two sheets and on the unit sphere. */
  {
    meromorph_remesh_result *remesh = NULL;
    size_t n, t, k;
    double *xyz, *values;
    int32_t *faces, *sheet, *degree;
    int ramification = 0;
    meromorph_default_options(&options);
    CHECK(meromorph_remesh_d(positions, V, triangles, F, &options, V, 2, &remesh) ==
          MEROMORPH_ERROR_ARGUMENT);
    CHECK(remesh == NULL && strstr(meromorph_last_error(), "area_correct") != NULL);
    /* Vertex targets beyond the command line's bound (or below 12) are refused before any work. */
    CHECK(meromorph_remesh_d(positions, V, triangles, F, &options, INT64_MAX, 1, &remesh) ==
          MEROMORPH_ERROR_ARGUMENT);
    CHECK(remesh == NULL && strstr(meromorph_last_error(), "target_vertices") != NULL);
    CHECK(meromorph_remesh_d(positions, V, triangles, F, &options, 2000000001, 1, &remesh) ==
          MEROMORPH_ERROR_ARGUMENT);
    CHECK(meromorph_remesh_d(positions, V, triangles, F, &options, 5, 1, &remesh) ==
          MEROMORPH_ERROR_ARGUMENT);
    CHECK(meromorph_remesh_d(positions, V, triangles, F, &options, 0, 1, &remesh) == MEROMORPH_OK);
    n = meromorph_remesh_vertex_count(remesh);
    t = meromorph_remesh_triangle_count(remesh);
    CHECK(n > 0.9 * V && n < 1.1 * V);
    CHECK(t == 2 * n); /* Euler characteristic 0 for a closed surface: V - 3F/2 + F = 0 */
    xyz = malloc(sizeof(double) * 3 * n);
    values = malloc(sizeof(double) * 3 * n);
    faces = malloc(sizeof(int32_t) * 3 * t);
    sheet = malloc(sizeof(int32_t) * n);
    degree = malloc(sizeof(int32_t) * n);
    CHECK(meromorph_remesh_mesh(remesh, xyz, faces, sheet, degree, values) == MEROMORPH_OK);
    CHECK(meromorph_remesh_mesh(remesh, NULL, NULL, NULL, NULL, NULL) == MEROMORPH_OK);
    for (k = 0; k < 3 * t; ++k)
      CHECK(faces[k] >= 0 && (size_t)faces[k] < n);
    for (k = 0; k < n; ++k) {
      CHECK(sheet[k] == 0 || sheet[k] == 1);
      CHECK(fabs(sqrt(values[3 * k] * values[3 * k] + values[3 * k + 1] * values[3 * k + 1] +
                      values[3 * k + 2] * values[3 * k + 2]) -
                 1.0) < 1e-9);
      if (degree[k] >= 2) ramification += degree[k] - 1;
    }
    CHECK(ramification == 4); /* Riemann-Hurwitz for genus 1, degree 2 */
    CHECK(strstr(meromorph_remesh_report_json(remesh), "\"remesh\"") != NULL);
    CHECK(strstr(meromorph_remesh_summary(remesh), "Hausdorff") != NULL);
    CHECK(meromorph_remesh_vertex_count(NULL) == 0 && meromorph_remesh_summary(NULL)[0] == '\0');
    CHECK(meromorph_remesh_mesh(NULL, xyz, NULL, NULL, NULL, NULL) == MEROMORPH_ERROR_ARGUMENT);
    meromorph_remesh_free(remesh);
    meromorph_remesh_free(NULL);
    {
      /* The same from float positions. */
      float *single = malloc(sizeof(float) * 3 * V);
      for (k = 0; k < 3 * (size_t)V; ++k)
        single[k] = (float)positions[k];
      remesh = NULL;
      CHECK(meromorph_remesh_f(single, V, triangles, F, &options, 0, 1, &remesh) == MEROMORPH_OK);
      CHECK(meromorph_remesh_vertex_count(remesh) > 0.9 * V);
      meromorph_remesh_free(remesh);
      free(single);
    }
    free(xyz);
    free(values);
    free(faces);
    free(sheet);
    free(degree);
  }

  {
    /* A CAD washer: with the defaults, vertices are added where its triangles cannot carry the
       map; they lie on the triangles named, and the surface as written has them after the
       input's. Without add_vertices (or from a caller that predates it) the input's triangles
       are kept and the map is reported as not valid. */
    double *p = malloc(sizeof(double) * 3 * WASHER_V);
    int32_t *t = malloc(sizeof(int32_t) * 3 * WASHER_F);
    size_t a, n, m, k;
    double *bary, *xyz;
    int32_t *on, *surface, *source;
    fill_washer(p, t);
    meromorph_default_options(&options);
    CHECK(options.add_vertices == 1);
    CHECK(meromorph_parameterize_d(p, WASHER_V, t, WASHER_F, &options, &result) == MEROMORPH_OK);
    CHECK(meromorph_map_valid(result) == 1);
    a = meromorph_added_vertex_count(result);
    n = meromorph_vertex_count(result);
    m = meromorph_triangle_count(result);
    CHECK(a > 0 && n == WASHER_V + a && m > WASHER_F);
    bary = malloc(sizeof(double) * 2 * a);
    xyz = malloc(sizeof(double) * 3 * a);
    on = malloc(sizeof(int32_t) * a);
    surface = malloc(sizeof(int32_t) * 3 * m);
    source = malloc(sizeof(int32_t) * m);
    CHECK(meromorph_added_vertices(result, on, bary, xyz) == MEROMORPH_OK);
    for (k = 0; k < a; ++k) {
      const int32_t *c = t + 3 * on[k];
      int axis;
      CHECK(on[k] >= 0 && on[k] < WASHER_F);
      CHECK(bary[2 * k] >= -1e-12 && bary[2 * k + 1] >= -1e-12 &&
            bary[2 * k] + bary[2 * k + 1] <= 1 + 1e-12);
      for (axis = 0; axis < 3; ++axis) {
        const double at = (1 - bary[2 * k] - bary[2 * k + 1]) * p[3 * c[0] + axis] +
                          bary[2 * k] * p[3 * c[1] + axis] + bary[2 * k + 1] * p[3 * c[2] + axis];
        CHECK(fabs(at - xyz[3 * k + axis]) < 1e-9);
      }
    }
    CHECK(meromorph_surface_triangles(result, surface, source) == MEROMORPH_OK);
    for (k = 0; k < 3 * m; ++k)
      CHECK(surface[k] >= 0 && (size_t)surface[k] < n);
    for (k = 0; k < m; ++k)
      CHECK(source[k] >= 0 && source[k] < WASHER_F && (k >= WASHER_F || source[k] == (int32_t)k));
    meromorph_result_free(result);
    result = NULL;
    options.add_vertices = 0;
    CHECK(meromorph_parameterize_d(p, WASHER_V, t, WASHER_F, &options, &result) == MEROMORPH_OK);
    CHECK(meromorph_map_valid(result) == 0 && meromorph_added_vertex_count(result) == 0);
    CHECK(meromorph_vertex_count(result) == WASHER_V &&
          meromorph_triangle_count(result) == WASHER_F);
    meromorph_result_free(result);
    result = NULL;
    meromorph_default_options(&options);
    options.struct_size = offsetof(meromorph_options, add_vertices);
    options.add_vertices = 1; /* beyond the old struct: never read */
    CHECK(meromorph_parameterize_d(p, WASHER_V, t, WASHER_F, &options, &result) == MEROMORPH_OK);
    CHECK(meromorph_added_vertex_count(result) == 0);
    meromorph_result_free(result);
    result = NULL;
    meromorph_default_options(&options);
    options.add_vertices = 2;
    CHECK(meromorph_parameterize_d(p, WASHER_V, t, WASHER_F, &options, &result) ==
          MEROMORPH_ERROR_ARGUMENT);
    CHECK(strstr(meromorph_last_error(), "add_vertices") != NULL);
    CHECK(meromorph_added_vertex_count(NULL) == 0);
    CHECK(meromorph_added_vertices(NULL, NULL, NULL, NULL) == MEROMORPH_ERROR_ARGUMENT);
    free(p);
    free(t);
    free(bary);
    free(xyz);
    free(on);
    free(surface);
    free(source);
  }

  { /* a match: the torus onto itself turned a quarter about its axis and moved, fixed by two
       landmarks (a torus of revolution turns onto itself): vertex v lands on its moved self */
    meromorph_match_result *match = NULL;
    double *moved = malloc(sizeof(double) * 3 * V), *weights = malloc(sizeof(double) * 3 * V);
    double *points = malloc(sizeof(double) * 3 * V), worst = 0;
    int32_t *on = malloc(sizeof(int32_t) * V);
    const int32_t pairs[4] = {0, 0, 300, 300}, far[2] = {0, V + 5};
    size_t v;
    make_torus();
    for (v = 0; v < (size_t)V; ++v) {
      moved[3 * v] = -positions[3 * v + 1] + 5;
      moved[3 * v + 1] = positions[3 * v];
      moved[3 * v + 2] = positions[3 * v + 2] - 1;
    }
    CHECK(meromorph_match_d(positions, V, triangles, F, moved, V, triangles, F, pairs, 2, NULL,
                            &match) == MEROMORPH_OK);
    CHECK(meromorph_match_vertex_count(match) == V);
    CHECK(meromorph_match_points(match, on, weights, points) == MEROMORPH_OK);
    for (v = 0; v < (size_t)V; ++v) {
      const double dx = points[3 * v] - moved[3 * v], dy = points[3 * v + 1] - moved[3 * v + 1],
                   dz = points[3 * v + 2] - moved[3 * v + 2];
      const double d = sqrt(dx * dx + dy * dy + dz * dz);
      if (on[v] < 0 || on[v] >= F ||
          fabs(weights[3 * v] + weights[3 * v + 1] + weights[3 * v + 2] - 1) > 1e-9)
        break;
      if (d > worst) worst = d;
    }
    CHECK(v == (size_t)V && worst < 1e-3);
    { /* per triangle: one target triangle, each corner's point in its weights (projected on its
         plane: within a small fraction of the grid's spacing) */
      int32_t *centre_on = malloc(sizeof(int32_t) * F);
      double *corner_weights = malloc(sizeof(double) * 9 * F), off = 0;
      size_t f;
      int k, j, c;
      CHECK(meromorph_match_triangle_count(match) == F);
      CHECK(meromorph_match_triangles(match, centre_on, corner_weights) == MEROMORPH_OK);
      for (f = 0; f < (size_t)F; ++f) {
        if (centre_on[f] < 0 || centre_on[f] >= F) break;
        for (k = 0; k < 3; ++k) {
          const double *w = corner_weights + 9 * f + 3 * k;
          const int32_t corner = triangles[3 * f + k];
          if (fabs(w[0] + w[1] + w[2] - 1) > 1e-9) off = 1e9;
          for (c = 0; c < 3; ++c) {
            double at = 0;
            for (j = 0; j < 3; ++j)
              at += w[j] * moved[3 * triangles[3 * centre_on[f] + j] + c];
            if (fabs(at - points[3 * corner + c]) > off) off = fabs(at - points[3 * corner + c]);
          }
        }
      }
      CHECK(f == (size_t)F && off < 0.05);
      free(centre_on);
      free(corner_weights);
    }
    CHECK(strstr(meromorph_match_report_json(match), "\"lattice_map\"") != NULL);
    meromorph_match_free(match);
    match = NULL;
    CHECK(meromorph_match_d(positions, V, triangles, F, moved, V, triangles, F, far, 1, NULL,
                            &match) == MEROMORPH_ERROR_INPUT);
    CHECK(match == NULL && strstr(meromorph_last_error(), "not there") != NULL);
    CHECK(meromorph_match_d(positions, V, triangles, F, moved, V, triangles, F, NULL, 1, NULL,
                            &match) == MEROMORPH_ERROR_ARGUMENT);
    meromorph_match_free(NULL);
    free(moved);
    free(weights);
    free(points);
    free(on);
  }
  { /* forms, writing a map's files and reading them back */
    meromorph_forms_result *forms = NULL;
    meromorph_mesh *mesh = NULL;
    const char *protect[1] = {"c_abi_written.ply"};
    double *xyz;
    int32_t *written;
    size_t k;
    make_torus();
    CHECK(meromorph_forms_d(positions, V, triangles, F, NULL, &forms) == MEROMORPH_OK);
    CHECK(meromorph_forms_genus(forms) == 1 && meromorph_forms_genus(NULL) == -1);
    CHECK(strstr(meromorph_forms_report_json(forms), "\"modulus\"") != NULL);
    meromorph_forms_free(forms);
    CHECK(meromorph_forms_d(positions, V, triangles, F - 1, NULL, &forms) == MEROMORPH_ERROR_INPUT);
    CHECK(forms == NULL && strlen(meromorph_last_error()) > 0);

    meromorph_default_options(&options);
    CHECK(meromorph_parameterize_d(positions, V, triangles, F, &options, &result) == MEROMORPH_OK);
    remove("c_abi_written.ply");
    CHECK(meromorph_write_map(result, "c_abi_written.ply", "c_abi_sphere.ply", "c_abi_report.json",
                              NULL, 0) == MEROMORPH_OK);
    CHECK(meromorph_write_map(result, "c_abi_written.ply", NULL, NULL, protect, 1) ==
          MEROMORPH_ERROR_ARGUMENT);
    CHECK(meromorph_write_map(result, "c_abi_written.stl", NULL, NULL, NULL, 0) ==
          MEROMORPH_ERROR_ARGUMENT);
    CHECK(meromorph_write_map(result, NULL, NULL, NULL, NULL, 0) == MEROMORPH_ERROR_ARGUMENT);
    CHECK(meromorph_write_map(result, "no_such_folder/x.ply", NULL, NULL, NULL, 0) ==
          MEROMORPH_ERROR_OUTPUT);
    CHECK(meromorph_read_mesh("c_abi_written.ply", &mesh) == MEROMORPH_OK);
    CHECK(meromorph_mesh_vertex_count(mesh) == V && meromorph_mesh_triangle_count(mesh) == F);
    xyz = malloc(sizeof(double) * 3 * V);
    written = malloc(sizeof(int32_t) * 3 * F);
    CHECK(meromorph_mesh_arrays(mesh, xyz, written) == MEROMORPH_OK);
    for (k = 0; k < 3 * (size_t)F; ++k)
      if (written[k] != triangles[k]) break;
    CHECK(k == 3 * (size_t)F);
    for (k = 0; k < 3 * (size_t)V; ++k)
      if (fabs(xyz[k] - positions[k]) > 1e-6) break;
    CHECK(k == 3 * (size_t)V);
    meromorph_mesh_free(mesh);
    mesh = NULL;
    CHECK(meromorph_read_mesh("c_abi_sphere.ply", &mesh) == MEROMORPH_OK);
    CHECK(meromorph_mesh_vertex_count(mesh) == V);
    meromorph_mesh_free(mesh);
    mesh = NULL;
    CHECK(meromorph_read_mesh("no_such_file.ply", &mesh) == MEROMORPH_ERROR_ARGUMENT);
    CHECK(mesh == NULL && strstr(meromorph_last_error(), "no_such_file.ply") != NULL);
    CHECK(meromorph_mesh_vertex_count(NULL) == 0 && meromorph_mesh_notes(NULL)[0] == '\0');
    meromorph_result_free(result);
    result = NULL;
    free(xyz);
    free(written);
  }

  printf("%d passed, 0 failed\n", passed);
  return 0;
}
