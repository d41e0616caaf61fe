// The C ABI (meromorph.h) over the core: arrays in, the parameterization out, errors as codes.
#include "meromorph.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "common/errors.h"
#include "forms/holomorphic_pipeline.h"
#include "io/mesh_reader.h"
#include "io/staged_outputs.h"
#include "job/map_files.h"
#include "job/surface_map.h"
#include "maps/parameterization.h"
#include "match/surface_match.h"
#include "mesh/mesh_from_arrays.h"
#include "mesh/repair.h"
#include "remesh/surface_remesh.h"
#include "report/remesh_summary.h"
#include "report/report_json.h"

struct meromorph_result {
  meromorph::Parameterization map;
  std::string report;
  std::string invalid_reasons, advice;
  size_t vertices = 0, triangles = 0;
  // The written surface's triangles (the input's, or with vertices added the cut ones), which
  // are the sphere's too when nothing was split.
  std::vector<std::array<int, 3>> surface_triangles;
  // The caller's vertex positions, for meromorph_write_map (with the added vertices and
  // surface_triangles: the surface as written).
  std::vector<meromorph::Point3> input_positions;
};

struct meromorph_mesh {
  meromorph::MeshArrays arrays;
  std::string notes;
};

struct meromorph_forms_result {
  int genus = -1;
  std::string report;
};

struct meromorph_match_result {
  meromorph::MatchedPoints points;
  std::vector<meromorph::FaceMatch> faces;
  std::string report;
};

struct meromorph_remesh_result {
  std::vector<double> xyz, sphere_xyz;
  std::vector<int32_t> triangles, layer, branch;
  std::string report, summary;
};

