// Validation: everything that keeps a mesh from being a closed, connected, oriented 2-manifold,
// named with where it is.
//
// In:  a mesh as read (vertex and face indices are the file's own, 0-based).
// Out: `Validation`, a list of findings. Each finding has a machine name (`finding_code`), a
//      sentence saying what and where (naming no tool), the complete lists of vertices / edges
//      (as vertex pairs) / faces where it occurs, whether `repair_mesh` can fix it, and its
//      remedies as codes (common/remedy.h) for each adapter to word. An empty list means the
//      mesh can be parameterized. The mesh itself is not changed. `refusal` makes the InputError
//      that tells a finding.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "common/errors.h"
#include "mesh/mesh.h"

namespace meromorph {

enum class FindingKind {
  empty_mesh,
  non_finite_coordinates,
  repeated_vertex_in_face,
  zero_area_faces,
  duplicate_faces,
  beyond_double_precision,
  duplicate_vertices,
  unreferenced_vertices,
  non_manifold_edges,
  non_manifold_vertices,
  boundary_loops,
  several_components,
  inconsistent_orientation,
  non_orientable,
};

// "non_manifold_edges", ...: the name used in JSON reports and tests.
const char *finding_code(FindingKind kind);

struct Finding {
  explicit Finding(FindingKind kind_, bool repairable_ = false)
      : kind(kind_), repairable(repairable_) {}

  FindingKind kind;
  bool repairable = false;
  std::string message;
  std::vector<int> vertices;
  std::vector<std::array<int, 2>> edges;
  std::vector<int> faces;
  std::vector<int> sizes; // boundary loop lengths in edges, or component sizes in faces
  std::vector<Remedy> remedies;
};

struct Validation {
  std::vector<Finding> findings;
  // What is unusual but harmless (for example vertices at the same position that the topology
  // keeps apart), in the user's words, for the report's `notes`.
  std::vector<std::string> notes;

  bool ok() const { return findings.empty(); }
  bool all_repairable() const;
  const Finding *find(FindingKind kind) const;
  // The finding to tell the user first: the first one repair cannot fix (the first one else).
  // Needs at least one finding.
  const Finding &main_finding() const;
};

// Faces whose area is at most this fraction of their longest edge squared count as zero-area.
constexpr double zero_area_tolerance = 1e-12;
// Faces whose longest edge is below this fraction of the mesh's size cannot be resolved in
// double precision beside the rest of the mesh.
constexpr double smallest_relative_face = 1e-11;

// A face that uses one vertex twice.
bool repeats_a_vertex(const MeshFace &face);
// A face whose area is at most zero_area_tolerance times its longest edge squared (scale-safe:
// computed on edge vectors brought to unit size).
bool has_zero_area(const MeshFace &face);
bool has_zero_area(const Point3 &p0, const Point3 &p1, const Point3 &p2);

Validation validate_mesh(const Mesh &mesh);

// Faces on the same three vertices as another: pairs (a face, the next one on those vertices),
// in the order of their sorted corners; faces that use a vertex twice are not paired.
std::vector<std::array<int, 2>>
faces_on_the_same_vertices(const std::vector<std::array<int, 3>> &triangles);

// The error that refuses the mesh for this finding: its message (and `more`), its remedies.
InputError refusal(const Finding &finding, const std::string &more = "");

} // namespace meromorph
