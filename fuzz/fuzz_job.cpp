// libFuzzer target: a command-line job past reading, chosen at build time by MEROMORPH_FUZZ_JOB:
// `forms` (the holomorphic forms, as `meromorph forms`) or `remesh` (the map and the remesh, as
// `meromorph remesh`), on what the OFF reader makes of the bytes after the first two. Byte 0
// picks the options (--close-holes, --split-nonmanifold, --uniform, the vertex target); byte 1
// scales every coordinate by 10^k, k from -300 to 300, so the scale sweep is part of every run.
// Any crash, sanitizer finding, InternalError (the CLI's exit 1) or exception other than
// meromorph::Error is a bug.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/errors.h"
#include "forms/holomorphic_pipeline.h"
#include "io/format_readers.h"
#include "job/surface_map.h"
#include "mesh/mesh_from_arrays.h"
#include "remesh/surface_remesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  using namespace meromorph;
  if (size < 2) return 0;
  const uint8_t options = data[0];
  const int exponent = int(data[1] % 61) * 10 - 300;
  const std::string bytes(reinterpret_cast<const char *>(data + 2), size - 2);
  try {
    std::vector<std::string> notes;
    MeshArrays arrays = read_off("fuzz.off", bytes, notes);
    if (arrays.positions.size() > 3000 || arrays.triangles.size() > 6000) return 0; // keep it fast
    const double scale = std::pow(10.0, exponent);
    for (Point3 &p : arrays.positions)
      p *= scale;
    Mesh mesh;
    mesh_from_arrays(arrays, mesh);
    const std::string job = MEROMORPH_FUZZ_JOB;
    if (job == "forms") {
      compute_holomorphic_forms(mesh, SolverKind::cholmod, {});
    } else {
      ParameterizeOptions settings;
      settings.area_correct = true;
      settings.close_holes = options & 1;
      settings.split_nonmanifold = options & 2;
      settings.set_aside_defects = false; // as the remesh commands
      const Parameterization map = parameterize_surface(mesh, settings, {});
      if (!map.valid) return 0;
      RemeshOptions remesh_options;
      remesh_options.even_out = !(options & 4);
      remesh_options.vertices = 12 + (options >> 3) * 16;
      SurfaceRemesh remesh;
      add_written_vertices(map, mesh);
      remesh_through_sphere(mesh, map, remesh_options, {}, remesh);
    }
  } catch (const InternalError &) {
    __builtin_trap(); // the command line's exit 1: a bug
  } catch (const Error &) {
    // A clear refusal is the expected outcome for most inputs.
  }
  return 0;
}
