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
 *      wrong in words (with vertex / face indices), naming no tool or option;
 *      meromorph_last_error_remedies() gives what to do as codes for the caller to word.
 * Ownership: the caller owns every buffer it passes (nothing is kept after a call returns) and
 *      frees a result with meromorph_result_free. Strings returned by a result live as long as
 *      the result.
 * Threads: every function may be called from several threads at once on different results and
 *      meshes; a result may be read by several threads at once; the last error is per thread and
 *      stays valid until that thread's next call of meromorph_parameterize_* or failing getter.
 * No C++ exception and no abort crosses this boundary. Compiles as C99 and as C++.
 */
#ifndef MEROMORPH_H
#define MEROMORPH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The ABI's version: it changes only for a real break (and with it the library's SONAME and
   symbol version, libmeromorph.so.5 and MEROMORPH_5). Additions do not change it: a new option is
   a new field at the end of meromorph_options, which struct_size tells apart (an older caller's
   struct gets the new field's default), and a new function is a new symbol. */
#define MEROMORPH_ABI_VERSION 5

#if defined(__GNUC__)
#define MEROMORPH_API __attribute__((visibility("default")))
#else
#define MEROMORPH_API
#endif

typedef enum meromorph_status {
  MEROMORPH_OK = 0,
  MEROMORPH_ERROR_INTERNAL = 1,  /* a bug: please report it with the input */
  MEROMORPH_ERROR_ARGUMENT = 2,  /* a null pointer, a bad option, a buffer of the wrong kind */
  MEROMORPH_ERROR_INPUT = 3,     /* the mesh cannot be parameterized: open, non-manifold, ... */
  MEROMORPH_ERROR_CANCELLED = 4, /* the progress callback asked to stop */
  MEROMORPH_ERROR_OUTPUT = 5     /* a file could not be written (meromorph_write_map) */
} meromorph_status;

/* Remedies: what the user can do about a refusal (meromorph_last_error_remedies) or an invalid
   map (meromorph_advice_remedy), as codes each caller words for its users (its own options and
   menus); the library's messages name no tool, option or menu. */
typedef enum meromorph_remedy {
  MEROMORPH_REMEDY_REPAIR = 1,                 /* safe repairs: merge seam duplicates, drop unused
                                                  vertices, orient the faces consistently */
  MEROMORPH_REMEDY_CLOSE_HOLES = 2,            /* options.close_holes = 1, or close them */
  MEROMORPH_REMEDY_SPLIT_NONMANIFOLD = 3,      /* options.split_nonmanifold = 1 */
  MEROMORPH_REMEDY_REMOVE_ZERO_AREA_FACES = 4, /* optional: they are kept out of the computation */
  MEROMORPH_REMEDY_REMOVE_DUPLICATE_FACES = 5, /* faces on the same three vertices */
  MEROMORPH_REMEDY_REMESH = 6,                 /* needles and caps: remesh isotropically */
  MEROMORPH_REMEDY_REFINE = 7,                 /* too coarse near the branch points: subdivide */
  MEROMORPH_REMEDY_GENERIC_FORM_PAIR = 8,      /* options.form_pair = -1, -1 */
  MEROMORPH_REMEDY_SHORTEN_THIN_PARTS = 9,     /* long thin parts: shorten, thicken, or map apart */
  MEROMORPH_REMEDY_CHECK_UNITS = 10,           /* a stray vertex, or coordinates in other units */
  MEROMORPH_REMEDY_CHOOSE_UV_KIND = 11,        /* pack_uv needs uv_kind 0 (spherical) */
  MEROMORPH_REMEDY_ADD_VERTICES = 12           /* options.add_vertices = 1 (and strict = 0) */
} meromorph_remedy;

/* Progress: fraction in [0, 1] and the stage in words. Return 0 to cancel, non-zero to go on.
   It is called on the thread that called meromorph (the work runs meanwhile on a thread of its
   own, which ends with the call), at least every quarter second while the work runs; after a cancel
   the call returns when the work reaches its next report (at most the end of one Laplacian
   factorization). */
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
  int close_holes;       /* 1: close holes for the computation only (outputs keep the input's faces;
                            default); 0: refuse a mesh with holes. Since ABI version 2; a version-1
                            struct_size is still accepted, with the default here. */
  int split_nonmanifold; /* 1: take non-manifold vertices and edges apart for the computation (the
                            layered sphere then has copies of the split vertices: see
                            meromorph_sphere_mesh; default); 0: refuse such a mesh. Since ABI
                            version 3; a version 1 or 2 struct_size is accepted, with the
                            default here. */
  int pack_uv;           /* several parts, spherical uvs: 1 puts part k's uvs in cell k of a grid
                            over the unit square; 0: each part fills it (default). Since ABI
                            version 3. */
  int area_correct;      /* 1: after centring, the Moebius transformation that spreads the map
                            most evenly in area (angles unchanged); 0: not (default). Since
                            meromorph 0.2; an older struct_size is accepted, with 0 here. */
  int strict;            /* 1: refuse, naming the problem, what the defaults deal with for the
                            computation (holes, non-manifold spots, seam duplicates, doubled faces,
                            faces that use a vertex twice, vertices on no face) whatever
                            close_holes and split_nonmanifold say; 0: deal with them (default: they
                            are welded or left out for the computation, and the results still have
                            every input vertex and triangle). Since meromorph 0.2; an older
                            struct_size is accepted, with 0 here. */
  int add_vertices;      /* 1: where the input's triangles cannot carry the map without turning
                            some over (slivers, coarse triangles at branch points), add the
                            vertices it needs (default): they come after the input's, and
                            meromorph_vertex_count and meromorph_triangle_count count the surface
                            as written (see meromorph_added_vertices); 0 (and with strict): keep
                            the input's triangles and report the map as not valid. Since
                            meromorph 0.3; an older struct_size is accepted, with 0 here. */
  double remesh_edge_length; /* meromorph_remesh_*: > 0: about this edge length, in the input's
                                units, instead of target_vertices (the count of equilateral
                                triangles of that side tiling the surface); 0: not given (default).
                                Since meromorph 0.4; an older struct_size is accepted, with 0. */
  double remesh_max_error;   /* meromorph_remesh_*: > 0: the remesh within this distance of the
                                surface both ways (Hausdorff, a fraction of the bounding-box
                                diagonal, below 1), with as few vertices as the tries find, instead
                                of target_vertices; 0: not given (default). Since meromorph 0.4. */
} meromorph_options;

