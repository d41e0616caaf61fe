// A closed genus-1 surface as a flat torus: the integral of its normalized holomorphic 1-form,
// in the reduced basis of its lattice, and the triangles of the surface found by a flat point.
//
// In:  a closed genus-1 mesh, its edges (mesh_edges.h) and the normalized holomorphic form psi on
//      them (A-period 1, B-period tau; holomorphic_pipeline.h).
// Out: `FlatTorus`: the reduced modulus tau (|Re tau| <= 1/2, |tau| >= 1, Im tau > 0: the lattice
//      Z + Z tau has its shortest period 1), per vertex its lattice coordinates (u, v) (the flat
//      point u + v tau, up to the lattice; zero at vertex 0), per face its corners' lattice
//      coordinates developed across the face (corner 0 in [0, 1)^2), and the flat area of each
//      face. `FlatTorusLocator::holding(p)`: the face whose developed triangle holds the flat
//      point p (lattice coordinates, any representative) and p's weights at its corners; where no
//      face holds it exactly (rounding between faces), the nearest face among those looked at;
//      -1 where none. Faces are kept in cells of a periodic grid of every size 2^-level, each at
//      the level of its size, so the exponentially small faces of a long part and the large ones
//      elsewhere are both found in a few lookups.
#pragma once

#include <array>
#include <complex>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"

namespace meromorph {

struct FlatTorus {
  std::complex<double> tau;
  std::vector<Eigen::Vector2d> vertex;               // (u, v) per vertex
  std::vector<std::array<Eigen::Vector2d, 3>> faces; // developed corners per face
  std::vector<double> face_areas;                    // flat area (the torus's is Im tau)

  // The flat point u + v tau.
  std::complex<double> point(const Eigen::Vector2d &uv) const { return uv[0] + uv[1] * tau; }
  // The lattice coordinates of a flat point.
  Eigen::Vector2d coordinates(std::complex<double> z) const;
  // The shortest flat displacement between two points of the torus (lattice coordinates).
  double distance(const Eigen::Vector2d &a, const Eigen::Vector2d &b) const;
};

FlatTorus flat_torus(const Mesh &mesh, const MeshEdges &edges, const Eigen::VectorXcd &psi,
                     std::complex<double> period_b);

// The basis of the lattice Z + Z tau reduced (Gauss): returns (w1, w2) with w2 / w1 in the
// fundamental domain and the orientation kept.
std::array<std::complex<double>, 2> reduced_lattice_basis(std::complex<double> tau);

class FlatTorusLocator {
public:
  explicit FlatTorusLocator(const FlatTorus &torus);
  struct Hold {
    int face = -1;
    Eigen::Vector3d weights = Eigen::Vector3d::Zero();
  };
  Hold holding(const Eigen::Vector2d &p) const;

private:
  static constexpr int max_level = 28;
  static std::uint64_t key(int level, std::int64_t i, std::int64_t j);
  const FlatTorus &torus_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
  std::array<bool, max_level + 1> used_{};
};

} // namespace meromorph