namespace {

thread_local std::string last_error;
thread_local std::vector<int32_t> last_remedies;

static_assert(int(meromorph::last_remedy) == MEROMORPH_REMEDY_ADD_VERTICES,
              "meromorph_remedy in meromorph.h lists every Remedy of common/remedy.h");

meromorph_status fail(meromorph_status status, const std::string &message,
                      const std::vector<meromorph::Remedy> &remedies = {}) {
  last_error = message;
  last_remedies.clear();
  for (meromorph::Remedy remedy : remedies)
    last_remedies.push_back(int32_t(remedy));
  return status;
}

// What is wrong with `options` for a mesh of these sizes ("" when nothing is).
std::string check_options(const meromorph_options &options, size_t vertex_count,
                          size_t triangle_count) {
  if (options.uv_kind != 0 && options.uv_kind != 1)
    return "options.uv_kind is " + std::to_string(options.uv_kind) +
           "; use 0 (spherical) or 1 (stereographic)";
  if (options.mobius != 0 && options.mobius != 1)
    return "options.mobius is " + std::to_string(options.mobius) + "; use 0 or 1";
  if (options.close_holes != 0 && options.close_holes != 1)
    return "options.close_holes is " + std::to_string(options.close_holes) + "; use 0 or 1";
  if (options.split_nonmanifold != 0 && options.split_nonmanifold != 1)
    return "options.split_nonmanifold is " + std::to_string(options.split_nonmanifold) +
           "; use 0 or 1";
  if (options.pack_uv != 0 && options.pack_uv != 1)
    return "options.pack_uv is " + std::to_string(options.pack_uv) + "; use 0 or 1";
  if (options.strict != 0 && options.strict != 1)
    return "options.strict is " + std::to_string(options.strict) + "; use 0 or 1";
  if (options.add_vertices != 0 && options.add_vertices != 1)
    return "options.add_vertices is " + std::to_string(options.add_vertices) + "; use 0 or 1";
  if (!(options.remesh_edge_length >= 0) || !(options.remesh_edge_length < 1e300))
    return "options.remesh_edge_length is " + std::to_string(options.remesh_edge_length) +
           "; use 0 (not given) or a length in the input's units";
  if (!(options.remesh_max_error >= 0) || !(options.remesh_max_error < 1))
    return "options.remesh_max_error is " + std::to_string(options.remesh_max_error) +
           "; use 0 (not given) or a fraction of the diagonal below 1";
  if (options.area_correct != 0 && options.area_correct != 1)
    return "options.area_correct is " + std::to_string(options.area_correct) + "; use 0 or 1";
  if (options.origin_vertex < -1 || (long long)options.origin_vertex >= (long long)vertex_count)
    return "options.origin_vertex is " + std::to_string(options.origin_vertex) +
           "; use -1 (automatic) or a vertex from 0 to " + std::to_string(vertex_count - 1);
  if (options.pole_face < -1 || (long long)options.pole_face >= (long long)triangle_count)
    return "options.pole_face is " + std::to_string(options.pole_face) +
           "; use -1 (automatic) or a triangle from 0 to " + std::to_string(triangle_count - 1);
  for (int k = 0; k < 2; ++k)
    if (options.form_pair[k] < -1)
      return "options.form_pair[" + std::to_string(k) + "] is " +
             std::to_string(options.form_pair[k]) + "; use -1 (a generic pair) or a form index";
  if (!(options.layer_gap >= 0 && options.layer_gap <= 1e6))
    return "options.layer_gap must be a number from 0 to 1e6";
  return "";
}

// The caller's pointers and sizes: MEROMORPH_OK when they can be read, else the status and
// the problem.
template <typename Scalar>
std::pair<meromorph_status, std::string> check_arrays(const Scalar *positions, size_t vertex_count,
                                                      const int32_t *triangles,
                                                      size_t triangle_count) {
  if (!positions && vertex_count) return {MEROMORPH_ERROR_ARGUMENT, "positions pointer is NULL"};
  if (!triangles && triangle_count) return {MEROMORPH_ERROR_ARGUMENT, "triangles pointer is NULL"};
  if (vertex_count == 0 || triangle_count == 0)
    return {MEROMORPH_ERROR_INPUT,
            "the mesh has no " + std::string(vertex_count ? "faces" : "vertices")};
  if (vertex_count > size_t(INT32_MAX) || triangle_count > size_t(INT32_MAX) / 3)
    return {MEROMORPH_ERROR_ARGUMENT,
            "the mesh has more vertices or triangles than 32-bit indices can address"};
  return {MEROMORPH_OK, ""};
}

// The caller's options (of this or an earlier version) over the defaults, in `settings`.
std::string read_options(const meromorph_options *options, meromorph_options &settings) {
  meromorph_default_options(&settings);
  if (!options) return "";
  // Version 1 ended before close_holes, version 2 before split_nonmanifold, version 5 (up to
  // meromorph 0.1) before area_correct, and 0.2 as first built, before strict; version 5 with
  // strict before add_vertices; meromorph 0.3 before remesh_edge_length.
  const size_t known_sizes[] = {offsetof(meromorph_options, close_holes),
                                offsetof(meromorph_options, split_nonmanifold),
                                offsetof(meromorph_options, area_correct),
                                offsetof(meromorph_options, strict),
                                offsetof(meromorph_options, add_vertices),
                                offsetof(meromorph_options, remesh_edge_length),
                                sizeof(meromorph_options)};
  if (std::find(std::begin(known_sizes), std::end(known_sizes), options->struct_size) ==
      std::end(known_sizes))
    return "options.struct_size is " + std::to_string(options->struct_size) +
           ", which matches no version of meromorph_options (this library's is " +
           std::to_string(sizeof(meromorph_options)) +
           "): initialize the options with meromorph_default_options";
  settings.add_vertices = 0; // an older caller counts on the input's vertices and triangles
  std::memcpy(&settings, options, options->struct_size);
  settings.struct_size = sizeof(meromorph_options);
  return "";
}

meromorph::ParameterizeOptions core_options(const meromorph_options &settings) {
  meromorph::ParameterizeOptions parameters;
  parameters.uv_kind =
      settings.uv_kind == 1 ? meromorph::UvKind::stereographic : meromorph::UvKind::spherical;
  parameters.mobius = settings.mobius != 0;
  parameters.origin_vertex = settings.origin_vertex;
  parameters.form_pair = {settings.form_pair[0], settings.form_pair[1]};
  parameters.layer_gap = settings.layer_gap;
  parameters.pole_face = settings.pole_face;
  parameters.close_holes = settings.close_holes != 0;
  parameters.split_nonmanifold = settings.split_nonmanifold != 0;
  parameters.add_vertices = settings.add_vertices != 0;
  if (settings.strict != 0) meromorph::refuse_instead(parameters);
  parameters.pack_uv = settings.pack_uv != 0;
  parameters.area_correct = settings.area_correct != 0;
  return parameters;
}

meromorph::Progress core_progress(const meromorph_options &settings) {
  if (!settings.progress) return {};
  const meromorph_progress_fn callback = settings.progress;
  void *user = settings.progress_user;
  return meromorph::Progress([callback, user](double fraction, const std::string &stage) {
    return callback(fraction, stage.c_str(), user) != 0;
  });
}

template <typename Scalar>
meromorph::MeshArrays mesh_arrays(const Scalar *positions, size_t vertex_count,
                                  const int32_t *triangles, size_t triangle_count) {
  meromorph::MeshArrays arrays;
  arrays.positions.reserve(vertex_count);
  for (size_t v = 0; v < vertex_count; ++v)
    arrays.positions.emplace_back(double(positions[3 * v]), double(positions[3 * v + 1]),
                                  double(positions[3 * v + 2]));
  arrays.triangles.reserve(triangle_count);
  for (size_t t = 0; t < triangle_count; ++t)
    arrays.triangles.push_back({triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]});
  return arrays;
}