/* A map and everything measured on it; opaque. Made by meromorph_parameterize_*, read by the
   getters below (any number of threads at once), freed by meromorph_result_free. */
typedef struct meromorph_result meromorph_result;

/* The ABI version this library serves (MEROMORPH_ABI_VERSION when built from this header). */
MEROMORPH_API int meromorph_abi_version(void);
/* The library's version, "major.minor.patch"; static storage. */
MEROMORPH_API const char *meromorph_version(void);
/* Fills *options with the defaults and struct_size = sizeof(meromorph_options).
   Inputs:  options  not NULL (nothing happens when it is). */
MEROMORPH_API void meromorph_default_options(meromorph_options *options);
/* What the calling thread's last failed call said, in words with vertex / face indices; "" when
   none. Per thread; valid until that thread's next call of meromorph_parameterize_* (which clears
   it) or of a getter that fails. */
MEROMORPH_API const char *meromorph_last_error(void);
/* The remedies for the calling thread's last failed call (meromorph_remedy codes), valid as long
   as meromorph_last_error.
   Outputs: remedies  up to `capacity` codes (caller-owned; may be NULL when capacity is 0).
   Returns: how many remedies there are (may exceed capacity: call again with more room). */
MEROMORPH_API int meromorph_last_error_remedies(int32_t *remedies, int capacity);

