// Moebius area correction (Choi, Leung-Liu, Gu, Lui 2020, "Moebius area correction"): the
// conformal map made as even in area as a Moebius transformation can make it.
//
// In:  the mesh (its faces and positions give the surface areas), the unit-sphere position per
//      vertex (the map, linear on each face) and the degree d (the image covers the sphere d
//      times).
// Out: `sample_shares`: per face, its share of the image (spherical area over d * 4 pi) over its
//      share of the surface area (1: as many samples of a uniform sphere as its area deserves;
//      0 for faces of zero area or folded image). `area_distortion`: the mean over faces of
//      positive area of |log(share)|. `correct_area`: the positions moved, in place, by the ball
//      translation x -> T_c(x) (mobius_centering.h) that minimises the area distortion (rotations
//      do not change areas, so c in the unit ball is the whole family that matters), found by
//      Nelder-Mead over c = tanh(|y|) y / |y| on at most 200k faces spread over the mesh; the
//      distortion before and after, measured on every face, and c. The translation is shortened
//      (halved, at most 7 times) until it turns no more faces over than before, and kept only when
//      it lowers the distortion. Orientation, degree and branching are unchanged.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace meromorph {

struct AreaCorrection {
  bool applied = false;
  double distortion_before = 0, distortion_after = 0;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
};

std::vector<double> sample_shares(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere,
                                  int degree);

double area_distortion(const Mesh &mesh, const std::vector<Eigen::Vector3d> &sphere, int degree);

AreaCorrection correct_area(const Mesh &mesh, std::vector<Eigen::Vector3d> &sphere, int degree);

} // namespace meromorph