// The map of `arrays` with its report; throws what the core throws.
std::unique_ptr<meromorph_result> map_result(meromorph::MeshArrays &arrays,
                                             const meromorph_options &settings) {
  using namespace meromorph;
  // The C++ entry point (job/surface_map.h) over the arrays as they are (no copy).
  using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  using Corners = Eigen::Matrix<int32_t, Eigen::Dynamic, 3, Eigen::RowMajor>;
  static_assert(sizeof(Point3) == 3 * sizeof(double) && sizeof(arrays.triangles[0]) == 12);
  const Eigen::Map<const Positions> V(reinterpret_cast<const double *>(arrays.positions.data()),
                                      Eigen::Index(arrays.positions.size()), 3);
  const Eigen::Map<const Corners> F(reinterpret_cast<const int32_t *>(arrays.triangles.data()),
                                    Eigen::Index(arrays.triangles.size()), 3);
  auto out = std::make_unique<meromorph_result>();
  out->map = parameterize_arrays(V, F, core_options(settings), core_progress(settings));
  nlohmann::json report = parameterization_json(out->map);
  report["version"] = MEROMORPH_VERSION;
  out->report = json_text(report);
  out->invalid_reasons = join_phrases(out->map.invalid);
  std::vector<std::string> causes;
  for (const Advice &advice : out->map.advice)
    causes.push_back(advice.cause);
  out->advice = join_phrases(causes);
  out->vertices = arrays.positions.size() + out->map.added_vertices.size();
  out->input_positions = std::move(arrays.positions); // (the map no longer reads them)
  if (!out->map.surface_faces.empty()) arrays.triangles = out->map.surface_faces;
  out->triangles = arrays.triangles.size();
  out->surface_triangles = std::move(arrays.triangles);
  return out;
}

// Runs `job`, turning what it throws into a status and the thread's last error.
template <typename Job> meromorph_status guarded(Job &&job) {
  using namespace meromorph;
  try {
    job();
    return MEROMORPH_OK;
  } catch (const Cancelled &) {
    return fail(MEROMORPH_ERROR_CANCELLED, "cancelled by the progress callback");
  } catch (const ArgumentError &error) {
    return fail(MEROMORPH_ERROR_ARGUMENT, error.what(), error.remedies());
  } catch (const InputError &error) {
    return fail(MEROMORPH_ERROR_INPUT, error.what(), error.remedies());
  } catch (const WriteError &error) {
    return fail(MEROMORPH_ERROR_OUTPUT, error.what());
  } catch (const std::bad_alloc &) {
    return fail(MEROMORPH_ERROR_INTERNAL, "out of memory");
  } catch (const std::exception &error) {
    return fail(MEROMORPH_ERROR_INTERNAL, error.what());
  } catch (...) {
    return fail(MEROMORPH_ERROR_INTERNAL, "unknown internal failure");
  }
}

// The checks every entry point makes before any work: the result pointer, the arrays and the
// options (read into `settings`).
template <typename Scalar, typename Result>
meromorph_status check_call(const Scalar *positions, size_t vertex_count, const int32_t *triangles,
                            size_t triangle_count, const meromorph_options *options,
                            Result **result, meromorph_options &settings) {
  last_error.clear();
  last_remedies.clear();
  if (!result) return fail(MEROMORPH_ERROR_ARGUMENT, "result pointer is NULL");
  *result = nullptr;
  if (auto [status, problem] = check_arrays(positions, vertex_count, triangles, triangle_count);
      status != MEROMORPH_OK)
    return fail(status, problem);
  if (const std::string problem = read_options(options, settings); !problem.empty())
    return fail(MEROMORPH_ERROR_ARGUMENT, problem);
  if (const std::string problem = check_options(settings, vertex_count, triangle_count);
      !problem.empty())
    return fail(MEROMORPH_ERROR_ARGUMENT, problem);
  return MEROMORPH_OK;
}

// An entry point: the checks of check_call, then `make(arrays, settings)` (the caller's mesh as
// arrays) into *result, what it throws turned into a status by guarded.
template <typename Scalar, typename Result, typename Make>
meromorph_status checked_call(const Scalar *positions, size_t vertex_count,
                              const int32_t *triangles, size_t triangle_count,
                              const meromorph_options *options, Result **result, Make &&make) {
  meromorph_options settings;
  if (const meromorph_status status =
          check_call(positions, vertex_count, triangles, triangle_count, options, result, settings);
      status != MEROMORPH_OK)
    return status;
  return guarded([&] {
    meromorph::MeshArrays arrays = mesh_arrays(positions, vertex_count, triangles, triangle_count);
    *result = make(arrays, settings).release();
  });
}

template <typename Scalar>
meromorph_status parameterize(const Scalar *positions, size_t vertex_count,
                              const int32_t *triangles, size_t triangle_count,
                              const meromorph_options *options, meromorph_result **result) {
  return checked_call(positions, vertex_count, triangles, triangle_count, options, result,
                      map_result);
}