/* Maps a mesh.
   Inputs:
     positions       3 * vertex_count values, x y z per vertex, finite (double or float)
     vertex_count    number of vertices
     triangles       3 * triangle_count vertex indices, 0-based, < vertex_count, counter-clockwise
                     seen from outside
     triangle_count  number of triangles
     options         NULL for the defaults, or made by meromorph_default_options: struct_size this
                     header's sizeof (or an earlier version's); uv_kind 0 or 1, mobius 0 or 1,
                     origin_vertex -1 or a vertex, pole_face -1 or a triangle, form_pair -1, -1 or
                     two different form indices below the genus, layer_gap finite in [0, 1e6];
                     progress may be NULL
   Outputs:
     result          *result: the new result, owned by the caller (meromorph_result_free); NULL
                     on failure. The caller's buffers are not kept.
   Returns: MEROMORPH_OK; MEROMORPH_ERROR_ARGUMENT for NULL pointers and bad options;
     MEROMORPH_ERROR_INPUT for a mesh that cannot be mapped (open without close_holes,
     non-manifold without split_nonmanifold, an out-of-range index, a non-finite coordinate, ...,
     and a map that is not a valid branched cover is not an error: see meromorph_map_valid);
     MEROMORPH_ERROR_CANCELLED when progress returned 0; meromorph_last_error says why.
   Thread-safe: yes, for different calls at once. */
MEROMORPH_API meromorph_status meromorph_parameterize_d(
    const double *positions, size_t vertex_count, const int32_t *triangles, size_t triangle_count,
    const meromorph_options *options, meromorph_result **result);
MEROMORPH_API meromorph_status meromorph_parameterize_f(const float *positions, size_t vertex_count,
                                                        const int32_t *triangles,
                                                        size_t triangle_count,
                                                        const meromorph_options *options,
                                                        meromorph_result **result);
/* Frees a result and the strings it owns; NULL is allowed (nothing happens). */
MEROMORPH_API void meromorph_result_free(meromorph_result *result);

/* Scalar getters. Inputs: result (may be NULL: counts give 0, genus and degree -1, flags 0,
   strings ""). Thread-safe: yes. Strings are owned by the result and live as long as it. */
/* The surface as written: the input's vertices and triangles, unless vertices were added
   (options.add_vertices): then the input's vertices followed by the added ones, and the
   triangles of meromorph_surface_triangles. */
MEROMORPH_API size_t meromorph_vertex_count(const meromorph_result *result);
MEROMORPH_API size_t meromorph_triangle_count(const meromorph_result *result);
MEROMORPH_API int meromorph_genus(const meromorph_result *result);  /* summed over the parts */
MEROMORPH_API int meromorph_degree(const meromorph_result *result); /* summed over the parts */
MEROMORPH_API int meromorph_riemann_hurwitz_ok(const meromorph_result *result); /* 1 or 0 */
/* 1 when the map is a valid branched cover of the sphere (the expected degree, Riemann-Hurwitz,
   no face turned over), 0 otherwise. */
MEROMORPH_API int meromorph_map_valid(const meromorph_result *result);
/* When the map is not valid: what fails, with face indices, reasons joined by "; " ("" when
   valid). */
MEROMORPH_API const char *meromorph_invalid_reasons(const meromorph_result *result);
/* When the map is not valid: the likely causes found on this mesh, with figures and places,
   joined by "; " ("" otherwise). Each cause has a remedy: */
MEROMORPH_API const char *meromorph_advice(const meromorph_result *result);
/* The number of causes (0 when the map is valid or result is NULL), cause `index` alone ("" out of
   range; lives as long as the result) and its remedy (a meromorph_remedy; 0 out of range). */
MEROMORPH_API int meromorph_advice_count(const meromorph_result *result);
MEROMORPH_API const char *meromorph_advice_cause(const meromorph_result *result, int index);
MEROMORPH_API int meromorph_advice_remedy(const meromorph_result *result, int index);

