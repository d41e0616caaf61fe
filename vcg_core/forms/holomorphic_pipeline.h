// The holomorphic 1-forms of a closed surface and their periods, stage by stage.
//
// In:  a mesh that validation accepts (closed, connected, oriented manifold), the solver to use,
//      and progress. Throws InputError naming the problem otherwise.
// Out: `HolomorphicForms`: the homology basis (2g loops), closed, harmonic and conjugate forms, the
//      canonical basis, the periods of the normalized holomorphic forms along it, the modulus
//      (genus 1, reduced) or the Riemann matrix (genus >= 2), the residuals that measure how
//      discrete the result is, and the time of each stage in milliseconds.
#pragma once

#include <complex>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "common/progress.h"
#include "forms/homology_basis.h"
#include "forms/intrinsic_delaunay.h"
#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"
#include "solvers/laplacian_solver.h"

namespace meromorph {

struct HolomorphicForms {
  int genus = 0;
  // Genus >= 1: the triangulation the forms are computed on (intrinsic_delaunay.h); the homology
  // basis and the harmonic forms live on its edges, `normalized` on the mesh's (the prepared mesh's
  // edges).
  std::shared_ptr<const IntrinsicDelaunay> intrinsic;
  HomologyBasis homology;
  std::vector<Eigen::VectorXd> harmonic;       // h_j, 2g of them
  Eigen::MatrixXd conjugate;                   // *h_j ~ sum_k C_jk h_k
  Eigen::MatrixXcd loop_periods;               // tau_j along primal loop k (2g x 2g)
  Eigen::MatrixXi wedge;                       // integral of omega_j ^ omega_k
  Eigen::MatrixXi symplectic;                  // canonical basis in omega coordinates
  Eigen::MatrixXcd a_periods, b_periods;       // phi_j along a_k, b_k (g x g)
  std::optional<std::complex<double>> modulus; // genus 1, reduced
  Eigen::MatrixXcd riemann_matrix;             // g x g (genus >= 1)
  std::vector<Eigen::VectorXcd> normalized;    // psi_m per edge: A-periods delta, B-periods Omega

  double closedness_residual = 0;   // max over faces and forms of |sum around the face|
  double coclosedness_residual = 0; // max over vertices of |div h| / max |w h|
  double conjugate_residual = 0;    // relative L2 error of the conjugate fit
  double wedge_rounding = 0;        // distance of the intersection numbers to integers
  double non_holomorphicity_mean = 0, non_holomorphicity_max = 0; // |g| / |f|, area-weighted mean
  std::vector<std::pair<std::string, double>> timings_ms;
  std::vector<std::string> notes; // validation's notes (harmless oddities of the mesh)
};

struct Validation;
struct PreparedMesh;

// `validated`: the mesh's validation when the caller has made it (and it found nothing); else
// the mesh is validated here.
HolomorphicForms compute_holomorphic_forms(const Mesh &mesh,
                                           SolverKind solver = SolverKind::cholmod,
                                           const Progress &progress = {},
                                           const Validation *validated = nullptr);

// The same on a mesh validated and prepared by the caller, at unit scale (prepared_mesh.h).
HolomorphicForms compute_holomorphic_forms(const PreparedMesh &prepared, SolverKind solver,
                                           const Progress &progress);

// Frees what only the forms' own computation and checks read (the intrinsic triangulation, the
// homology basis, the harmonic forms): the maps read the genus, `normalized`, the Riemann matrix,
// the modulus and the figures only. On a million-vertex genus-5 mesh that is about 300 MB.
void release_intermediates(HolomorphicForms &forms);

} // namespace meromorph