// The remesh of `arrays` with its report and summary; throws what the core throws.
std::unique_ptr<meromorph_remesh_result> remesh_result(meromorph::MeshArrays &arrays,
                                                       const meromorph_options &settings,
                                                       int64_t target_vertices, bool area_correct) {
  using namespace meromorph;
  Mesh mesh;
  mesh_from_arrays(arrays, mesh);
  // A new triangulation: the safe repairs first (mesh/repair.h), as `meromorph remesh` makes them
  // (strict: none, and the defects are refused).
  const std::vector<std::string> repairs =
      settings.strict ? std::vector<std::string>{} : repair_mesh(mesh);
  ParameterizeOptions parameters = core_options(settings);
  parameters.area_correct = area_correct;
  parameters.set_aside_defects = false; // the remesh samples the input's own faces
  const Progress progress = core_progress(settings);
  const Parameterization map = parameterize_surface(mesh, parameters, progress.range(0.0, 0.6));
  if (!map.valid)
    throw InputError("no valid map on this triangulation, so nothing to remesh through: " +
                     join_phrases(map.invalid));
  RemeshOptions options;
  options.vertices = target_vertices > 0 ? (long long)target_vertices : -1;
  if (settings.remesh_edge_length > 0) options.edge_length = settings.remesh_edge_length;
  if (settings.remesh_max_error > 0) options.max_error = settings.remesh_max_error;
  SurfaceRemesh remesh;
  add_written_vertices(map, mesh); // the surface the map was written on
  remesh_through_sphere(mesh, map, options, progress.range(0.6, 1.0), remesh);
  auto out = std::make_unique<meromorph_remesh_result>();
  for (const auto &vertex : remesh.mesh.vert)
    for (int axis = 0; axis < 3; ++axis)
      out->xyz.push_back(double(vertex.cP()[axis]));
  for (const auto &face : remesh.mesh.face)
    for (int corner = 0; corner < 3; ++corner)
      out->triangles.push_back(int32_t(index_of(remesh.mesh, face.cV(corner))));
  out->layer.assign(remesh.layer.begin(), remesh.layer.end());
  out->branch.assign(remesh.local_degree.begin(), remesh.local_degree.end());
  for (const Eigen::Vector3d &p : remesh.sphere)
    out->sphere_xyz.insert(out->sphere_xyz.end(), {p.x(), p.y(), p.z()});
  nlohmann::json report = parameterization_json(map);
  report["remesh"] = remesh_json(remesh);
  report["repairs"] = repairs;
  report["version"] = MEROMORPH_VERSION;
  out->report = json_text(report);
  out->summary = remesh_summary("the mesh", map, remesh);
  return out;
}

template <typename Scalar>
meromorph_status remesh(const Scalar *positions, size_t vertex_count, const int32_t *triangles,
                        size_t triangle_count, const meromorph_options *options,
                        int64_t target_vertices, int area_correct,
                        meromorph_remesh_result **result) {
  return checked_call(positions, vertex_count, triangles, triangle_count, options, result,
                      [&](meromorph::MeshArrays &arrays, const meromorph_options &settings) {
                        if (area_correct != 0 && area_correct != 1)
                          throw meromorph::ArgumentError(
                              "area_correct is " + std::to_string(area_correct) + "; use 0 or 1");
                        if (target_vertices > meromorph::max_remesh_vertices ||
                            (target_vertices > 0 && target_vertices < 12))
                          throw meromorph::ArgumentError(
                              "target_vertices is " + std::to_string(target_vertices) +
                              "; give 12 to " + std::to_string(meromorph::max_remesh_vertices) +
                              ", or 0 for the input's vertex count");
                        return remesh_result(arrays, settings, target_vertices, area_correct == 1);
                      });
}

// The forms of `arrays` with their report; throws what the core throws.
std::unique_ptr<meromorph_forms_result> forms_result(meromorph::MeshArrays &arrays,
                                                     const meromorph_options &settings) {
  using namespace meromorph;
  Mesh mesh;
  mesh_from_arrays(arrays, mesh);
  const HolomorphicForms forms =
      compute_holomorphic_forms(mesh, SolverKind::cholmod, core_progress(settings));
  auto out = std::make_unique<meromorph_forms_result>();
  out->genus = forms.genus;
  nlohmann::json report = holomorphic_forms_json(forms, SolverKind::cholmod);
  report["version"] = MEROMORPH_VERSION;
  out->report = json_text(report);
  return out;
}

// The files of `result` (meromorph_write_map).
void write_map_files(const meromorph_result &result, const char *surface_path,
                     const char *sphere_path, const char *report_path,
                     const char *const *protected_paths, size_t protected_count) {
  using namespace meromorph;
  std::vector<std::string> inputs;
  for (size_t k = 0; k < protected_count; ++k)
    if (protected_paths[k]) inputs.emplace_back(protected_paths[k]);
  StagedOutputs outputs(inputs);
  MeshFormat surface_format = MeshFormat::ply;
  std::string surface_file, sphere_file, report_file;
  if (surface_path) {
    surface_format = output_format(surface_path);
    if (surface_format == MeshFormat::stl)
      throw ArgumentError(std::string(surface_path) +
                          ": an STL file cannot hold texture coordinates, which are the map: "
                          "write .ply, .obj or .off");
    surface_file = outputs.add(surface_path);
  }
  if (sphere_path) {
    if (output_format(sphere_path) != MeshFormat::ply)
      throw ArgumentError(std::string(sphere_path) +
                          ": the layered sphere is written as PLY (.ply)");
    sphere_file = outputs.add(sphere_path);
  }
  if (report_path) report_file = outputs.add(report_path);
  // The surface as written (as add_written_vertices makes it from the input mesh).
  MeshArrays written;
  written.positions = result.input_positions;
  for (const AddedVertex &added : result.map.added_vertices)
    written.positions.emplace_back(added.position[0], added.position[1], added.position[2]);
  written.triangles = result.surface_triangles;
  Mesh mesh;
  mesh_from_arrays(written, mesh);
  outputs.writing([&] {
    if (surface_path) write_surface(mesh, result.map, surface_format, surface_file);
    if (sphere_path) write_layered_sphere(mesh, result.map, sphere_file);
    if (report_path) write_text_file(report_file, result.report + "\n");
    outputs.commit();
  });
}

} // namespace

