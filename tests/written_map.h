// An independent check of a written map: reads the layered-sphere file that `meromorph param
// --sphere` wrote, with a PLY parser and geometry of its own (nothing from the core), and
// re-derives what the report claims.
//
// In:  the sphere file (binary little-endian PLY: vertex x, y, z, int layer, uchar branch, int
//      source_vertex, int component; face vertex_indices) and the Euler characteristic of the
//      surface.
// Out: `WrittenMap`: folded faces (chordal image triangle with non-positive signed volume),
//      the local degree of every vertex (winding of its one-ring's image in the tangent-plane
//      stereographic chart at its image), the degree (total signed solid angle / 4 pi), whether
//      Riemann-Hurwitz holds, the `branch` property as written, and each layer's signed area over
//      4 pi (each face counted a third for the layer of each of its corners) with the area of the
//      faces along the cuts beside it.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

namespace meromorph::test {

struct WrittenMap {
  int vertices = 0, faces = 0;
  std::vector<std::array<double, 3>> sphere; // radial projections onto the unit sphere
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> layer, branch_property;
  std::vector<int> folded_faces;
  std::vector<int> local_degree;
  std::vector<int> branch_vertices; // local degree >= 2
  int ramification = 0;
  double area_over_4pi = 0;
  int degree = 0;
  bool riemann_hurwitz = false;
  std::vector<double> layer_coverage; // per layer: signed area / 4 pi
  // Per layer: the image area / 4 pi of the faces whose corners lie on several layers (along the
  // cuts), which the layer may cover in part: how far its coverage may be from 1 for that reason.
  std::vector<double> layer_cut_area;
  // Several parts and closed holes: the `source_vertex` and `component` properties, vertices on
  // a hole of the written surface (their winding is not measured: local degree 1), and per
  // component the signed area / 4 pi and the ramification.
  std::vector<int> source_vertex, component;
  std::vector<char> on_boundary;
  std::map<int, double> component_area_over_4pi;
  std::map<int, int> component_ramification;
};

// `component_spacing`: the report's; part k's sphere is centred at x = k * spacing.
WrittenMap read_written_map(const std::string &sphere_ply, int euler, double component_spacing = 0);

// Every per-vertex property of a binary little-endian PLY file (double, float, int, uchar), by
// name, as doubles: e.g. texture_u and texture_v of the surface `param -o` wrote.
std::map<std::string, std::vector<double>> read_vertex_columns(const std::string &surface_ply);

// A binary little-endian PLY file as written: every per-vertex property by name (as above) and
// the triangles (faces that hold only a vertex_indices list of uchar count and int indices), unless
// `with_faces` is false.
struct WrittenMesh {
  std::map<std::string, std::vector<double>> columns;
  std::vector<std::array<int, 3>> triangles;
};
WrittenMesh read_written_mesh(const std::string &surface_ply, bool with_faces = true);

// The mean corner-angle error in degrees between the surface as written by `param -o` (binary
// PLY with double x, y, z) and the chordal triangles of the written sphere.
double written_angle_error_degrees(const WrittenMap &map, const std::string &surface_ply);

} // namespace meromorph::test