/* Per-vertex and per-corner arrays, copied into the caller's buffer, in the input's order.
   Inputs:  result  not NULL
   Outputs (caller-owned, not NULL):
     meromorph_sphere_positions   xyz    3 * meromorph_vertex_count doubles (unit sphere)
     meromorph_layered_positions  xyz    3 * meromorph_vertex_count doubles (layer k at radius
                                         1 + layer_gap * k; part k shifted by k * spacing in x)
     meromorph_vertex_uvs         uv     2 * meromorph_vertex_count doubles
     meromorph_corner_uvs         uv     6 * meromorph_triangle_count doubles (u, v per corner)
     meromorph_layers             layer  meromorph_vertex_count int32
     meromorph_vertex_components  component  meromorph_vertex_count int32 (the part, 0-based;
                                         since ABI version 2)
   A vertex that split_nonmanifold split gets the values of the fan of its first triangle here
   (its corner uvs are exact for every triangle; meromorph_sphere_mesh has every copy).
   Returns: MEROMORPH_OK, or MEROMORPH_ERROR_ARGUMENT if a pointer is NULL. Thread-safe: yes. */
MEROMORPH_API meromorph_status meromorph_sphere_positions(const meromorph_result *result,
                                                          double *xyz);
MEROMORPH_API meromorph_status meromorph_layered_positions(const meromorph_result *result,
                                                           double *xyz);
MEROMORPH_API meromorph_status meromorph_vertex_uvs(const meromorph_result *result, double *uv);
MEROMORPH_API meromorph_status meromorph_corner_uvs(const meromorph_result *result, double *uv);
MEROMORPH_API meromorph_status meromorph_layers(const meromorph_result *result, int32_t *layer);
MEROMORPH_API meromorph_status meromorph_vertex_components(const meromorph_result *result,
                                                           int32_t *component);
/* The distance in x between the parts' layered spheres (0 for one part; NULL result: 0). */
MEROMORPH_API double meromorph_component_spacing(const meromorph_result *result);

/* The layered sphere as a mesh (since ABI version 3): the input's vertices in order, then, when
   split_nonmanifold split vertices, their copies; the input's triangles in order, pointing at the
   copies where split.
   Inputs:  result  not NULL
   Outputs (caller-owned; any may be NULL: not filled), with n = meromorph_sphere_vertex_count:
     layered_xyz    3 * n doubles
     triangles      3 * meromorph_triangle_count int32
     source_vertex  n int32: the input vertex each sphere vertex stands for
     layer, component  n int32 each
     branch         n int32: the local degree at a branch point, 0 elsewhere
   Returns: MEROMORPH_OK, or MEROMORPH_ERROR_ARGUMENT for a NULL result. Thread-safe: yes. */
MEROMORPH_API size_t meromorph_sphere_vertex_count(const meromorph_result *result);
MEROMORPH_API meromorph_status meromorph_sphere_mesh(const meromorph_result *result,
                                                     double *layered_xyz, int32_t *triangles,
                                                     int32_t *source_vertex, int32_t *layer,
                                                     int32_t *component, int32_t *branch);

/* Vertices added where the input's triangles could not carry the map (since meromorph 0.3):
   meromorph_added_vertex_count of them (0 when none was; NULL result: 0), numbered after the
   input's vertices in the order given here.
   Inputs:  result  not NULL
   Outputs (caller-owned; any may be NULL: not filled), with a = meromorph_added_vertex_count:
     triangles    a int32: the input's triangle each lies on (inside or on a side)
     barycentric  2 * a doubles: b1, b2 of that triangle's second and third corners
                  (the point is (1 - b1 - b2) * p0 + b1 * p1 + b2 * p2)
     xyz          3 * a doubles: its position
   meromorph_surface_triangles: the written surface's triangles (meromorph_triangle_count of them;
   the input's when no vertex was added): an input triangle that was cut keeps its index with one
   piece, its other pieces come after the input's triangles.
     triangles        3 * meromorph_triangle_count int32 (may be NULL)
     source_triangle  meromorph_triangle_count int32: the input's triangle each is part of (may be
                      NULL)
   Returns: MEROMORPH_OK, or MEROMORPH_ERROR_ARGUMENT for a NULL result. Thread-safe: yes. */
MEROMORPH_API size_t meromorph_added_vertex_count(const meromorph_result *result);
MEROMORPH_API meromorph_status meromorph_added_vertices(const meromorph_result *result,
                                                        int32_t *triangles, double *barycentric,
                                                        double *xyz);
MEROMORPH_API meromorph_status meromorph_surface_triangles(const meromorph_result *result,
                                                           int32_t *triangles,
                                                           int32_t *source_triangle);