extern "C" {

int meromorph_abi_version(void) {
  return MEROMORPH_ABI_VERSION;
}
const char *meromorph_version(void) {
  return MEROMORPH_VERSION;
}
const char *meromorph_last_error(void) {
  return last_error.c_str();
}
int meromorph_last_error_remedies(int32_t *remedies, int capacity) {
  if (remedies)
    for (int i = 0; i < capacity && size_t(i) < last_remedies.size(); ++i)
      remedies[i] = last_remedies[size_t(i)];
  return int(last_remedies.size());
}

void meromorph_default_options(meromorph_options *options) {
  if (!options) return;
  std::memset(options, 0, sizeof(*options));
  options->struct_size = sizeof(meromorph_options);
  options->uv_kind = 0;
  options->mobius = 1;
  options->origin_vertex = -1;
  options->form_pair[0] = -1;
  options->form_pair[1] = -1;
  options->layer_gap = 0.0;
  options->pole_face = -1;
  options->close_holes = 1;
  options->split_nonmanifold = 1;
  options->add_vertices = 1;
}

meromorph_status meromorph_parameterize_d(const double *positions, size_t vertex_count,
                                          const int32_t *triangles, size_t triangle_count,
                                          const meromorph_options *options,
                                          meromorph_result **result) {
  return parameterize(positions, vertex_count, triangles, triangle_count, options, result);
}

meromorph_status meromorph_parameterize_f(const float *positions, size_t vertex_count,
                                          const int32_t *triangles, size_t triangle_count,
                                          const meromorph_options *options,
                                          meromorph_result **result) {
  return parameterize(positions, vertex_count, triangles, triangle_count, options, result);
}

void meromorph_result_free(meromorph_result *result) {
  delete result;
}

size_t meromorph_vertex_count(const meromorph_result *r) {
  return r ? r->vertices : 0;
}
size_t meromorph_triangle_count(const meromorph_result *r) {
  return r ? r->triangles : 0;
}
int meromorph_genus(const meromorph_result *r) {
  return r ? r->map.genus : -1;
}
int meromorph_degree(const meromorph_result *r) {
  return r ? r->map.degree : -1;
}
int meromorph_riemann_hurwitz_ok(const meromorph_result *r) {
  return r ? r->map.riemann_hurwitz_ok : 0;
}
int meromorph_map_valid(const meromorph_result *r) {
  return r ? r->map.valid : 0;
}
const char *meromorph_invalid_reasons(const meromorph_result *r) {
  return r ? r->invalid_reasons.c_str() : "";
}
const char *meromorph_advice(const meromorph_result *r) {
  return r ? r->advice.c_str() : "";
}
int meromorph_advice_count(const meromorph_result *r) {
  return r ? int(r->map.advice.size()) : 0;
}
const char *meromorph_advice_cause(const meromorph_result *r, int index) {
  if (!r || index < 0 || size_t(index) >= r->map.advice.size()) return "";
  return r->map.advice[size_t(index)].cause.c_str();
}
int meromorph_advice_remedy(const meromorph_result *r, int index) {
  if (!r || index < 0 || size_t(index) >= r->map.advice.size()) return 0;
  return int(r->map.advice[size_t(index)].remedy);
}

#define MEROMORPH_CHECK(result, buffer)                                                            \
  if (!(result)) return fail(MEROMORPH_ERROR_ARGUMENT, "result is NULL");                          \
  if (!(buffer)) return fail(MEROMORPH_ERROR_ARGUMENT, "output buffer is NULL")

meromorph_status meromorph_sphere_positions(const meromorph_result *r, double *xyz) {
  MEROMORPH_CHECK(r, xyz);
  for (size_t v = 0; v < r->vertices; ++v)
    for (int k = 0; k < 3; ++k)
      xyz[3 * v + k] = r->map.sphere[v][k];
  return MEROMORPH_OK;
}

meromorph_status meromorph_layered_positions(const meromorph_result *r, double *xyz) {
  MEROMORPH_CHECK(r, xyz);
  for (size_t v = 0; v < r->vertices; ++v)
    for (int k = 0; k < 3; ++k)
      xyz[3 * v + k] = r->map.layered[v][k];
  return MEROMORPH_OK;
}

meromorph_status meromorph_vertex_uvs(const meromorph_result *r, double *uv) {
  MEROMORPH_CHECK(r, uv);
  for (size_t v = 0; v < r->vertices; ++v)
    for (int k = 0; k < 2; ++k)
      uv[2 * v + k] = r->map.uv.vertex[v][k];
  return MEROMORPH_OK;
}

meromorph_status meromorph_corner_uvs(const meromorph_result *r, double *uv) {
  MEROMORPH_CHECK(r, uv);
  for (size_t f = 0; f < r->map.uv.wedge.size(); ++f)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 2; ++k)
        uv[6 * f + 2 * c + k] = r->map.uv.wedge[f][c][k];
  return MEROMORPH_OK;
}

