// Aligning two flat tori: the affine map between their lattices that takes corresponding points
// of two genus-1 surfaces onto each other.
//
// In:  both surfaces as flat tori (match/flat_torus.h) and a function on each one's vertices that
//      does not depend on the triangulation, the placement or the size (the log conformal
//      factor, sphere_alignment.h); landmark pairs (source vertex, target vertex) when given.
// Out: `TorusAlignment`: in lattice coordinates, x -> M x + c (M an integer matrix of determinant
//      1: the lattices' bases matched, the extremal quasi-conformal map between the tori; c a
//      translation), the map's dilatation K = (|a| + |b|) / (|a| - |b|) for z -> a z + b conj(z)
//      (1 when the two conformal structures are the same), and how it was found. Candidates for M:
//      every basis change whose dilatation is within 25% of the least (the lattice's symmetries:
//      z -> -z always, quarter turns of a square torus, sixth turns of a hexagonal one). With
//      landmarks c is their mean and the candidate with the smallest residual is taken (ties, as
//      with one landmark, by the functions); without, M and c that best match the two functions
//      sampled on a grid of the torus: every translation of the grid tried, the best refined by a
//      local search. `alternatives`: other maps that fit within a fifth of the way from the best
//      to what a translation at random costs and within three times the best's cost (a
//      symmetric surface has several).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "match/flat_torus.h"

namespace meromorph {

struct TorusAlignment {
  Eigen::Matrix2i lattice_map = Eigen::Matrix2i::Identity(); // M
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();           // c
  double dilatation = 1;
  std::string method;
  double cost = 0;                  // automatic: mean squared difference of the functions
  double landmark_distance_max = 0; // flat, in units of the target's shortest period
  struct Alternative {
    Eigen::Matrix2i lattice_map;
    Eigen::Vector2d shift;
    double cost = 0;
  };
  std::vector<Alternative> alternatives;

  Eigen::Vector2d apply(const Eigen::Vector2d &x) const;
  Eigen::Vector2d apply_inverse(const Eigen::Vector2d &y) const;
};

struct TorusFunction {
  const FlatTorus &torus;
  const FlatTorusLocator &locator;
  const std::vector<std::array<int, 3>> &triangles; // the surface's, for the values
  const std::vector<double> &values;                // per vertex
};

TorusAlignment align_tori(const TorusFunction &source, const TorusFunction &target,
                          const std::vector<std::pair<int, int>> &landmarks);

// The dilatation of the affine map of lattice coordinates M from the torus of modulus
// tau_source to the torus of modulus tau_target.
double lattice_map_dilatation(const Eigen::Matrix2i &map, std::complex<double> tau_source,
                              std::complex<double> tau_target);

} // namespace meromorph
