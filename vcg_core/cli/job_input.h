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

inline JobInput read_job_input(const std::string &path, bool repair, Mesh &mesh) {
  const auto start = std::chrono::steady_clock::now();
  JobInput input;
  // (reading is serial: the other core's thread is started meanwhile, common/parallel_for.h)
  while_threads_start([&] { input.source = read_mesh(path, mesh); });
  if (repair) input.repairs = repair_mesh(mesh);
  tune_blas_for_job(long(mesh.vert.size())); // cli/process_settings.h
  input.read_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return input;
}

template <typename Compute> auto naming_the_input(const std::string &path, Compute compute) {
  try {
    return compute();
  } catch (const InputError &error) { // what is wrong with the mesh: say which file
    throw InputError(path + ": " + error.what(), error.remedies());
  }
}

} // namespace meromorph::cli