meromorph_status meromorph_layers(const meromorph_result *r, int32_t *layer) {
  MEROMORPH_CHECK(r, layer);
  for (size_t v = 0; v < r->vertices; ++v)
    layer[v] = r->map.sheets.vertex_layer[v];
  return MEROMORPH_OK;
}

meromorph_status meromorph_vertex_components(const meromorph_result *r, int32_t *component) {
  MEROMORPH_CHECK(r, component);
  const std::vector<int> &part = r->map.vertex_component;
  for (size_t v = 0; v < r->vertices; ++v)
    component[v] = part.empty() ? 0 : part[v];
  return MEROMORPH_OK;
}
double meromorph_component_spacing(const meromorph_result *r) {
  return r ? r->map.component_spacing : 0.0;
}

size_t meromorph_sphere_vertex_count(const meromorph_result *r) {
  return r ? r->map.layered.size() : 0;
}

meromorph_status meromorph_sphere_mesh(const meromorph_result *r, double *layered_xyz,
                                       int32_t *triangles, int32_t *source_vertex, int32_t *layer,
                                       int32_t *component, int32_t *branch) {
  if (!r) return fail(MEROMORPH_ERROR_ARGUMENT, "result is NULL");
  const meromorph::Parameterization &map = r->map;
  const size_t count = map.layered.size();
  for (size_t v = 0; v < count; ++v) {
    if (layered_xyz)
      for (int k = 0; k < 3; ++k)
        layered_xyz[3 * v + k] = map.layered[v][k];
    if (source_vertex)
      source_vertex[v] =
          map.sphere_source_vertex.empty() ? int32_t(v) : map.sphere_source_vertex[v];
    if (layer) layer[v] = map.sheets.vertex_layer[v];
    if (component) component[v] = map.vertex_component.empty() ? 0 : map.vertex_component[v];
    if (branch) branch[v] = map.branch_flag[v];
  }
  if (triangles) {
    const auto &faces = map.sphere_faces.empty() ? r->surface_triangles : map.sphere_faces;
    for (size_t t = 0; t < faces.size(); ++t)
      for (int k = 0; k < 3; ++k)
        triangles[3 * t + k] = faces[t][k];
  }
  return MEROMORPH_OK;
}

size_t meromorph_added_vertex_count(const meromorph_result *r) {
  return r ? r->map.added_vertices.size() : 0;
}

meromorph_status meromorph_added_vertices(const meromorph_result *r, int32_t *triangles,
                                          double *barycentric, double *xyz) {
  if (!r) return fail(MEROMORPH_ERROR_ARGUMENT, "result is NULL");
  for (size_t k = 0; k < r->map.added_vertices.size(); ++k) {
    const meromorph::AddedVertex &added = r->map.added_vertices[k];
    if (triangles) triangles[k] = added.face;
    if (barycentric) barycentric[2 * k] = added.b1, barycentric[2 * k + 1] = added.b2;
    if (xyz)
      for (int axis = 0; axis < 3; ++axis)
        xyz[3 * k + size_t(axis)] = added.position[axis];
  }
  return MEROMORPH_OK;
}

meromorph_status meromorph_surface_triangles(const meromorph_result *r, int32_t *triangles,
                                             int32_t *source_triangle) {
  if (!r) return fail(MEROMORPH_ERROR_ARGUMENT, "result is NULL");
  const auto &faces = r->surface_triangles;
  for (size_t t = 0; t < r->triangles; ++t) {
    if (triangles)
      for (int k = 0; k < 3; ++k)
        triangles[3 * t + size_t(k)] = faces[t][size_t(k)];
    if (source_triangle)
      source_triangle[t] =
          r->map.surface_face_source.empty() ? int32_t(t) : r->map.surface_face_source[t];
  }
  return MEROMORPH_OK;
}

size_t meromorph_branch_point_count(const meromorph_result *r) {
  return r ? r->map.branch_points.size() : 0;
}

meromorph_status meromorph_branch_points(const meromorph_result *r, int32_t *vertices,
                                         int32_t *degrees) {
  MEROMORPH_CHECK(r, vertices);
  for (size_t i = 0; i < r->map.branch_points.size(); ++i) {
    vertices[i] = r->map.branch_points[i].vertex;
    if (degrees) degrees[i] = r->map.branch_points[i].local_degree;
  }
  return MEROMORPH_OK;
}

meromorph_status meromorph_get_distortion(const meromorph_result *r, meromorph_distortion *d) {
  return meromorph_map_distortion(r, d);
}

namespace {

void copy_distortion(const meromorph::QualityStatistics &figures, int folded_away,
                     meromorph_distortion *d) {
  d->angle_error_mean_degrees = figures.angle_error_mean_degrees;
  d->quasi_conformal_mean = figures.quasi_conformal_mean;
  d->quasi_conformal_p95 = figures.quasi_conformal_p95;
  d->quasi_conformal_max = figures.quasi_conformal_max;
  d->folded_faces_away_from_branch_points = folded_away;
  d->folded_faces = figures.folded_faces;
}

} // namespace

