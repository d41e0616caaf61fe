// libFuzzer target: the C ABI's mesh intake. The bytes become a vertex count, a triangle count,
// options and the arrays (with whatever values they hold: NaN, huge, negative or out-of-range
// indices, mismatched counts within the buffers given); meromorph_parameterize_d must return a
// status, never crash, and a successful result must answer every getter. Built a second time
// with MEROMORPH_FUZZ_REMESH (fuzz_c_abi_remesh): meromorph_remesh_d with a vertex target and
// area correction from the bytes too (any int64, any int), its result answering every getter.
// Both variants then compute the forms of the same arrays (meromorph_forms_d).
#include <cstdint>
#include <cstring>
#include <vector>

#include "meromorph.h"

namespace {

template <class T> T take(const uint8_t *&data, size_t &size) {
  T value{};
  const size_t n = size < sizeof(T) ? size : sizeof(T);
  std::memcpy(&value, data, n);
  data += n;
  size -= n;
  return value;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const uint8_t first = take<uint8_t>(data, size);
  const size_t vertex_count = first % 64;
  const size_t triangle_count = take<uint8_t>(data, size) % 128;
  meromorph_options options;
  meromorph_default_options(&options);
  const uint8_t flags = take<uint8_t>(data, size);
  if (flags & 1) options.uv_kind = take<int8_t>(data, size);
  if (flags & 2) options.origin_vertex = take<int8_t>(data, size);
  if (flags & 4) options.pole_face = take<int8_t>(data, size);
  if (flags & 8) options.layer_gap = take<double>(data, size);
  if (flags & 16) options.form_pair[0] = take<int8_t>(data, size);
  if (flags & 32) options.mobius = take<int8_t>(data, size);
  options.close_holes = (first >> 6) & 1;
  options.split_nonmanifold = (first >> 7) & 1;
  // Positions: small integers (a lattice, so meshes are often valid) or raw doubles.
  std::vector<double> positions(3 * vertex_count);
  for (double &p : positions)
    p = (flags & 64) ? take<double>(data, size) : double(take<int8_t>(data, size) % 8);
  std::vector<int32_t> triangles(3 * triangle_count);
  for (int32_t &t : triangles)
    t = (flags & 128) ? take<int32_t>(data, size)
                      : int32_t(take<uint8_t>(data, size) % (vertex_count + 1));
#ifdef MEROMORPH_FUZZ_REMESH
  int64_t target = (flags & 1) ? take<int64_t>(data, size) : take<int16_t>(data, size);
  // Targets the library accepts (12 to 2e9) are capped at 4096 vertices: a remesh of millions of
  // vertices is legitimate work, too slow for a fuzz run; the bounds are still tried.
  if (target > 4096 && target <= 2000000000) target = 4096;
  const int area_correct = (flags & 2) ? take<int32_t>(data, size) : 1;
  // The size by an edge length or a largest distance instead, from a last byte: any double, but
  // accepted ones that would ask for more than a few thousand vertices on the lattice's meshes
  // (edges below 0.5, distances below 1%) are raised to that, as the target is capped above.
  const uint8_t sizing = take<uint8_t>(data, size);
  if (sizing == 1 && !(flags & 64)) {
    const double length = take<double>(data, size);
    options.remesh_edge_length = (length > 0 && length < 0.5) ? 0.5 : length;
  }
  if (sizing == 2) {
    const double error = take<double>(data, size);
    options.remesh_max_error = (error > 0 && error < 0.01) ? 0.01 : error;
  }
  meromorph_remesh_result *remesh = nullptr;
  const meromorph_status remeshed =
      meromorph_remesh_d(positions.data(), vertex_count, triangles.data(), triangle_count, &options,
                         target, area_correct, &remesh);
  if (remeshed == MEROMORPH_OK) {
    const size_t n = meromorph_remesh_vertex_count(remesh),
                 t = meromorph_remesh_triangle_count(remesh);
    if (target > 0 && n > size_t(64 * target + 10000)) __builtin_trap(); // the target holds
    std::vector<double> xyz(3 * n), sphere(3 * n);
    std::vector<int32_t> corners(3 * t), layer(n), branch(n);
    if (meromorph_remesh_mesh(remesh, xyz.data(), corners.data(), layer.data(), branch.data(),
                              sphere.data()) != MEROMORPH_OK)
      __builtin_trap();
    for (int32_t c : corners)
      if (c < 0 || size_t(c) >= n) __builtin_trap();
    (void)std::strlen(meromorph_remesh_report_json(remesh));
    (void)std::strlen(meromorph_remesh_summary(remesh));
  } else if (remesh != nullptr || std::strlen(meromorph_last_error()) == 0) {
    __builtin_trap();
  }
  meromorph_remesh_free(remesh);
  return 0;
#endif
  meromorph_result *result = nullptr;
  const meromorph_status status = meromorph_parameterize_d(
      positions.data(), vertex_count, triangles.data(), triangle_count, &options, &result);
  if (status == MEROMORPH_OK) {
    // The surface as written: the input's, or with vertices added where the map needs them.
    const size_t written_vertices = meromorph_vertex_count(result),
                 written_triangles = meromorph_triangle_count(result);
    if (written_vertices != vertex_count + meromorph_added_vertex_count(result) ||
        written_triangles < triangle_count)
      __builtin_trap();
    std::vector<double> buffer(6 * (written_vertices + written_triangles) + 6);
    std::vector<int32_t> ints(written_vertices + 1), degrees(written_vertices + 1);
    meromorph_sphere_positions(result, buffer.data());
    meromorph_layered_positions(result, buffer.data());
    meromorph_vertex_uvs(result, buffer.data());
    meromorph_corner_uvs(result, buffer.data());
    meromorph_layers(result, ints.data());
    const size_t sphere_vertices = meromorph_sphere_vertex_count(result);
    std::vector<double> layered(3 * sphere_vertices);
    std::vector<int32_t> sphere_ints(sphere_vertices), sphere_triangles(3 * written_triangles);
    if (meromorph_sphere_mesh(result, layered.data(), sphere_triangles.data(), sphere_ints.data(),
                              sphere_ints.data(), sphere_ints.data(),
                              sphere_ints.data()) != MEROMORPH_OK)
      __builtin_trap();
    for (int32_t t : sphere_triangles)
      if (t < 0 || size_t(t) >= sphere_vertices) __builtin_trap(); // the sphere mesh is whole
    if (meromorph_branch_point_count(result) <= written_vertices)
      meromorph_branch_points(result, ints.data(), degrees.data());
    meromorph_distortion distortion;
    meromorph_get_distortion(result, &distortion);
    (void)std::strlen(meromorph_report_json(result));
  } else if (result != nullptr || std::strlen(meromorph_last_error()) == 0) {
    __builtin_trap(); // a failure must leave no result and say why
  }
  meromorph_result_free(result);
  // The forms of the same arrays: a status, never a crash; a result answers its getters.
  meromorph_forms_result *forms = nullptr;
  if (meromorph_forms_d(positions.data(), vertex_count, triangles.data(), triangle_count, nullptr,
                        &forms) == MEROMORPH_OK) {
    if (meromorph_forms_genus(forms) < 0) __builtin_trap();
    (void)std::strlen(meromorph_forms_report_json(forms));
  } else if (forms != nullptr || std::strlen(meromorph_last_error()) == 0) {
    __builtin_trap();
  }
  meromorph_forms_free(forms);
  return 0;
}
