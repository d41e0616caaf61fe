// Where a uniform sampling of the sphere leaves the surface short of samples.
//
// In:  a mesh, each face's sample share (area_correction.h: image share over surface share; 1 is
//      fair), the fraction of its fair share below which a face counts as sparse, and the share of
//      the surface area from which a sparse region is worth a warning.
// Out: the regions (faces joined across shared sides) of sparse faces that cover at least that
//      share of the surface, largest first: their faces, share of the surface area, share of the
//      samples they get over their fair share, and a vertex of their sparsest face.
#pragma once

#include <vector>

#include "mesh/mesh.h"

namespace meromorph {

struct SparseRegion {
  int faces = 0;
  double area_share = 0;
  double sample_share = 0;
  int vertex = -1;
};

std::vector<SparseRegion> sparsely_sampled_regions(const Mesh &mesh,
                                                   const std::vector<double> &shares,
                                                   double sparse_below, double min_area_share);

} // namespace meromorph