meromorph_status meromorph_map_distortion(const meromorph_result *r, meromorph_distortion *d) {
  MEROMORPH_CHECK(r, d);
  copy_distortion(r->map.quality.overall, r->map.quality.away_from_branch_points.folded_faces, d);
  return MEROMORPH_OK;
}

meromorph_status meromorph_map_distortion_away_from_branch_points(const meromorph_result *r,
                                                                  meromorph_distortion *d) {
  MEROMORPH_CHECK(r, d);
  const auto &away = r->map.quality.away_from_branch_points;
  copy_distortion(away, away.folded_faces, d);
  return MEROMORPH_OK;
}

const char *meromorph_report_json(const meromorph_result *r) {
  return r ? r->report.c_str() : "";
}

meromorph_status meromorph_remesh_d(const double *positions, size_t vertex_count,
                                    const int32_t *triangles, size_t triangle_count,
                                    const meromorph_options *options, int64_t target_vertices,
                                    int area_correct, meromorph_remesh_result **result) {
  return remesh(positions, vertex_count, triangles, triangle_count, options, target_vertices,
                area_correct, result);
}

meromorph_status meromorph_remesh_f(const float *positions, size_t vertex_count,
                                    const int32_t *triangles, size_t triangle_count,
                                    const meromorph_options *options, int64_t target_vertices,
                                    int area_correct, meromorph_remesh_result **result) {
  return remesh(positions, vertex_count, triangles, triangle_count, options, target_vertices,
                area_correct, result);
}

void meromorph_remesh_free(meromorph_remesh_result *r) {
  delete r;
}

size_t meromorph_remesh_vertex_count(const meromorph_remesh_result *r) {
  return r ? r->layer.size() : 0;
}

size_t meromorph_remesh_triangle_count(const meromorph_remesh_result *r) {
  return r ? r->triangles.size() / 3 : 0;
}

meromorph_status meromorph_remesh_mesh(const meromorph_remesh_result *r, double *xyz,
                                       int32_t *triangles, int32_t *layer, int32_t *branch,
                                       double *sphere_xyz) {
  if (!r) return fail(MEROMORPH_ERROR_ARGUMENT, "result pointer is NULL");
  if (xyz) std::copy(r->xyz.begin(), r->xyz.end(), xyz);
  if (triangles) std::copy(r->triangles.begin(), r->triangles.end(), triangles);
  if (layer) std::copy(r->layer.begin(), r->layer.end(), layer);
  if (branch) std::copy(r->branch.begin(), r->branch.end(), branch);
  if (sphere_xyz) std::copy(r->sphere_xyz.begin(), r->sphere_xyz.end(), sphere_xyz);
  return MEROMORPH_OK;
}

const char *meromorph_remesh_report_json(const meromorph_remesh_result *r) {
  return r ? r->report.c_str() : "";
}

const char *meromorph_remesh_summary(const meromorph_remesh_result *r) {
  return r ? r->summary.c_str() : "";
}

meromorph_status meromorph_write_map(const meromorph_result *r, const char *surface_path,
                                     const char *sphere_path, const char *report_path,
                                     const char *const *protected_paths, size_t protected_count) {
  last_error.clear();
  last_remedies.clear();
  if (!r) return fail(MEROMORPH_ERROR_ARGUMENT, "result pointer is NULL");
  if (!surface_path && !sphere_path && !report_path)
    return fail(MEROMORPH_ERROR_ARGUMENT,
                "no file to write: give a surface, sphere or report path");
  if (!protected_paths && protected_count)
    return fail(MEROMORPH_ERROR_ARGUMENT, "protected_paths pointer is NULL");
  return guarded([&] {
    write_map_files(*r, surface_path, sphere_path, report_path, protected_paths, protected_count);
  });
}

meromorph_status meromorph_read_mesh(const char *path, meromorph_mesh **mesh) {
  last_error.clear();
  last_remedies.clear();
  if (!mesh) return fail(MEROMORPH_ERROR_ARGUMENT, "mesh pointer is NULL");
  *mesh = nullptr;
  if (!path) return fail(MEROMORPH_ERROR_ARGUMENT, "path is NULL");
  return guarded([&] {
    meromorph::Mesh read;
    const meromorph::MeshSource source = meromorph::read_mesh(path, read);
    auto out = std::make_unique<meromorph_mesh>();
    out->arrays = meromorph::arrays_from_mesh(read);
    out->notes = meromorph::join_phrases(source.notes);
    *mesh = out.release();
  });
}

void meromorph_mesh_free(meromorph_mesh *mesh) {
  delete mesh;
}

size_t meromorph_mesh_vertex_count(const meromorph_mesh *mesh) {
  return mesh ? mesh->arrays.positions.size() : 0;
}

size_t meromorph_mesh_triangle_count(const meromorph_mesh *mesh) {
  return mesh ? mesh->arrays.triangles.size() : 0;
}

