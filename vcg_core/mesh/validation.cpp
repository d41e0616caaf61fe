#include "mesh/validation.h"

#if defined(_OPENMP)
#include <parallel/algorithm>
#endif

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/append.h>

#include "common/errors.h"
#include "common/parallel_for.h"
#include "common/wording.h"
#include "mesh/topology.h"
#include "mesh/unit_scale.h"

namespace meromorph {

const char *finding_code(FindingKind kind) {
  switch (kind) {
  case FindingKind::empty_mesh:
    return "empty_mesh";
  case FindingKind::non_finite_coordinates:
    return "non_finite_coordinates";
  case FindingKind::repeated_vertex_in_face:
    return "repeated_vertex_in_face";
  case FindingKind::zero_area_faces:
    return "zero_area_faces";
  case FindingKind::duplicate_faces:
    return "duplicate_faces";
  case FindingKind::beyond_double_precision:
    return "beyond_double_precision";
  case FindingKind::duplicate_vertices:
    return "duplicate_vertices";
  case FindingKind::unreferenced_vertices:
    return "unreferenced_vertices";
  case FindingKind::non_manifold_edges:
    return "non_manifold_edges";
  case FindingKind::non_manifold_vertices:
    return "non_manifold_vertices";
  case FindingKind::boundary_loops:
    return "boundary_loops";
  case FindingKind::several_components:
    return "several_components";
  case FindingKind::inconsistent_orientation:
    return "inconsistent_orientation";
  case FindingKind::non_orientable:
    return "non_orientable";
  }
  return "?";
}

bool Validation::all_repairable() const {
  return std::all_of(findings.begin(), findings.end(),
                     [](const Finding &f) { return f.repairable; });
}

const Finding &Validation::main_finding() const {
  for (const Finding &f : findings)
    if (!f.repairable) return f;
  return findings.front();
}

const Finding *Validation::find(FindingKind kind) const {
  for (const Finding &f : findings)
    if (f.kind == kind) return &f;
  return nullptr;
}

bool repeats_a_vertex(const MeshFace &face) {
  return face.cV(0) == face.cV(1) || face.cV(1) == face.cV(2) || face.cV(2) == face.cV(0);
}

bool has_zero_area(const MeshFace &face) {
  return has_zero_area(face.cP(0), face.cP(1), face.cP(2));
}

bool has_zero_area(const Point3 &p0, const Point3 &p1, const Point3 &p2) {
  // Edge vectors halved against overflow and scaled by a power of two to unit size, so neither
  // the squares of huge coordinates overflow nor those of tiny ones underflow.
  const Point3 corner[3] = {p0, p1, p2};
  Point3 edge[3];
  double largest = 0;
  for (int k = 0; k < 3; ++k) {
    edge[k] = corner[(k + 1) % 3] / 2 - corner[k] / 2;
    for (int i = 0; i < 3; ++i)
      largest = std::max(largest, std::abs(edge[k][i]));
  }
  if (!std::isfinite(largest)) return false; // non-finite coordinates are their own finding
  if (largest == 0) return true;
  int exponent = 0;
  std::frexp(largest, &exponent);
  // A power of two multiplies exactly; ldexp itself only where that power is out of range.
  const double scale = std::ldexp(1.0, -exponent);
  const bool in_range = std::abs(exponent) < 1000;
  for (Point3 &e : edge)
    for (int i = 0; i < 3; ++i)
      e[i] = in_range ? e[i] * scale : std::ldexp(e[i], -exponent);
  const double twice_area = (edge[0] ^ edge[1]).Norm();
  const double longest =
      std::max({edge[0].SquaredNorm(), edge[1].SquaredNorm(), edge[2].SquaredNorm()});
  return twice_area <= 2 * zero_area_tolerance * longest;
}

namespace {

std::string list_edges(const std::vector<std::array<int, 2>> &edges, size_t shown = 10) {
  std::string text;
  for (size_t i = 0; i < std::min(shown, edges.size()); ++i)
    text += (i ? ", " : "") + std::to_string(edges[i][0]) + "-" + std::to_string(edges[i][1]);
  if (edges.size() > shown) text += " and " + std::to_string(edges.size() - shown) + " more";
  return text;
}

std::string list_sizes(const std::vector<int> &sizes) {
  std::vector<int> sorted = sizes;
  std::sort(sorted.begin(), sorted.end(), std::greater<int>());
  return list_indices(sorted, 12);
}

void check_coordinates(const Mesh &mesh, Validation &out) {
  Finding finding(FindingKind::non_finite_coordinates);
  for (size_t v = 0; v < mesh.vert.size(); ++v) {
    const Point3 &p = mesh.vert[v].cP();
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      finding.vertices.push_back(int(v));
  }
  if (finding.vertices.empty()) return;
  finding.message = plural(finding.vertices.size(), "vertex has", "vertices have") +
                    " coordinates that are not finite numbers (NaN or infinity): vertices " +
                    list_indices(finding.vertices);
  out.findings.push_back(finding);
}

void check_doubled_faces(const Mesh &mesh, Validation &out);

void check_faces(const Mesh &mesh, Validation &out, bool doubled_faces_possible) {
  Finding repeated(FindingKind::repeated_vertex_in_face, true);
  Finding flat(FindingKind::zero_area_faces);
  Finding tiny(FindingKind::beyond_double_precision);
  // Sides at unit scale: halved (against overflow), then scaled by the unit scale's power of two.
  const int unit_exponent = unit_scale_of(mesh).exponent + 1;
  const double unit_factor = std::ldexp(1.0, unit_exponent); // exact where in range
  const bool factor_in_range = std::abs(unit_exponent) < 1000;
  auto unit_length = [&](const Point3 &a, const Point3 &b) {
    const Point3 half = b * 0.5 - a * 0.5;
    if (factor_in_range) return (half * unit_factor).Norm();
    return Point3(std::ldexp(half[0], unit_exponent), std::ldexp(half[1], unit_exponent),
                  std::ldexp(half[2], unit_exponent))
        .Norm();
  };
  enum : char { fine, repeats, zero_area, too_small };
  std::vector<char> kind(mesh.face.size());
  parallel_for(mesh.face.size(), [&](size_t f) {
    const MeshFace &face = mesh.face[f];
    if (repeats_a_vertex(face)) {
      kind[f] = repeats;
    } else if (has_zero_area(face)) {
      kind[f] = zero_area;
    } else {
      double longest = 0;
      for (int k = 0; k < 3; ++k)
        longest = std::max(longest, unit_length(face.cP(k), face.cP((k + 1) % 3)));
      kind[f] = longest < smallest_relative_face ? too_small : fine;
    }
  });
  for (size_t f = 0; f < kind.size(); ++f)
    if (kind[f] != fine)
      (kind[f] == repeats ? repeated : kind[f] == zero_area ? flat : tiny).faces.push_back(int(f));
  if (!tiny.faces.empty()) {
    tiny.message = plural(tiny.faces.size(), "face is", "faces are") +
                   " smaller than 1e-11 of the whole mesh, too small for double precision "
                   "beside the rest (a stray vertex far away, or coordinates in wildly "
                   "different units?): faces " +
                   list_indices(tiny.faces);
    tiny.remedies = {Remedy::check_units};
    out.findings.push_back(tiny);
  }
  if (!repeated.faces.empty()) {
    repeated.message = plural(repeated.faces.size(), "face uses", "faces use") +
                       " the same vertex twice (degenerate faces): faces " +
                       list_indices(repeated.faces);
    out.findings.push_back(repeated);
  }
  if (!flat.faces.empty()) {
    flat.message = plural(flat.faces.size(), "face has", "faces have") +
                   " zero area (corners on a line or at one point): faces " +
                   list_indices(flat.faces);
    flat.remedies = {Remedy::remove_zero_area_faces};
    out.findings.push_back(flat);
  }

  if (doubled_faces_possible) check_doubled_faces(mesh, out);
}

// Two faces on the same three vertices: a doubled face, or a flat pillow of two triangles.
void check_doubled_faces(const Mesh &mesh, Validation &out) {
  std::vector<std::array<int, 3>> triangles(mesh.face.size());
  for (size_t f = 0; f < mesh.face.size(); ++f)
    for (int k = 0; k < 3; ++k)
      triangles[f][size_t(k)] = index_of(mesh, mesh.face[f].cV(k));
  Finding doubled(FindingKind::duplicate_faces);
  for (const auto &pair : faces_on_the_same_vertices(triangles)) {
    doubled.faces.push_back(pair[0]); // both faces of the pair
    doubled.faces.push_back(pair[1]);
    doubled.edges.push_back(pair);
  }
  if (!doubled.faces.empty()) {
    std::sort(doubled.faces.begin(), doubled.faces.end());
    doubled.faces.erase(std::unique(doubled.faces.begin(), doubled.faces.end()),
                        doubled.faces.end());
    std::string pairs;
    for (size_t i = 0; i < std::min<size_t>(10, doubled.edges.size()); ++i)
      pairs += (i ? ", " : "") + std::to_string(doubled.edges[i][0]) + " and " +
               std::to_string(doubled.edges[i][1]);
    if (doubled.edges.size() > 10)
      pairs += " and " + std::to_string(doubled.edges.size() - 10) + " more";
    doubled.message = plural(doubled.edges.size(), "face uses", "faces use") +
                      " the same three vertices as another face (doubled faces): faces " + pairs;
    doubled.remedies = {Remedy::remove_duplicate_faces};
    doubled.edges.clear();
    out.findings.push_back(doubled);
  }
}

void check_vertices(const Mesh &mesh, Validation &out) {
  // Exact duplicates: sort by position, then compare neighbours.
  std::vector<int> order(mesh.vert.size());
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](int v) {
    const Point3 &p = mesh.vert[v].cP();
    return std::make_tuple(p[0], p[1], p[2]);
  };
  // A total order (ties by index): the same result from the parallel sort as from any other.
  const auto before = [&](int a, int b) { return key(a) < key(b) || (key(a) == key(b) && a < b); };
#if defined(_OPENMP)
  __gnu_parallel::sort(order.begin(), order.end(), before);
#else
  std::sort(order.begin(), order.end(), before);
#endif
  // Coinciding vertices on the edge of a hole are a seam that merging closes: a finding that
  // repair fixes. Elsewhere the topology keeps them apart and the map needs no position to
  // differ from another: a note.
  Finding duplicates(FindingKind::duplicate_vertices, true);
  std::vector<char> boundary;
  int kept_apart = 0;
  size_t first = 0; // where the run of vertices at the position of order[i] starts
  for (size_t i = 1; i < order.size(); ++i) {
    if (key(order[i]) != key(order[i - 1])) {
      first = i;
      continue;
    }
    if (boundary.empty()) boundary = boundary_vertices(mesh);
    if (!boundary[size_t(order[first])] || !boundary[size_t(order[i])]) {
      ++kept_apart;
      continue;
    }
    duplicates.edges.push_back({order[first], order[i]});
    duplicates.vertices.push_back(order[i]);
  }
  if (kept_apart)
    out.notes.push_back(plural(size_t(kept_apart), "vertex sits", "vertices sit") +
                        " exactly on another vertex that the surface keeps apart (coincident "
                        "vertices); they are kept as they are");
  if (!duplicates.vertices.empty()) {
    std::sort(duplicates.edges.begin(), duplicates.edges.end(),
              [](auto &a, auto &b) { return a[1] < b[1]; });
    std::sort(duplicates.vertices.begin(), duplicates.vertices.end());
    std::string pairs;
    for (size_t i = 0; i < std::min<size_t>(10, duplicates.edges.size()); ++i)
      pairs += (i ? ", " : "") + std::to_string(duplicates.edges[i][1]) + " = " +
               std::to_string(duplicates.edges[i][0]);
    if (duplicates.edges.size() > 10)
      pairs += " and " + std::to_string(duplicates.edges.size() - 10) + " more";
    duplicates.message =
        plural(duplicates.vertices.size(), "vertex sits", "vertices sit") +
        " exactly on another vertex along the edge of a hole (duplicate vertices on a "
        "seam, which repair merges): " +
        pairs;
    duplicates.remedies = {Remedy::repair};
    out.findings.push_back(duplicates);
  }

