// Scale-safe geometry: conformal maps depend neither on position nor on scale, so the core
// computes on a copy of the mesh centred at the origin and scaled by a power of two to unit
// size. Squared lengths, areas and cotangents then never overflow or underflow, and every
// tolerance means the same on a mesh in nanometres as in light years.
//
// In:  a mesh with finite coordinates (validation refuses any other).
// Out: `UnitScale` (the centre and the power-of-two factor: unit = (input - centre) * factor,
//      exact up to one rounding), and the copy with the same vertices and faces in the same order;
//      or, with `UnitScaleInPlace`, the mesh itself moved to unit scale for as long as the object
//      lives and put back bit for bit after (its positions kept meanwhile: 24 bytes a vertex
//      instead of a second mesh).
#pragma once

#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

struct UnitScale {
  Point3 centre{0, 0, 0}; // the centre of the bounding box
  int exponent = 0;       // factor = 2^exponent; the largest |coordinate - centre| is in [0.5, 1)
  // The unit-scale position of an input position (safe up to the largest doubles).
  Point3 apply(const Point3 &position) const;
  // The input position of a unit-scale one.
  Point3 undo(const Point3 &unit) const;
};

UnitScale unit_scale_of(const Mesh &mesh);

// True when `mesh` is already centred and of unit size (a copy would change nothing that
// matters).
bool is_at_unit_scale(const Mesh &mesh);

// `unit` becomes the vertices of `mesh` moved by `scale`, with the same faces in the same order.
void copy_at_unit_scale(const Mesh &mesh, const UnitScale &scale, Mesh &unit);

class UnitScaleInPlace {
public:
  explicit UnitScaleInPlace(Mesh &mesh);
  ~UnitScaleInPlace();
  UnitScaleInPlace(const UnitScaleInPlace &) = delete;
  UnitScaleInPlace &operator=(const UnitScaleInPlace &) = delete;
  // The positions the vertices had before, by vertex index.
  const std::vector<Point3> &originals() const { return original_; }

private:
  Mesh &mesh_;
  std::vector<Point3> original_;
};

} // namespace meromorph