meromorph_status meromorph_mesh_arrays(const meromorph_mesh *mesh, double *xyz,
                                       int32_t *triangles) {
  if (!mesh) return fail(MEROMORPH_ERROR_ARGUMENT, "mesh pointer is NULL");
  if (xyz)
    for (const meromorph::Point3 &p : mesh->arrays.positions)
      for (int axis = 0; axis < 3; ++axis)
        *xyz++ = double(p[axis]);
  if (triangles)
    for (const auto &triangle : mesh->arrays.triangles)
      triangles = std::copy(triangle.begin(), triangle.end(), triangles);
  return MEROMORPH_OK;
}

const char *meromorph_mesh_notes(const meromorph_mesh *mesh) {
  return mesh ? mesh->notes.c_str() : "";
}

meromorph_status meromorph_forms_d(const double *positions, size_t vertex_count,
                                   const int32_t *triangles, size_t triangle_count,
                                   const meromorph_options *options,
                                   meromorph_forms_result **result) {
  return checked_call(positions, vertex_count, triangles, triangle_count, options, result,
                      forms_result);
}

void meromorph_forms_free(meromorph_forms_result *result) {
  delete result;
}

int meromorph_forms_genus(const meromorph_forms_result *result) {
  return result ? result->genus : -1;
}

const char *meromorph_forms_report_json(const meromorph_forms_result *result) {
  return result ? result->report.c_str() : "";
}

meromorph_status meromorph_match_d(const double *source_positions, size_t source_vertex_count,
                                   const int32_t *source_triangles, size_t source_triangle_count,
                                   const double *target_positions, size_t target_vertex_count,
                                   const int32_t *target_triangles, size_t target_triangle_count,
                                   const int32_t *landmark_pairs, size_t landmark_count,
                                   const meromorph_options *options,
                                   meromorph_match_result **result) {
  using namespace meromorph;
  meromorph_options settings;
  if (const meromorph_status status =
          check_call(source_positions, source_vertex_count, source_triangles, source_triangle_count,
                     options, result, settings);
      status != MEROMORPH_OK)
    return status;
  if (auto [status, problem] = check_arrays(target_positions, target_vertex_count, target_triangles,
                                            target_triangle_count);
      status != MEROMORPH_OK)
    return fail(status, "target: " + problem);
  if (landmark_count > 0 && !landmark_pairs)
    return fail(MEROMORPH_ERROR_ARGUMENT, "landmark_pairs is NULL with landmark_count > 0");
  return guarded([&] {
    MatchOptions match_options;
    for (size_t k = 0; k < landmark_count; ++k)
      match_options.landmarks.emplace_back(landmark_pairs[2 * k], landmark_pairs[2 * k + 1]);
    MeshArrays source_arrays =
        mesh_arrays(source_positions, source_vertex_count, source_triangles, source_triangle_count);
    MeshArrays target_arrays =
        mesh_arrays(target_positions, target_vertex_count, target_triangles, target_triangle_count);
    Mesh source, target;
    mesh_from_arrays(source_arrays, source);
    mesh_from_arrays(target_arrays, target);
    const SurfaceMatch match =
        match_surfaces(source, target, match_options, core_progress(settings));
    auto out = std::make_unique<meromorph_match_result>();
    out->points = match.forward;
    out->faces = match.faces;
    nlohmann::json report = match_json(match, landmark_count);
    report["version"] = MEROMORPH_VERSION;
    out->report = json_text(report);
    *result = out.release();
  });
}

void meromorph_match_free(meromorph_match_result *result) {
  delete result;
}

size_t meromorph_match_vertex_count(const meromorph_match_result *result) {
  return result ? result->points.target_face.size() : 0;
}

size_t meromorph_match_triangle_count(const meromorph_match_result *result) {
  return result ? result->faces.size() : 0;
}

meromorph_status meromorph_match_triangles(const meromorph_match_result *result,
                                           int32_t *target_triangle, double *weights) {
  if (!result) return fail(MEROMORPH_ERROR_ARGUMENT, "result is NULL");
  for (size_t f = 0; f < result->faces.size(); ++f) {
    const meromorph::FaceMatch &face = result->faces[f];
    if (target_triangle) target_triangle[f] = face.target_face;
    if (weights)
      for (size_t k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
          weights[9 * f + 3 * k + size_t(j)] = face.weights[k][j];
  }
  return MEROMORPH_OK;
}

const char *meromorph_match_report_json(const meromorph_match_result *result) {
  return result ? result->report.c_str() : "";
}

meromorph_status meromorph_match_points(const meromorph_match_result *result,
                                        int32_t *target_triangle, double *weights,
                                        double *positions) {
  if (!result) return fail(MEROMORPH_ERROR_ARGUMENT, "result is NULL");
  const meromorph::MatchedPoints &points = result->points;
  for (size_t v = 0; v < points.target_face.size(); ++v) {
    if (target_triangle) target_triangle[v] = points.target_face[v];
    if (weights) {
      const Eigen::Vector2d &b = points.weights[v];
      weights[3 * v] = 1 - b[0] - b[1], weights[3 * v + 1] = b[0], weights[3 * v + 2] = b[1];
    }
    if (positions)
      for (int k = 0; k < 3; ++k)
        positions[3 * v + size_t(k)] = points.position[v][k];
  }
  return MEROMORPH_OK;
}

} // extern "C"