  std::vector<char> used(mesh.vert.size(), 0);
  for (const MeshFace &face : mesh.face)
    for (int c = 0; c < 3; ++c)
      used[index_of(mesh, face.cV(c))] = 1;
  Finding unused(FindingKind::unreferenced_vertices, true);
  for (size_t v = 0; v < used.size(); ++v)
    if (!used[v]) unused.vertices.push_back(int(v));
  if (!unused.vertices.empty()) {
    unused.message = plural(unused.vertices.size(), "vertex belongs", "vertices belong") +
                     " to no face (unreferenced vertices): vertices " +
                     list_indices(unused.vertices);
    unused.remedies = {Remedy::repair};
    out.findings.push_back(unused);
  }
}

std::array<int, 2> edge_key(const Mesh &mesh, const MeshFace &face, int e) {
  int a = index_of(mesh, face.cV0(e)), b = index_of(mesh, face.cV1(e));
  return {std::min(a, b), std::max(a, b)};
}

// Non-manifold edges: more than two faces on one edge. Returns whether there is one.
bool check_manifold_edges(Mesh &work, Validation &out) {
  Finding non_manifold(FindingKind::non_manifold_edges);
  std::set<std::array<int, 2>> seen;
  for (MeshFace &face : work.face) {
    if (face.IsD()) continue;
    for (int e = 0; e < 3; ++e) {
      if (vcg::face::IsManifold(face, e)) continue;
      const auto key = edge_key(work, face, e);
      if (!seen.insert(key).second) continue;
      vcg::face::Pos<MeshFace> around(&face, e);
      non_manifold.edges.push_back(key);
      non_manifold.sizes.push_back(around.NumberOfFacesOnEdge());
    }
  }
  if (!non_manifold.edges.empty()) {
    std::string where;
    for (size_t i = 0; i < std::min<size_t>(10, non_manifold.edges.size()); ++i)
      where += (i ? ", " : "") + std::to_string(non_manifold.edges[i][0]) + "-" +
               std::to_string(non_manifold.edges[i][1]) + " (" +
               std::to_string(non_manifold.sizes[i]) + " faces)";
    if (non_manifold.edges.size() > 10)
      where += " and " + std::to_string(non_manifold.edges.size() - 10) + " more";
    non_manifold.message = plural(non_manifold.edges.size(), "edge is", "edges are") +
                           " shared by more than two faces (non-manifold edges) between "
                           "vertices " +
                           where;
    non_manifold.remedies = {Remedy::split_nonmanifold};
    out.findings.push_back(non_manifold);
  }
  return !non_manifold.edges.empty();
}

// Non-manifold vertices: pieces of surface that meet only at a vertex.
void check_manifold_vertices(Mesh &work, Validation &out) {
  vcg::tri::Clean<Mesh>::CountNonManifoldVertexFF(work, true, true);
  Finding pinched(FindingKind::non_manifold_vertices);
  for (size_t v = 0; v < work.vert.size(); ++v)
    if (work.vert[v].IsS()) pinched.vertices.push_back(int(v));
  if (!pinched.vertices.empty()) {
    pinched.message = plural(pinched.vertices.size(), "vertex joins", "vertices join") +
                      " parts of the surface that touch only at that vertex (non-manifold "
                      "vertices): vertices " +
                      list_indices(pinched.vertices);
    pinched.remedies = {Remedy::split_nonmanifold};
    out.findings.push_back(pinched);
  }
}

// Boundary loops (only well defined where every edge is manifold).
void check_boundary_loops(Mesh &work, Validation &out) {
  Finding open(FindingKind::boundary_loops);
  for (const BoundaryLoop &loop : find_boundary_loops(work)) {
    open.vertices.push_back(loop.first_vertex);
    open.sizes.push_back(loop.length);
  }
  if (!open.sizes.empty()) {
    open.message = "the surface is open: it has " +
                   plural(open.sizes.size(), "boundary loop (hole)", "boundary loops (holes)") +
                   " of " + list_sizes(open.sizes) + " edges, through vertices " +
                   list_indices(open.vertices);
    open.remedies = {Remedy::close_holes};
    out.findings.push_back(open);
  }
}

// Connected components (through shared edges).
void check_components(Mesh &work, Validation &out) {
  std::vector<std::pair<int, MeshFace *>> components;
  vcg::tri::Clean<Mesh>::ConnectedComponents(work, components);
  if (components.size() > 1) {
    Finding several(FindingKind::several_components);
    for (auto &[size, representative] : components) {
      several.sizes.push_back(size);
      several.faces.push_back(index_of(work, representative));
    }
    several.message = "the mesh has " + std::to_string(components.size()) +
                      " separate parts (connected components) of " + list_sizes(several.sizes) +
                      " faces";
    out.findings.push_back(several);
  }
}

// Orientation: across each manifold edge the two faces must traverse it in opposite directions;
// where no choice of orientations agrees, the surface is not orientable.
void check_orientation(Mesh &work, Validation &out) {
  Finding flipped(FindingKind::inconsistent_orientation, true);
  std::set<std::array<int, 2>> flipped_seen;
  for (MeshFace &face : work.face) {
    if (face.IsD()) continue;
    for (int e = 0; e < 3; ++e)
      if (vcg::face::IsManifold(face, e) && !vcg::face::CheckOrientation(face, e)) {
        const auto key = edge_key(work, face, e);
        if (flipped_seen.insert(key).second) flipped.edges.push_back(key);
      }
  }
  if (!flipped.edges.empty()) {
    bool oriented = false, orientable = true;
    vcg::tri::Clean<Mesh>::OrientCoherentlyMesh(work, oriented, orientable);
    if (orientable) {
      flipped.message = plural(flipped.edges.size(), "edge has", "edges have") +
                        " its two faces pointing opposite ways (inconsistent orientation): "
                        "edges " +
                        list_edges(flipped.edges);
      flipped.remedies = {Remedy::repair};
      out.findings.push_back(flipped);
    } else {
      Finding klein(FindingKind::non_orientable);
      klein.edges = flipped.edges;
      klein.message = "the surface is not orientable (like a Moebius strip or a Klein bottle): no "
                      "choice of face orientations agrees across every edge; it has no conformal "
                      "map to the sphere";
      out.findings.push_back(klein);
    }
  }
}

// Topology on a copy without the faces that repeat a vertex (they have no proper edges).
void check_topology(const Mesh &mesh, Validation &out) {
  Mesh work;
  copy_with_face_adjacency(mesh, work);
  if (work.fn == 0) return;
  const bool non_manifold_edges = check_manifold_edges(work, out);
  check_manifold_vertices(work, out);
  if (!non_manifold_edges) check_boundary_loops(work, out);
  check_components(work, out);
  check_orientation(work, out);
}

} // namespace