/* Branch points: meromorph_branch_point_count of them (NULL result: 0).
   Inputs:  result  not NULL
   Outputs (caller-owned): vertices  count int32, the input's vertex of each (not NULL);
     local_degrees  count int32, e >= 2 (may be NULL).
   Returns: MEROMORPH_OK, or MEROMORPH_ERROR_ARGUMENT for a NULL result or vertices. */
MEROMORPH_API size_t meromorph_branch_point_count(const meromorph_result *result);
MEROMORPH_API meromorph_status meromorph_branch_points(const meromorph_result *result,
                                                       int32_t *vertices, int32_t *local_degrees);

typedef struct meromorph_distortion {
  double angle_error_mean_degrees; /* mean |corner angle on the sphere - on the surface| */
  double quasi_conformal_mean, quasi_conformal_p95, quasi_conformal_max; /* per face, >= 1 */
  int32_t folded_faces_away_from_branch_points;
  int32_t folded_faces;
} meromorph_distortion;
/* Distortion over the input's faces.
   Inputs:  result  not NULL.  Outputs: *distortion (caller-owned, not NULL).
   Returns: MEROMORPH_OK, or MEROMORPH_ERROR_ARGUMENT if a pointer is NULL. */
MEROMORPH_API meromorph_status meromorph_map_distortion(const meromorph_result *result,
                                                        meromorph_distortion *distortion);
/* The same over the faces that touch no branch point (where the map is conformal; at a branch
   point it cannot be): the figures to show first. folded_faces is then the same as
   folded_faces_away_from_branch_points. Since meromorph 0.2. */
MEROMORPH_API meromorph_status meromorph_map_distortion_away_from_branch_points(
    const meromorph_result *result, meromorph_distortion *distortion);
/* The same under its old name (kept for one release). */
MEROMORPH_API meromorph_status meromorph_get_distortion(const meromorph_result *result,
                                                        meromorph_distortion *distortion);

/* The JSON report, as `meromorph param --report` writes it (NULL result: ""); owned by the
   result. */
MEROMORPH_API const char *meromorph_report_json(const meromorph_result *result);

/* Remeshing through the layered sphere (since ABI version 5), as `meromorph remesh`: the mesh is
   mapped (with the Moebius area correction when area_correct is 1), a geodesic sphere with the
   branch values on vertices is lifted through every sheet, evened out and smoothed; the result is
   a closed surface of the same genus.
   Inputs: as meromorph_parameterize_d, and
     target_vertices  about how many vertices the remesh should have; <= 0: the input's count
     area_correct     1 (default of the CLI) or 0
   Outputs: *result: the new remesh, owned by the caller (meromorph_remesh_free); NULL on failure.
   Returns: as meromorph_parameterize_d, and MEROMORPH_ERROR_INPUT when the map is not a valid
     branched cover (nothing to remesh through; meromorph_last_error says why).
   Thread-safe: yes, for different calls at once. */
typedef struct meromorph_remesh_result meromorph_remesh_result;
MEROMORPH_API meromorph_status meromorph_remesh_d(const double *positions, size_t vertex_count,
                                                  const int32_t *triangles, size_t triangle_count,
                                                  const meromorph_options *options,
                                                  int64_t target_vertices, int area_correct,
                                                  meromorph_remesh_result **result);
/* The same with float positions (since meromorph 0.2). */
MEROMORPH_API meromorph_status meromorph_remesh_f(const float *positions, size_t vertex_count,
                                                  const int32_t *triangles, size_t triangle_count,
                                                  const meromorph_options *options,
                                                  int64_t target_vertices, int area_correct,
                                                  meromorph_remesh_result **result);
