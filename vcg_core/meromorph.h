/* meromorph C ABI: conformal maps of closed triangle meshes of any genus onto the sphere.
 *
 * In:  an oriented triangle mesh as flat arrays: vertex positions (x, y, z per vertex, double or
 *      float) and triangles (three 0-based int32 vertex indices each, counter-clockwise seen from
 *      outside), closed and manifold, or with several parts (each mapped on its own), holes
 *      (options.close_holes) and non-manifold spots (options.split_nonmanifold); and options (call
 * meromorph_default_options first; struct_size tells the library which version of the struct the
 * caller compiled). Out: an opaque result with per-vertex sphere positions, layered-sphere
 * positions, texture coordinates (per vertex and per triangle corner), layers, branch points with
 * local degrees, degree, genus, distortion figures and the JSON report of `meromorph param`.
 * Errors: meromorph_parameterize_* and the buffer getters return a status; the scalar getters
 *      return a value that marks a NULL result (-1, 0 or ""). meromorph_last_error() says what went
 *      wrong in words (with vertex / face indices).
 * Ownership: the caller owns every buffer it passes (nothing is kept after a call returns) and
 *      frees a result with meromorph_result_free. Strings returned by a result live as long as
 *      the result.
 * Threads: every function may be called from several threads at once on different results and
 *      meshes; a result may be read by several threads at once; the last error is per thread and
 *      stays valid until that thread's next call of meromorph_parameterize_*.
 * No C++ exception and no abort crosses this boundary. Compiles as C99 and as C++.
 */
#ifndef MEROMORPH_H
#define MEROMORPH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define MEROMORPH_ABI_VERSION 3

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
  int close_holes; /* 1: close holes for the computation only (outputs keep the input's faces);
                      0: refuse a mesh with holes (default). Since ABI version 2; a version-1
                      struct_size is still accepted, with 0 here. */
  int split_nonmanifold; /* 1: take non-manifold vertices and edges apart for the computation (the
                            layered sphere then has copies of the split vertices: see
                            meromorph_sphere_mesh); 0: refuse such a mesh (default). Since ABI
                            version 3; a version 1 or 2 struct_size is accepted, with 0 here. */
  int pack_uv;           /* several parts, spherical uvs: 1 puts part k's uvs in cell k of a grid
                            over the unit square; 0: each part fills it (default). Since ABI
                            version 3. */
} meromorph_options;

typedef struct meromorph_result meromorph_result;

MEROMORPH_API int meromorph_abi_version(void);
MEROMORPH_API const char *meromorph_version(void);
MEROMORPH_API void meromorph_default_options(meromorph_options *options);
MEROMORPH_API const char *meromorph_last_error(void);

/* Maps a mesh. positions: 3 * vertex_count values (x, y, z per vertex; finite). triangles:
   3 * triangle_count vertex indices (0-based, < vertex_count). options: NULL for the defaults, or
   initialized by meromorph_default_options (struct_size must be this header's sizeof); uv_kind 0
   or 1, mobius 0 or 1, origin_vertex -1 or a vertex, pole_face -1 or a triangle, form_pair -1 or
   form indices below the genus, layer_gap finite in [0, 1e6]. result: where the new result goes
   (set to NULL on failure). Returns MEROMORPH_ERROR_ARGUMENT for NULL pointers and bad options,
   MEROMORPH_ERROR_INPUT for a mesh that cannot be mapped (open, non-manifold, out-of-range
   index, non-finite coordinate, ...), MEROMORPH_ERROR_CANCELLED when progress returned 0. */
MEROMORPH_API meromorph_status meromorph_parameterize_d(
    const double *positions, size_t vertex_count, const int32_t *triangles, size_t triangle_count,
    const meromorph_options *options, meromorph_result **result);
MEROMORPH_API meromorph_status meromorph_parameterize_f(const float *positions, size_t vertex_count,
                                                        const int32_t *triangles,
                                                        size_t triangle_count,
                                                        const meromorph_options *options,
                                                        meromorph_result **result);
MEROMORPH_API void meromorph_result_free(meromorph_result *result);

/* Scalar getters: a NULL result gives 0 for counts, -1 for genus and degree, 0 for the
   Riemann-Hurwitz flag and "" for strings. */
