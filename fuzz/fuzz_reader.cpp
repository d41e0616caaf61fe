// libFuzzer target: one reader (chosen at build time by MEROMORPH_FUZZ_FORMAT: ply, off, obj or
// stl) on arbitrary bytes, then what `info --repair` does with what it read: validation,
// topology, the safe repairs and validation again. Any crash, sanitizer finding or exception
// other than meromorph::Error is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/errors.h"
#include "io/format_readers.h"
#include "mesh/repair.h"
#include "mesh/topology.h"
#include "mesh/validation.h"

namespace {

meromorph::MeshArrays read(const std::string &bytes, std::vector<std::string> &notes) {
  const std::string path = "fuzz." MEROMORPH_FUZZ_FORMAT;
  const std::string format = MEROMORPH_FUZZ_FORMAT;
  if (format == "ply") return meromorph::read_ply(path, bytes, notes, true); // values kept too
  if (format == "off") return meromorph::read_off(path, bytes, notes);
  if (format == "obj") return meromorph::read_obj(path, bytes, notes);
  return meromorph::read_stl(path, bytes, notes);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  using namespace meromorph;
  const std::string bytes(reinterpret_cast<const char *>(data), size);
  try {
    std::vector<std::string> notes;
    const MeshArrays arrays = read(bytes, notes);
    Mesh mesh;
    mesh_from_arrays(arrays, mesh);
    validate_mesh(mesh);
    compute_topology(mesh);
    repair_mesh(mesh);
    validate_mesh(mesh);
    compute_topology(mesh);
  } catch (const Error &) {
    // A clear refusal is the expected outcome for most inputs.
  }
  return 0;
}
