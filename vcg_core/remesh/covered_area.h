// How much of the surface lies under each face of a lifted sphere: a conformal map shrinks long
// parts exponentially, so a whole limb can sit under one sphere face whose three corners lift to
// its base; the face's own (flat) area then says nothing of the limb, the area under it does.
//
// In:  the mapped surface (path_lifting.h), the largest area one sample may stand for; a lifted
//      sphere (layered_sphere_lift.h) to measure.
// Out: `SurfaceSamples`: the surface cut into samples of at most that area (each face's centroids
//      of an m x m split, m as small as the bound allows): per sample its area, surface position
//      and image on the sphere (the face's map, projected from the centre).
//      `SampleLocator::covered_areas`: per lifted face, the area of the samples whose image its
//      sphere triangle holds (of the lifted copies that hold it, the one whose lifted triangle lies
//      nearest the sample: the sheet the sample is on). Samples no face holds (in a
//      hole's gap) count nowhere.
#pragma once

#include <array>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "remesh/layered_sphere_lift.h"
#include "remesh/path_lifting.h"

namespace meromorph {

struct SurfaceSamples {
  std::vector<double> area;
  std::vector<Eigen::Vector3d> position, image;
};

SurfaceSamples sample_surface(const MappedSurface &surface, double largest_sample_area);

// Follows one lifted sphere through rounds of refinement: each call locates only the samples whose
// face is gone since the last call, among the faces that are new (they cover the same part of the
// sphere).
class SampleLocator {
public:
  explicit SampleLocator(const SurfaceSamples &samples);
  std::vector<double> covered_areas(const LiftedSphere &lifted);

private:
  using Corners = std::array<int, 3>;
  struct CornersHash {
    size_t operator()(const Corners &c) const {
      unsigned long long h = 0;
      for (int corner : c)
        h = h * 0x9E3779B97F4A7C15ULL + (unsigned long long)(unsigned)corner;
      return size_t(h ^ (h >> 29));
    }
  };
  const SurfaceSamples *samples_;
  std::vector<Corners> holder_; // per sample, its face's corners ({-1, -1, -1}: none)
  std::vector<char> located_;
  std::unordered_set<Corners, CornersHash> known_;
};

} // namespace meromorph