/* Frees a remesh; NULL is allowed. */
MEROMORPH_API void meromorph_remesh_free(meromorph_remesh_result *result);
/* The remesh's vertex and triangle counts (NULL result: 0). */
MEROMORPH_API size_t meromorph_remesh_vertex_count(const meromorph_remesh_result *result);
MEROMORPH_API size_t meromorph_remesh_triangle_count(const meromorph_remesh_result *result);
/* The remesh, copied into the caller's buffers (any may be NULL: not filled), n vertices, t
   triangles: xyz 3n doubles; triangles 3t int32 (counter-clockwise from outside); layer n int32
   (the sheet each vertex lies on); branch n int32 (the local degree at branch vertices, 0
   elsewhere); sphere_xyz 3n doubles (each vertex's value on the unit sphere).
   Returns: MEROMORPH_OK, or MEROMORPH_ERROR_ARGUMENT for a NULL result. */
MEROMORPH_API meromorph_status meromorph_remesh_mesh(const meromorph_remesh_result *result,
                                                     double *xyz, int32_t *triangles,
                                                     int32_t *layer, int32_t *branch,
                                                     double *sphere_xyz);
/* The JSON report, as `meromorph remesh --report` writes it (the map's report with a "remesh"
   section: Hausdorff distances, angles, valences, folded lifts, ...); NULL result: "". */
MEROMORPH_API const char *meromorph_remesh_report_json(const meromorph_remesh_result *result);
/* One line of the quality figures in words, as the CLI prints them; NULL result: "". */
MEROMORPH_API const char *meromorph_remesh_summary(const meromorph_remesh_result *result);

/* Writing a map's files (a later addition to ABI version 5), as `meromorph param` writes them: the
   surface with per-vertex and per-corner texture coordinates and each vertex's layer as quality
   (.ply, .obj or .off; the surface as written, see meromorph_vertex_count), the layered sphere
   (.ply, with per-vertex layer, branch, source_vertex and component) and the JSON report. Inputs:
   result; surface_path, sphere_path, report_path: where to write (any may be NULL: not written; at
   least one given); protected_paths: protected_count paths that must not be written over (the
   caller's inputs; may be NULL when the count is 0). Outputs: the files, all or none: each is
   written beside its target under a temporary name and moved into place when all are complete.
   Returns: MEROMORPH_OK; MEROMORPH_ERROR_ARGUMENT for a NULL result, no path, an output that is a
            protected path or another output, an unsupported extension; MEROMORPH_ERROR_OUTPUT
            when a file cannot be written (meromorph_last_error gives the system's reason). */
MEROMORPH_API meromorph_status meromorph_write_map(const meromorph_result *result,
                                                   const char *surface_path,
                                                   const char *sphere_path, const char *report_path,
                                                   const char *const *protected_paths,
                                                   size_t protected_count);

/* Reading a mesh file (a later addition to ABI version 5), as the command-line tool reads it: PLY,
   OBJ, OFF or STL, polygons triangulated; nothing is validated or repaired. Inputs:  path  the file
   (its extension says the format) Outputs: *mesh: the mesh read, owned by the caller
   (meromorph_mesh_free); NULL on failure. Returns: MEROMORPH_OK; MEROMORPH_ERROR_ARGUMENT for a
   NULL pointer, a missing file or an unsupported extension; MEROMORPH_ERROR_INPUT for a broken file
   (the message names the line or element). */
typedef struct meromorph_mesh meromorph_mesh;
MEROMORPH_API meromorph_status meromorph_read_mesh(const char *path, meromorph_mesh **mesh);
MEROMORPH_API void meromorph_mesh_free(meromorph_mesh *mesh); /* NULL is allowed */
/* Counts (NULL mesh: 0), and the arrays copied into the caller's buffers (either may be NULL):
   xyz 3n doubles, triangles 3t int32 (0-based, in file order). */
MEROMORPH_API size_t meromorph_mesh_vertex_count(const meromorph_mesh *mesh);
MEROMORPH_API size_t meromorph_mesh_triangle_count(const meromorph_mesh *mesh);
MEROMORPH_API meromorph_status meromorph_mesh_arrays(const meromorph_mesh *mesh, double *xyz,
                                                     int32_t *triangles);
/* What the reader noted (polygons triangulated, ...), joined by "; " ("" when nothing). */
MEROMORPH_API const char *meromorph_mesh_notes(const meromorph_mesh *mesh);

