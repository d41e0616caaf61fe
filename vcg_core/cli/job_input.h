// The input of a CLI job: the mesh read (and repaired, when asked), with what that took.
//
// In:  the input path and whether to apply the safe repairs.
// Out: the mesh, where it came from, the repairs made and the reading time in milliseconds; and
//      `naming_the_input`: a computation on it whose InputError says which file it is about.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "cli/process_settings.h"
#include "common/errors.h"
#include "common/parallel_for.h"
#include "io/mesh_reader.h"
#include "mesh/repair.h"

namespace meromorph::cli {

struct JobInput {
  MeshSource source;
  std::vector<std::string> repairs;
  double read_ms = 0;
};

// `vertex_values`: keep the values a PLY file carries per vertex (MeshSource::vertex_values).
inline JobInput read_job_input(const std::string &path, bool repair, Mesh &mesh,
                               bool vertex_values = false) {
  const auto start = std::chrono::steady_clock::now();
  JobInput input;
  // (reading is serial: the other core's thread is started meanwhile, common/parallel_for.h)
  while_threads_start([&] { input.source = read_mesh(path, mesh, {}, vertex_values); });
  if (repair) input.repairs = repair_mesh(mesh);
  if (!input.repairs.empty()) input.source.triangle_face.clear(); // renumbered
  tune_blas_for_job(long(mesh.vert.size()));                      // cli/process_settings.h
  input.read_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return input;
}

// " (numbered as triangles; in the file, triangle 12 is in face 6, ...)": where the file's
// polygons were split into triangles, the file's own faces of the triangles a message names.
inline std::string file_faces_words(const MeshSource &source, const std::vector<int> &faces) {
  std::string words;
  for (size_t i = 0; i < faces.size() && i < 10; ++i)
    if (faces[i] >= 0 && size_t(faces[i]) < source.triangle_face.size())
      words += (words.empty() ? "" : ", ") + std::string("triangle ") + std::to_string(faces[i]) +
               " is in face " + std::to_string(source.triangle_face[size_t(faces[i])]);
  if (words.empty()) return "";
  return " (numbered as triangles; in the file, " + words + (faces.size() > 10 ? ", ..." : "") +
         ")";
}

template <typename Compute> auto naming_the_input(const MeshSource &source, Compute compute) {
  try {
    return compute();
  } catch (const InputError &error) { // what is wrong with the mesh: say which file
    throw InputError(source.path + ": " + error.what() + file_faces_words(source, error.faces()),
                     error.remedies());
  }
}

} // namespace meromorph::cli
