// The main job: a conformal map of a closed surface of any genus onto the sphere.
//
// In:  a mesh that validation accepts, options, progress (cancellable).
// Out: `Parameterization`: the map as a unit-sphere position per vertex (genus 0: a degree-1 map;
//      genus 1: the Weierstrass P-function of the flat coordinate, degree 2; genus g >= 2: the
//      ratio (omega1 + omega2) / (omega1 - omega2) of two holomorphic forms, by default the first
//      of a fixed list of generic pairs that the mesh resolves, degree 2g - 2), Moebius-centred
//      unless asked not to (and area-corrected when asked); its degree, branch points with local
//      degrees and the Riemann-Hurwitz check; layers (sheets) and the layered-sphere positions;
//      texture coordinates per vertex and per wedge; distortion; modulus or Riemann matrix;
//      timings. Nothing is forced: what is reported is what was measured.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "common/progress.h"
#include "common/remedy.h"
#include "maps/form_pairs.h"
#include "mesh/mesh.h"
#include "solvers/laplacian_solver.h"
#include "sphere/area_correction.h"
#include "sphere/map_quality.h"
#include "sphere/mobius_centering.h"
#include "sphere/sheets.h"
#include "sphere/sphere_geometry.h"
#include "sphere/texture_coordinates.h"

