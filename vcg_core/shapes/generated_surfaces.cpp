#include "shapes/generated_surfaces.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/create/platonic.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/stat.h>

#include "common/errors.h"
#include "mesh/mesh_from_arrays.h"
#include "shapes/implicit_surface.h"

namespace meromorph {

void make_icosphere(Mesh &mesh, int subdivisions, double radius) {
  if (subdivisions < 0 || subdivisions > 9)
    throw ArgumentError("sphere subdivisions must be between 0 and 9");
  mesh.Clear();
  vcg::tri::Sphere(mesh, subdivisions);
  for (MeshVertex &v : mesh.vert)
    v.P() = v.P().Normalize() * radius;
  vcg::tri::Allocator<Mesh>::CompactEveryVector(mesh);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
  vcg::tri::UpdateBounding<Mesh>::Box(mesh);
}

void make_grid_torus(Mesh &mesh, double major_radius, double minor_radius, int major_segments,
                     int minor_segments) {
  if (!(major_radius > minor_radius && minor_radius > 0))
    throw ArgumentError("a torus of revolution needs radii R > r > 0");
  if (major_segments < 3 || minor_segments < 3)
    throw ArgumentError("a torus needs at least 3 segments around each circle");
  MeshArrays arrays;
  for (int i = 0; i < major_segments; ++i) {
    const double u = 2 * M_PI * i / major_segments;
    for (int j = 0; j < minor_segments; ++j) {
      const double v = 2 * M_PI * j / minor_segments;
      const double ring = major_radius + minor_radius * std::cos(v);
      arrays.positions.emplace_back(ring * std::cos(u), ring * std::sin(u),
                                    minor_radius * std::sin(v));
    }
  }
  auto at = [&](int i, int j) {
    return (i % major_segments) * minor_segments + (j % minor_segments);
  };
  for (int i = 0; i < major_segments; ++i)
    for (int j = 0; j < minor_segments; ++j) {
      // (u, v) is a positively oriented chart of the outward normal: quads (i,j) (i,j+1) (i+1,j+1).
      arrays.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      arrays.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  mesh_from_arrays(arrays, mesh);
  if (enclosed_volume(mesh) < 0) vcg::tri::Clean<Mesh>::FlipMesh(mesh);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
  vcg::tri::UpdateBounding<Mesh>::Box(mesh);
}

namespace {

double distance_to_circle(const Point3 &p, const Point3 &centre, double radius) {
  const double dx = p[0] - centre[0], dy = p[1] - centre[1], dz = p[2] - centre[2];
  const double radial = std::sqrt(dx * dx + dy * dy) - radius;
  return std::sqrt(radial * radial + dz * dz);
}

// Polynomial smooth minimum (blend width k): rings that come closer than k merge smoothly.
double smooth_min(double a, double b, double k) {
  const double h = std::clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
  return b * (1 - h) + a * h - k * h * (1 - h);
}

} // namespace

void make_implicit_torus(Mesh &mesh, double major_radius, double minor_radius, int resolution,
                         bool remesh) {
  if (!(major_radius > minor_radius && minor_radius > 0))
    throw ArgumentError("a torus of revolution needs radii R > r > 0");
  if (resolution < 6) throw ArgumentError("resolution must be at least 6");
  const double voxel = 2 * M_PI * minor_radius / resolution;
  const double extent = major_radius + minor_radius;
  const vcg::Box3d box(Point3(-extent, -extent, -minor_radius),
                       Point3(extent, extent, minor_radius));
  extract_isosurface(
      [&](const Point3 &p) {
        return distance_to_circle(p, Point3(0, 0, 0), major_radius) - minor_radius;
      },
      box, voxel, mesh, remesh);
}

namespace {

double distance_to_segment(const Point3 &p, const Point3 &a, const Point3 &b) {
  const Point3 ab = b - a;
  const double t = std::clamp(((p - a) * ab) / ab.SquaredNorm(), 0.0, 1.0);
  return (p - (a + ab * t)).Norm();
}

} // namespace

void make_tentacle_blob(Mesh &mesh, int tentacles, double length, int resolution, bool hole) {
  if (tentacles < 0 || tentacles > 32) throw ArgumentError("tentacles must be between 0 and 32");
  if (length < 1.0 || length > 20.0)
    throw ArgumentError("tentacle length must be between 1 and 20");
  if (resolution < 10) throw ArgumentError("resolution must be at least 10");
  // Directions spread by the golden-angle spiral; with a hole (along z), within 30 degrees of the
  // equator, so that every tentacle leaves the ring around the hole.
  std::vector<Point3> tips, roots;
  const double band = hole ? 0.5 : 1.0;
  for (int k = 0; k < tentacles; ++k) {
    const double z = band * (1.0 - 2.0 * (k + 0.5) / tentacles), r = std::sqrt(1 - z * z);
    const double phi = k * M_PI * (3.0 - std::sqrt(5.0));
    const Point3 direction(r * std::cos(phi), r * std::sin(phi), z);
    tips.push_back(direction * length);
    roots.push_back(hole ? direction * 0.75 : Point3(0, 0, 0));
  }
  const double tube = 0.12, voxel = 2.0 / resolution;
  vcg::Box3d box(Point3(-1, -1, -1), Point3(1, 1, 1));
  for (const Point3 &tip : tips) {
    box.Add(tip + Point3(tube, tube, tube));
    box.Add(tip - Point3(tube, tube, tube));
  }
  extract_isosurface(
      [&](const Point3 &p) {
        double d = p.Norm() - 1.0;
        if (hole) d = std::max(d, 0.45 - std::hypot(p[0], p[1]));
        for (size_t k = 0; k < tips.size(); ++k)
          d = smooth_min(d, distance_to_segment(p, roots[k], tips[k]) - tube, 0.2);
        return d;
      },
      box, voxel, mesh);
}

void make_genus_surface(Mesh &mesh, int genus, int resolution, bool remesh) {
  if (genus < 0 || genus > 64) throw ArgumentError("genus must be between 0 and 64");
  if (resolution < 10) throw ArgumentError("resolution must be at least 10");
  const double blend = 0.15;
  const double voxel = 2 * 1.35 / resolution;
  if (genus == 0) {
    const vcg::Box3d box(Point3(-1, -1, -1), Point3(1, 1, 1));
    extract_isosurface([](const Point3 &p) { return p.Norm() - 1.0; }, box, voxel, mesh, remesh);
    return;
  }
  // Rings of different sizes and tube radii along a gently bending row, each overlapping the next:
  // no symmetry, so for genus >= 3 the surface is not hyperelliptic (a generic conformal class).
  struct Ring {
    Point3 centre;
    double radius, tube;
  };
  std::vector<Ring> rings;
  for (int k = 0; k < genus; ++k) {
    Ring ring{Point3(0, 0, 0), 1.0 + 0.2 * std::sin(1.3 * k + 0.5),
              0.33 + 0.05 * std::cos(1.7 * k)};
    if (k > 0) {
      const Ring &previous = rings.back();
      const double step = previous.radius + ring.radius + 0.5 * (previous.tube + ring.tube);
      const double turn = 0.35 * std::sin(0.9 * k);
      ring.centre = previous.centre + Point3(step * std::cos(turn), step * std::sin(turn), 0);
    }
    rings.push_back(ring);
  }
  vcg::Box3d box;
  for (const Ring &ring : rings) {
    const double reach = ring.radius + ring.tube;
    box.Add(ring.centre + Point3(reach, reach, ring.tube));
    box.Add(ring.centre - Point3(reach, reach, ring.tube));
  }
  extract_isosurface(
      [&](const Point3 &p) {
        double d = distance_to_circle(p, rings[0].centre, rings[0].radius) - rings[0].tube;
        for (size_t k = 1; k < rings.size(); ++k)
          d = smooth_min(d, distance_to_circle(p, rings[k].centre, rings[k].radius) - rings[k].tube,
                         blend);
        return d;
      },
      box, voxel, mesh, remesh);
}

namespace {

// A hash of an edge's two vertex indices in [0, 1): the same from either side of the edge.
double edge_hash(const Mesh &mesh, const MeshVertex *a, const MeshVertex *b) {
  std::uint64_t x =
      std::uint64_t(std::min(index_of(mesh, a), index_of(mesh, b))) * 0x9E3779B97F4A7C15ull ^
      std::uint64_t(std::max(index_of(mesh, a), index_of(mesh, b))) * 0xC2B2AE3D27D4EB4Full;
  x ^= x >> 31;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 29;
  return double(x >> 11) / double(1ull << 53);
}

// An edge is split when its hash says so and that of no other side of its two faces does: at
// most one split per face, so every needle is one split's.
struct NeedleEdges {
  const Mesh *mesh;
  double fraction;
  bool operator()(vcg::face::Pos<MeshFace> ep) const {
    if (edge_hash(*mesh, ep.V(), ep.VFlip()) >= fraction) return false;
    for (const MeshFace *face : {ep.F(), ep.FFlip()})
      for (int k = 0; k < 3; ++k) {
        const MeshVertex *a = face->cV(k), *b = face->cV((k + 1) % 3);
        const bool this_edge = (a == ep.V() && b == ep.VFlip()) || (a == ep.VFlip() && b == ep.V());
        if (!this_edge && edge_hash(*mesh, a, b) < fraction) return false;
      }
    return true;
  }
};

// Moves the midpoint RefineE made towards the edge's lower-address end (the end MidPoint uses).
struct NeedlePlacement {
  const Mesh *mesh;
  void operator()(MeshVertex &made, vcg::face::Pos<MeshFace> ep) {
    const MeshVertex *a = std::min(ep.V(), ep.VFlip()), *b = std::max(ep.V(), ep.VFlip());
    const double t = 0.002 + 0.008 * edge_hash(*mesh, b, a);
    made.P() = a->cP() + (b->cP() - a->cP()) * t;
  }
};

} // namespace

void inject_needles(Mesh &mesh, double fraction) {
  if (!(fraction >= 0 && fraction <= 1))
    throw ArgumentError("the fraction of edges to split must be between 0 and 1");
  vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
  NeedlePlacement placement{&mesh};
  vcg::tri::MidPoint<Mesh, NeedlePlacement> midpoint(&mesh, &placement);
  NeedleEdges edges{&mesh, fraction};
  vcg::tri::RefineE(mesh, midpoint, edges);
  vcg::tri::Allocator<Mesh>::CompactEveryVector(mesh);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
  vcg::tri::UpdateBounding<Mesh>::Box(mesh);
}

void subdivide_flat(Mesh &mesh, int steps) {
  if (steps < 0 || steps > 8) throw ArgumentError("subdivision steps must be between 0 and 8");
  for (int step = 0; step < steps; ++step) {
    vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
    vcg::tri::Refine(mesh, vcg::tri::MidPoint<Mesh>(&mesh), 0.0);
    vcg::tri::Allocator<Mesh>::CompactEveryVector(mesh);
  }
  vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
  vcg::tri::UpdateBounding<Mesh>::Box(mesh);
}

} // namespace meromorph