MEROMORPH_API size_t meromorph_vertex_count(const meromorph_result *result);
MEROMORPH_API size_t meromorph_triangle_count(const meromorph_result *result);
MEROMORPH_API int meromorph_genus(const meromorph_result *result);
MEROMORPH_API int meromorph_degree(const meromorph_result *result);
MEROMORPH_API int meromorph_riemann_hurwitz_ok(const meromorph_result *result);
/* 1 when the map is a valid branched cover of the sphere (the expected degree, Riemann-Hurwitz,
   no face turned over), 0 otherwise. */
MEROMORPH_API int meromorph_map_valid(const meromorph_result *result);
/* When the map is not valid: what fails, with face indices, reasons joined by "; " ("" when
   valid); owned by the result. */
MEROMORPH_API const char *meromorph_invalid_reasons(const meromorph_result *result);
/* When the map is not valid: the likely causes and what to do ("" otherwise); owned by the
   result. */
MEROMORPH_API const char *meromorph_advice(const meromorph_result *result);

/* Copies into the caller's buffer, which must hold (per vertex of the input, in its order):
   sphere and layered positions 3 doubles per vertex, vertex uvs 2 doubles per vertex, corner uvs
   6 doubles per triangle (u, v for each of its three corners), layers and components 1 int32 per
   vertex. A vertex that split_nonmanifold split gets the values of the fan of its first
   triangle here (its corner uvs are exact for every triangle). MEROMORPH_ERROR_ARGUMENT if a
   pointer is NULL. */
MEROMORPH_API meromorph_status meromorph_sphere_positions(const meromorph_result *result,
                                                          double *xyz);
MEROMORPH_API meromorph_status meromorph_layered_positions(const meromorph_result *result,
                                                           double *xyz);
MEROMORPH_API meromorph_status meromorph_vertex_uvs(const meromorph_result *result, double *uv);
MEROMORPH_API meromorph_status meromorph_corner_uvs(const meromorph_result *result, double *uv);
MEROMORPH_API meromorph_status meromorph_layers(const meromorph_result *result, int32_t *layer);
/* The part (connected component, 0-based) of each vertex; part k's layered sphere is centred at
   x = k * meromorph_component_spacing. Since ABI version 2. */
MEROMORPH_API meromorph_status meromorph_vertex_components(const meromorph_result *result,
                                                           int32_t *component);
MEROMORPH_API double meromorph_component_spacing(const meromorph_result *result);

/* The layered sphere as a mesh: meromorph_sphere_vertex_count vertices (the input's in order,
   then, when split_nonmanifold split vertices, their copies) and meromorph_triangle_count
   triangles (the input's, in order, pointing at the copies where split). Fills, per sphere
   vertex: layered_xyz 3 doubles, source_vertex (the input vertex), layer, component and branch
   (the local degree at a branch point, 0 elsewhere) 1 int32 each; triangles 3 int32 per
   triangle. Any buffer may be NULL (not filled). Since ABI version 3. */
MEROMORPH_API size_t meromorph_sphere_vertex_count(const meromorph_result *result);
MEROMORPH_API meromorph_status meromorph_sphere_mesh(const meromorph_result *result,
                                                     double *layered_xyz, int32_t *triangles,
                                                     int32_t *source_vertex, int32_t *layer,
                                                     int32_t *component, int32_t *branch);

MEROMORPH_API size_t meromorph_branch_point_count(const meromorph_result *result);
/* vertices (the input's) and local_degrees: meromorph_branch_point_count entries each;
   local_degrees may be NULL. */
MEROMORPH_API meromorph_status meromorph_branch_points(const meromorph_result *result,
                                                       int32_t *vertices, int32_t *local_degrees);

typedef struct meromorph_distortion {
  double angle_error_mean_degrees;
  double quasi_conformal_mean, quasi_conformal_p95, quasi_conformal_max;
  int32_t folded_faces_away_from_branch_points;
  int32_t folded_faces;
} meromorph_distortion;
/* Fills *distortion; MEROMORPH_ERROR_ARGUMENT if a pointer is NULL. */
MEROMORPH_API meromorph_status meromorph_get_distortion(const meromorph_result *result,
                                                        meromorph_distortion *distortion);

/* The JSON report (as `meromorph param --report`); owned by the result. */
MEROMORPH_API const char *meromorph_report_json(const meromorph_result *result);

#ifdef __cplusplus
}
#endif

#endif /* MEROMORPH_H */