namespace meromorph {

struct ParameterizeOptions {
  UvKind uv_kind = UvKind::spherical;
  bool mobius = true;
  int origin_vertex = -1; // genus 1: where z = 0, the double pole of P (-1: automatic)
  std::array<int, 2> form_pair{-1, -1}; // genus >= 2: (psi_i + psi_j) / (psi_i - psi_j); -1, -1:
                                        // a generic pair mixing all forms (parameterization.cpp)
  double layer_gap = 0.0;               // layer k on the sphere of radius 1 + gap * k
  int pole_face = -1;                   // genus 0: the face at the pole (-1: automatic)
  SolverKind solver = SolverKind::cholmod;
  bool close_holes = true; // parameterize_surface: close holes for the computation only
  // parameterize_surface, several parts, spherical texture coordinates: part k's texture in cell k
  // of a grid of n x n cells over the unit square (n = ceil(sqrt(parts)), row by row from the
  // bottom left) instead of each filling the unit square.
  bool pack_uv = false;
  // parameterize_surface: take non-manifold vertices and edges apart for the computation
  // (nonmanifold_split.h) instead of refusing the mesh.
  bool split_nonmanifold = true;
  // parameterize_surface: weld seam duplicates and leave doubled faces, faces that use a vertex
  // twice and vertices on no face out of the computation (job/set_aside.h) instead of refusing
  // the mesh; the outputs keep them all.
  bool set_aside_defects = true;
  // parameterize_surface: stop before the map is computed, once every refusal about the mesh's
  // structure is made (what `meromorph info` asks); the result is then empty.
  bool prepare_only = false;
  // After centring: the Moebius transformation that makes the map most even in area
  // (area_correction.h); conformality is unchanged, the texture density spreads more evenly.
  bool area_correct = false;
  // When the mesh's own triangulation carries no valid map (slivers, coarse faces near branch
  // points): compute on it refined (its long edges cut until none is longer than an even
  // triangulation's with 4, 16, ... times its vertices; up to this many times) and carry the map
  // back to its vertices. 0: never.
  int finer_levels = 3;
  // parameterize called on the mesh the outputs hold: where even the finer map cannot be carried
  // by the mesh's faces without turning some over, add the few vertices it needs (listed in
  // `added_vertices`) instead of refusing.
  bool add_vertices = true;
};

// A vertex added to the written surface (ParameterizeOptions::add_vertices): the input's face it
// lies on, its barycentric coordinates b1, b2 (of that face's second and third corners) and its
// position.
struct AddedVertex {
  int face = -1;
  double b1 = 0, b2 = 0;
  Eigen::Vector3d position;
};

// What parameterize_surface took apart (nonmanifold_split.h): input vertices that were split,
// input edges with more than two faces, and how many vertices the split added.
struct NonmanifoldSplitReport {
  std::vector<int> vertices;
  std::vector<std::array<int, 2>> edges;
  int added_vertices = 0;
};

// A hole closed for the computation (surface_map.h): its part, loop length in edges, a vertex of
// it, and the share of the sphere its closing faces cover (the gap it leaves in the outputs).
struct ClosedHoleReport {
  int part = 0, edges = 0, vertex = -1;
  double image_area_over_4pi = 0;
};

struct BranchPoint {
  int vertex = -1;
  Eigen::Vector3d position;
  Eigen::Vector3d sphere;
  int local_degree = 1;   // e; the point is a branch point of order e - 1
  int sphere_vertex = -1; // non-manifold spots split: the vertex in the layered sphere's numbering
};

struct Parameterization {
  int genus = 0;
  int euler = 2;
  int degree = 0;
  std::string method;
  double area_over_4pi = 0;
  int ramification = 0;
  bool riemann_hurwitz_ok = false;
  std::vector<BranchPoint> branch_points;
  std::optional<Complex> modulus;
  Eigen::MatrixXcd riemann_matrix;
  double non_holomorphicity_mean = 0;
  bool mobius_applied = false;
  MobiusCentering mobius;
  AreaCorrection area_correction; // with options.area_correct
  MapQuality quality;
  Sheets sheets;
  std::vector<Eigen::Vector3d> sphere;  // unit sphere
  std::vector<Eigen::Vector3d> layered; // radius 1 + gap * layer
  std::vector<int> branch_flag;         // local degree at branch vertices, 0 elsewhere
  // Genus 1: the flat coordinate z per vertex (the map is P(z); z is defined up to the lattice),
  // in the numbering of `sphere` (several parts: 0 on parts of another genus), and the lattice's
  // reduced basis (weierstrass_p.h; several parts: each part's own, in `components`). Empty
  // otherwise.
  std::vector<Complex> flat;
  std::array<Complex, 2> flat_periods{};
  TextureCoordinates uv;
  std::vector<std::pair<std::string, double>> timings_ms;
  // What the method used.
  int pole_face = -1, raised_weights = 0, origin_vertex = -1;
  bool intrinsic_delaunay = false; // genus 0: solved with the intrinsic Delaunay weights
  // Branch points placed on vertices fold-free: genus 1, half periods (genus1_branch_placement.h);
  // genus >= 2, critical points repaired inside faces (branch_snapping.h).
  int snapped_branch_points = 0;
  int untangled_vertices = 0;     // sliver corners moved to unfold them (fold_untangling.h)
  int computed_on_refinement = 0; // which refinement the map was computed on (finer_levels)
  std::array<int, 2> form_pair{-1, -1};
  FormPair form_coefficients; // genus >= 2: a_k, b_k of the pair used (form_pairs.h)
  int pair_attempts = 0;      // genus >= 2: pairs tried until one was generic
  int origin_attempts = 0;    // genus 1: origins tried until the map was valid
  // Whether the map as written is a valid branched cover: the expected degree (1, 2 or 2g - 2;
  // a chosen pair of forms may share zeros and give less), Riemann-Hurwitz, no face turned
  // over. `invalid` says what fails, with face indices.
  bool valid = false;
  std::vector<std::string> invalid;
  // When the map is not valid: the likely causes found on this mesh, each with its remedy (worded
  // by each adapter); empty otherwise.
  std::vector<Advice> advice;
  std::vector<std::string> notes; // harmless oddities of the mesh (coincident vertices, ...)
  // parameterize_surface, when the mesh had several parts or holes were closed: each part's own
  // map (figures only: its per-vertex arrays are in the ones above, in the input's numbering; its
  // branch points' vertices are the input's, -1 at a hole's centre), and the holes closed.
  std::vector<Parameterization> components;
  std::vector<ClosedHoleReport> holes_closed;
  std::vector<int> vertex_component; // per vertex: its part (empty: one part); part k's layered
                                     // sphere is centred at x = k * component_spacing
  double component_spacing = 0;
  // parameterize_surface with split_nonmanifold on a non-manifold mesh: the per-vertex arrays
  // above are per vertex of the split mesh (the input's vertices first, then the copies), whose
  // faces are `sphere_faces` (the input's, in order, pointing at the copies) and whose vertices
  // come from `sphere_source_vertex`; branch points name input vertices. Empty otherwise.
  NonmanifoldSplitReport nonmanifold_split;
  std::vector<int> sphere_source_vertex;
  std::vector<std::array<int, 3>> sphere_faces;
  // With vertices added (options.add_vertices): the per-vertex arrays above are per vertex of the
  // written surface, the input's vertices first, then these; its faces are `surface_faces` (the
  // input's, a cut face keeping its slot with one piece, then the other pieces), each part of
  // the input's face `surface_face_source`. Empty otherwise.
  std::vector<AddedVertex> added_vertices;
  std::vector<std::array<int, 3>> surface_faces;
  std::vector<int> surface_face_source;
};

// `--strict`'s options: what parameterize_surface otherwise deals with for the computation
// (close_holes, split_nonmanifold, set_aside_defects) is refused instead, and no vertex is added.
inline void refuse_instead(ParameterizeOptions &options) {
  options.close_holes = options.split_nonmanifold = options.set_aside_defects = false;
  options.add_vertices = false;
}

struct Validation;

// `validated`: the mesh's validation when the caller has made it (and it found nothing). The
// mesh's vertices are moved to unit scale for the computation and put back exactly as they were
// (mesh/unit_scale.h): no copy of the mesh is made.
Parameterization parameterize(Mesh &mesh, const ParameterizeOptions &options = {},
                              const Progress &progress = {}, const Validation *validated = nullptr);

} // namespace meromorph
