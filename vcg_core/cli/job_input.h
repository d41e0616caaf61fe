// The input of a CLI job: the mesh read (and repaired, when asked), with what that took.
//
// In:  the input path and whether to apply the safe repairs.
// Out: the mesh, where it came from, the repairs made and the reading time in milliseconds.
#pragma once

#include <chrono>
#include <string>
#include <vector>

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
  input.source = read_mesh(path, mesh);
  if (repair) input.repairs = repair_mesh(mesh);
  input.read_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return input;
}

} // namespace meromorph::cli
