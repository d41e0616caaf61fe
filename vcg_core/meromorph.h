/* meromorph C ABI: conformal maps of closed triangle meshes of any genus onto the sphere.
 *
 * In:  a closed, connected, oriented manifold triangle mesh as flat arrays: vertex positions
 *      (x, y, z per vertex, double or float) and triangles (three 0-based int32 vertex indices
 *      each, counter-clockwise seen from outside), and options (call meromorph_default_options
 *      first; struct_size tells the library which version of the struct the caller compiled).
 * Out: an opaque result with per-vertex sphere positions, layered-sphere positions, texture
 *      coordinates (per vertex and per triangle corner), layers, branch points with local
 *      degrees, degree, genus, distortion figures and the JSON report of `meromorph param`.
 * Errors: every function returns a status; meromorph_last_error() says what went wrong in words
 *      (with vertex / face indices), for this thread. No C++ exception and no abort crosses this
 *      boundary. Compiles as C99 and as C++.
 */
#ifndef MEROMORPH_H
#define MEROMORPH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define MEROMORPH_ABI_VERSION 1

#if defined(__GNUC__)
#define MEROMORPH_API __attribute__((visibility("default")))
#else
#define MEROMORPH_API
#endif

typedef enum meromorph_status {
  MEROMORPH_OK = 0,
  MEROMORPH_ERROR_INTERNAL = 1, /* a bug: please report it with the input */
  MEROMORPH_ERROR_ARGUMENT = 2, /* a null pointer, a bad option, a buffer of the wrong kind */
  MEROMORPH_ERROR_INPUT = 3,    /* the mesh cannot be parameterized: open, non-manifold, ... */
  MEROMORPH_ERROR_CANCELLED = 4 /* the progress callback asked to stop */
} meromorph_status;

/* Progress: fraction in [0, 1] and the stage in words. Return 0 to cancel, non-zero to go on. */
typedef int (*meromorph_progress_fn)(double fraction, const char *stage, void *user);

typedef struct meromorph_options {
  size_t struct_size;             /* sizeof(meromorph_options) as the caller compiled it */
  int uv_kind;                    /* 0: spherical (longitude, latitude), 1: stereographic */
  int mobius;                     /* 1: centre by a Moebius transformation (default), 0: do not */
  int origin_vertex;              /* genus 1: the double pole's vertex; -1: automatic */
  int form_pair[2];               /* genus >= 2: (psi_i + psi_j) / (psi_i - psi_j); default -1, -1:
                                  a generic pair mixing all forms */
  double layer_gap;               /* layer k on the sphere of radius 1 + gap * k; default 0 */
  int pole_face;                  /* genus 0: the face around the north pole; -1: automatic */
  meromorph_progress_fn progress; /* may be NULL */
  void *progress_user;
} meromorph_options;

typedef struct meromorph_result meromorph_result;

MEROMORPH_API int meromorph_abi_version(void);
MEROMORPH_API const char *meromorph_version(void);
MEROMORPH_API void meromorph_default_options(meromorph_options *options);
MEROMORPH_API const char *meromorph_last_error(void);

MEROMORPH_API meromorph_status meromorph_parameterize_d(
    const double *positions, size_t vertex_count, const int32_t *triangles, size_t triangle_count,
    const meromorph_options *options, meromorph_result **result);
MEROMORPH_API meromorph_status meromorph_parameterize_f(const float *positions, size_t vertex_count,
                                                        const int32_t *triangles,
                                                        size_t triangle_count,
                                                        const meromorph_options *options,
                                                        meromorph_result **result);
MEROMORPH_API void meromorph_result_free(meromorph_result *result);

MEROMORPH_API size_t meromorph_vertex_count(const meromorph_result *result);
MEROMORPH_API size_t meromorph_triangle_count(const meromorph_result *result);
MEROMORPH_API int meromorph_genus(const meromorph_result *result);
MEROMORPH_API int meromorph_degree(const meromorph_result *result);
MEROMORPH_API int meromorph_riemann_hurwitz_ok(const meromorph_result *result);
/* When Riemann-Hurwitz fails: the likely causes and what to do ("" otherwise); owned by the
   result. */
MEROMORPH_API const char *meromorph_advice(const meromorph_result *result);

/* Buffers are the caller's: 3 per vertex, 2 per vertex, 6 per triangle, 1 per vertex. */
MEROMORPH_API meromorph_status meromorph_sphere_positions(const meromorph_result *result,
                                                          double *xyz);
MEROMORPH_API meromorph_status meromorph_layered_positions(const meromorph_result *result,
                                                           double *xyz);
MEROMORPH_API meromorph_status meromorph_vertex_uvs(const meromorph_result *result, double *uv);
MEROMORPH_API meromorph_status meromorph_corner_uvs(const meromorph_result *result, double *uv);
MEROMORPH_API meromorph_status meromorph_layers(const meromorph_result *result, int32_t *layer);

MEROMORPH_API size_t meromorph_branch_point_count(const meromorph_result *result);
/* vertices and local_degrees: meromorph_branch_point_count entries each. */
MEROMORPH_API meromorph_status meromorph_branch_points(const meromorph_result *result,
                                                       int32_t *vertices, int32_t *local_degrees);

typedef struct meromorph_distortion {
  double angle_error_mean_degrees;
  double quasi_conformal_mean, quasi_conformal_p95, quasi_conformal_max;
  int32_t folded_faces_away_from_branch_points;
  int32_t folded_faces;
} meromorph_distortion;
MEROMORPH_API meromorph_status meromorph_get_distortion(const meromorph_result *result,
                                                        meromorph_distortion *distortion);

/* The JSON report (as `meromorph param --report`); owned by the result. */
MEROMORPH_API const char *meromorph_report_json(const meromorph_result *result);

#ifdef __cplusplus
}
#endif

#endif /* MEROMORPH_H */