Validation validate_mesh(const Mesh &mesh) {
  Validation out;
  if (mesh.vert.empty() || mesh.face.empty()) {
    Finding empty(FindingKind::empty_mesh);
    empty.message = mesh.vert.empty()
                        ? "the mesh has no vertices"
                        : "the mesh has " + plural(mesh.vert.size(), "vertex", "vertices") +
                              " but no faces (a point cloud?)";
    out.findings.push_back(empty);
    return out;
  }
  check_coordinates(mesh, out);
  // A closed, oriented, connected manifold surface has no topological finding, and no doubled
  // faces either (two faces on the same vertices would make a separate pillow or an edge run
  // twice one way): the common case, checked in linear time without a copy.
  const bool one_closed_surface = is_closed_oriented_connected_manifold(mesh);
  check_faces(mesh, out, !one_closed_surface);
  check_vertices(mesh, out);
  if (!one_closed_surface) check_topology(mesh, out);
  return out;
}

std::vector<std::array<int, 2>>
faces_on_the_same_vertices(const std::vector<std::array<int, 3>> &triangles) {
  std::vector<std::pair<std::array<int, 3>, int>> sorted_corners;
  sorted_corners.reserve(triangles.size());
  for (size_t f = 0; f < triangles.size(); ++f) {
    std::array<int, 3> corners = triangles[f];
    std::sort(corners.begin(), corners.end());
    if (corners[0] == corners[1] || corners[1] == corners[2]) continue; // uses a vertex twice
    sorted_corners.push_back({corners, int(f)});
  }
  std::sort(sorted_corners.begin(), sorted_corners.end());
  std::vector<std::array<int, 2>> pairs;
  for (size_t i = 1; i < sorted_corners.size(); ++i)
    if (sorted_corners[i].first == sorted_corners[i - 1].first)
      pairs.push_back({sorted_corners[i - 1].second, sorted_corners[i].second});
  return pairs;
}

InputError refusal(const Finding &finding, const std::string &more) {
  return InputError(finding.message + more, finding.remedies, finding.faces);
}

} // namespace meromorph
