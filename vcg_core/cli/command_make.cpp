// `meromorph make sphere|torus|genus -o OUT ...`: the project's deterministic test surfaces.
#include <filesystem>
#include <iostream>

#include "cli/exit_codes.h"
#include "commands.h"
#include "common/errors.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "mesh/topology.h"
#include "shapes/cad_parts.h"
#include "shapes/generated_surfaces.h"
#include "shapes/rigid_motion.h"

namespace meromorph::cli {
namespace {

struct MakeOptions {
  std::string output;
  bool rigid_motion = false;
  std::uint64_t seed = 1;
  double scale = 1.0;
  double needles = 0.0;
  // sphere
  int subdivisions = 4;
  double radius = 1.0;
  // torus
  double major_radius = 2.0, minor_radius = 1.0;
  int major_segments = 0, minor_segments = 0;
  std::string method = "grid";
  // genus surface and implicit torus
  int genus = 2;
  int resolution = 40;
  bool raw_marching_cubes = false;
  // blob
  int tentacles = 6;
  double tentacle_length = 4.0;
  bool hole = false;
  // cad
  int holes = 2, segments = 64;
  double thickness = 0.05;
  // subdivide
  std::string input;
  int steps = 1;
};

int finish(Mesh &mesh, const MakeOptions &options) {
  if (options.needles > 0) inject_needles(mesh, options.needles);
  if (options.rigid_motion || options.scale != 1.0) {
    Similarity motion = options.rigid_motion ? random_rigid_motion(options.seed) : Similarity{};
    motion.scale = options.scale;
    apply_similarity(motion, mesh);
  }
  write_mesh(mesh, options.output);
  const Topology topology = compute_topology(mesh);
  std::cout << "wrote " << options.output << ": " << topology.vertices << " vertices, "
            << topology.faces << " faces, genus "
            << (topology.genus ? std::to_string(*topology.genus) : std::string("undefined"))
            << "\n";
  return int(ExitCode::done);
}

void add_common(CLI::App *command, MakeOptions &options) {
  command->add_option("-o,--output", options.output, "output mesh file (.ply, .obj, .off, .stl)")
      ->required();
  command->add_flag("--rigid-motion", options.rigid_motion,
                    "move the surface by a random rotation and translation (see --seed)");
  command->add_option("--seed", options.seed, "seed of the random rigid motion")
      ->capture_default_str();
  command->add_option("--scale", options.scale, "uniform scale applied at the end")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command
      ->add_option("--needles", options.needles,
                   "split this fraction of the edges close to one end, leaving needles down to "
                   "about 0.1 degrees on the same surface (as scans and exporters do)")
      ->check(CLI::Range(0.0, 1.0));
}

CLI::App *add_sphere(CLI::App *make, MakeOptions &options) {
  CLI::App *sphere = make->add_subcommand("sphere", "Icosphere: 10 * 4^s + 2 vertices.");
  add_common(sphere, options);
  sphere->add_option("-s,--subdivisions", options.subdivisions, "subdivision steps (0..9)")
      ->capture_default_str();
  sphere->add_option("--radius", options.radius, "radius")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  return sphere;
}

CLI::App *add_torus(CLI::App *make, MakeOptions &options) {
  CLI::App *torus = make->add_subcommand(
      "torus", "Torus of revolution with radii R > r; its exact conformal modulus is "
               "i*sqrt(R^2 - r^2)/r.");
  add_common(torus, options);
  torus
      ->add_option("-R,--major-radius", options.major_radius,
                   "distance from the axis to the "
                   "tube's centre")
      ->capture_default_str();
  torus->add_option("-r,--minor-radius", options.minor_radius, "radius of the tube")
      ->capture_default_str();
  torus->add_option("--segments", options.major_segments,
                    "grid: quads around the axis (default: keeps quads square for the "
                    "resolution)");
  torus->add_option("--minor-segments", options.minor_segments, "grid: quads around the tube");
  torus
      ->add_option("--method", options.method,
                   "grid (regular quads split in two) or implicit (marching cubes + isotropic "
                   "remeshing)")
      ->check(CLI::IsMember({"grid", "implicit"}))
      ->capture_default_str();
  torus->add_option("--resolution", options.resolution, "edges around the tube")
      ->capture_default_str();
  return torus;
}

CLI::App *add_genus(CLI::App *make, MakeOptions &options) {
  CLI::App *genus = make->add_subcommand(
      "genus", "Closed surface of the given genus: rings of tubes in a row (marching cubes + "
               "isotropic remeshing).");
  add_common(genus, options);
  genus->add_option("-g,--genus", options.genus, "genus (0..64)")->capture_default_str();
  genus->add_option("--resolution", options.resolution, "edges across one ring")
      ->capture_default_str();
  return genus;
}

CLI::App *add_blob(CLI::App *make, MakeOptions &options) {
  CLI::App *blob = make->add_subcommand(
      "blob", "Genus 0 with long thin parts: a ball with tentacles (the hard case for maps to the "
              "sphere).");
  add_common(blob, options);
  blob->add_option("--tentacles", options.tentacles, "number of tentacles")->capture_default_str();
  blob->add_option("--length", options.tentacle_length, "tentacle length (ball radius 1)")
      ->capture_default_str();
  blob->add_option("--resolution", options.resolution, "edges across the ball")
      ->capture_default_str();
  blob->add_flag("--hole", options.hole,
                 "a hole through the ball: genus 1, a figure with long limbs");
  return blob;
}

CLI::App *add_cad(CLI::App *make, MakeOptions &options) {
  CLI::App *cad = make->add_subcommand(
      "cad", "A part as CAD programs export it (write .stl): a plate with round holes (genus = "
             "holes) or a cylinder (--holes 0), its flat faces cut into long thin triangles.");
  add_common(cad, options);
  cad->add_option("--holes", options.holes, "holes through the plate (0: a cylinder)")
      ->capture_default_str();
  cad->add_option("--segments", options.segments,
                  "segments around each circle (a multiple of 4 with holes)")
      ->capture_default_str();
  cad->add_option("--thickness", options.thickness,
                  "plate thickness (holes 1 apart) or cylinder height (radius 1); a thin plate "
                  "has corners down to atan(thickness)")
      ->capture_default_str();
  return cad;
}

CLI::App *add_subdivide(CLI::App *make, MakeOptions &options) {
  CLI::App *subdivide = make->add_subcommand(
      "subdivide", "A mesh subdivided flat: every face into four, the same surface (the "
                   "benchmark's larger meshes).");
  subdivide->add_option("INPUT", options.input, "mesh file (.ply, .obj, .off, .stl)")->required();
  add_common(subdivide, options);
  subdivide->add_option("-s,--steps", options.steps, "subdivision steps (0..8)")
      ->capture_default_str();
  return subdivide;
}

void make_torus(Mesh &mesh, const MakeOptions &options) {
  if (options.method == "implicit") {
    make_implicit_torus(mesh, options.major_radius, options.minor_radius, options.resolution,
                        !options.raw_marching_cubes);
    return;
  }
  const int minor = options.minor_segments > 0 ? options.minor_segments : options.resolution;
  const int major = options.major_segments > 0
                        ? options.major_segments
                        : int(std::lround(minor * options.major_radius / options.minor_radius));
  make_grid_torus(mesh, options.major_radius, options.minor_radius, major, minor);
}

} // namespace

Command add_make_command(CLI::App &app) {
  auto options = std::make_shared<MakeOptions>();
  CLI::App *make = app.add_subcommand("make", "Write one of meromorph's test surfaces.");
  make->require_subcommand(1);
  CLI::App *sphere = add_sphere(make, *options);
  CLI::App *torus = add_torus(make, *options);
  CLI::App *genus = add_genus(make, *options);
  for (CLI::App *implicit : {torus, genus})
    implicit->add_flag("--raw-marching-cubes", options->raw_marching_cubes,
                       "keep marching cubes' triangles (many obtuse and needle-shaped ones): a "
                       "stress test; default remeshes them isotropically");
  CLI::App *blob = add_blob(make, *options);
  CLI::App *subdivide = add_subdivide(make, *options);
  CLI::App *cad = add_cad(make, *options);

  return [options, sphere, torus, blob, subdivide, cad]() {
    Mesh mesh;
    if (subdivide->parsed()) {
      std::error_code error;
      if (std::filesystem::equivalent(options->input, options->output, error))
        throw ArgumentError(options->output + " is the input: write the subdivided mesh to "
                                              "another file");
      read_mesh(options->input, mesh);
      subdivide_flat(mesh, options->steps);
    } else if (sphere->parsed())
      make_icosphere(mesh, options->subdivisions, options->radius);
    else if (torus->parsed())
      make_torus(mesh, *options);
    else if (cad->parsed())
      make_cad_part(mesh, options->holes, options->segments, options->thickness);
    else if (blob->parsed())
      make_tentacle_blob(mesh, options->tentacles, options->tentacle_length, options->resolution,
                         options->hole);
    else
      make_genus_surface(mesh, options->genus, options->resolution, !options->raw_marching_cubes);
    return finish(mesh, *options);
  };
}

} // namespace meromorph::cli