/* The holomorphic 1-forms of a closed, connected, oriented surface (a later addition to ABI version
   5), as `meromorph forms`: the periods, the modulus (genus 1) or the Riemann matrix (genus >= 2)
   and the canonical homology basis it is taken in, residuals and timings, as JSON. Inputs: as
   meromorph_parameterize_d (only options.progress and progress_user are read). Outputs: *result,
   owned by the caller (meromorph_forms_free); NULL on failure. Returns: as meromorph_parameterize_d
   (MEROMORPH_ERROR_INPUT for an open, non-manifold or disconnected mesh, naming where). */
typedef struct meromorph_forms_result meromorph_forms_result;
MEROMORPH_API meromorph_status meromorph_forms_d(const double *positions, size_t vertex_count,
                                                 const int32_t *triangles, size_t triangle_count,
                                                 const meromorph_options *options,
                                                 meromorph_forms_result **result);
MEROMORPH_API void meromorph_forms_free(meromorph_forms_result *result);       /* NULL is allowed */
MEROMORPH_API int meromorph_forms_genus(const meromorph_forms_result *result); /* NULL: -1 */
/* The JSON report, as `meromorph forms --report` writes it; NULL result: "". */
MEROMORPH_API const char *meromorph_forms_report_json(const meromorph_forms_result *result);

/* A match (a later addition to ABI version 5), as `meromorph match`: every vertex of SOURCE on a
   point of TARGET, two closed surfaces of the same genus (0, 1 or 2), through their conformal
   spheres, flat tori or canonical maps. Inputs: both meshes as in meromorph_parameterize_d;
   landmark_pairs: 2 per pair (SOURCE vertex, TARGET vertex), landmark_count pairs (NULL with 0:
   aligned automatically; genus 0 needs three or more); options: only options.progress and
   progress_user are read (may be NULL). Outputs: *result, owned by the caller
   (meromorph_match_free); NULL on failure. Returns: as meromorph_parameterize_d
   (MEROMORPH_ERROR_INPUT when the genera differ or are above 2, a surface has no valid map, or a
   landmark names a vertex that is not there, naming it). */
typedef struct meromorph_match_result meromorph_match_result;
MEROMORPH_API meromorph_status meromorph_match_d(
    const double *source_positions, size_t source_vertex_count, const int32_t *source_triangles,
    size_t source_triangle_count, const double *target_positions, size_t target_vertex_count,
    const int32_t *target_triangles, size_t target_triangle_count, const int32_t *landmark_pairs,
    size_t landmark_count, const meromorph_options *options, meromorph_match_result **result);
MEROMORPH_API void meromorph_match_free(meromorph_match_result *result); /* NULL is allowed */
MEROMORPH_API size_t meromorph_match_vertex_count(const meromorph_match_result *result);
/* Per SOURCE vertex: the TARGET triangle it lies on (its index in target_triangles; -1 where none
   was found), the weights of that triangle's three corners (3 per vertex, summing to 1) and the
   point (3 per vertex). Any pointer may be NULL (not written). */
MEROMORPH_API meromorph_status meromorph_match_points(const meromorph_match_result *result,
                                                      int32_t *target_triangle, double *weights,
                                                      double *positions);
/* Per SOURCE triangle (source_triangle_count of them): the TARGET triangle that holds the image of
   its centre (-1 where none was found) and, per corner, the weights of that triangle's three
   corners that give the corner's matched point (9 per triangle; outside [0, 1] where the corner
   lies on another TARGET triangle). For values given per TARGET triangle corner, such as texture
   coordinates with seams: each SOURCE triangle reads them from one side of a seam. Any pointer
   may be NULL. */
MEROMORPH_API size_t meromorph_match_triangle_count(const meromorph_match_result *result);
MEROMORPH_API meromorph_status meromorph_match_triangles(const meromorph_match_result *result,
                                                         int32_t *target_triangle, double *weights);
/* The JSON report, as `meromorph match --report` writes it (without the inputs); NULL: "". */
MEROMORPH_API const char *meromorph_match_report_json(const meromorph_match_result *result);

#ifdef __cplusplus
}
#endif

#endif /* MEROMORPH_H */
