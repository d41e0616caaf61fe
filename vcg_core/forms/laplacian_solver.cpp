#include "forms/laplacian_solver.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include "common/errors.h"
#include "common/serial_openmp.h"

namespace meromorph {

SolverKind solver_from_name(const std::string &name) {
  if (name == "cholmod") return SolverKind::cholmod;
  if (name == "ldlt") return SolverKind::eigen_ldlt;
  throw ArgumentError("unknown solver '" + name + "' (cholmod or ldlt)");
}

const char *solver_name(SolverKind kind) {
  return kind == SolverKind::cholmod ? "cholmod" : "ldlt";
}

namespace {

// Free vertices numbered densely; pinned ones get -1.
std::vector<int> free_numbering(int size, const std::vector<int> &pinned) {
  std::vector<int> numbering(size, 0);
  for (int p : pinned)
    numbering.at(p) = -1;
  int next = 0;
  for (int &n : numbering)
    if (n == 0) n = next++;
  return numbering;
}

// L restricted to the free vertices.
Eigen::SparseMatrix<double> restricted(const Eigen::SparseMatrix<double> &laplacian,
                                       const std::vector<int> &numbering, int free_count) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(size_t(laplacian.nonZeros()));
  for (int column = 0; column < laplacian.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator it(laplacian, column); it; ++it) {
      const int row = numbering[it.row()], col = numbering[it.col()];
      if (row >= 0 && col >= 0) entries.emplace_back(row, col, it.value());
    }
  Eigen::SparseMatrix<double> reduced(free_count, free_count);
  reduced.setFromTriplets(entries.begin(), entries.end());
  return reduced;
}

// CHOLMOD's fill-reducing ordering: AMD alone. By default CHOLMOD tries AMD and, where the fill
// looks high, METIS too and keeps the better; on these Laplacians the METIS attempt costs more than
// its lower fill saves (measured: eight x1024, 786k vertices: factorization 10.5 s -> 5.8 s,
// peak memory +9%; kitten x16 7.1 -> 4.4 s; maxplanck x64's map 17.9 -> 11.5 s).
template <class Factorization> void configure(Factorization &) {}
template <class Matrix> void configure(Eigen::CholmodSupernodalLLT<Matrix> &factorization) {
  cholmod_common &common = factorization.cholmod();
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_AMD;
}

template <class Factorization> class PinnedSolver : public LaplacianSolver {
public:
  PinnedSolver(const Eigen::SparseMatrix<double> &laplacian, const std::vector<int> &pinned)
      : numbering_(free_numbering(int(laplacian.rows()), pinned)),
        free_count_(int(laplacian.rows()) - int(pinned.size())) {
    configure(factorization_);
    const SerialOpenMP one_thread; // serial_openmp.h: CHOLMOD's fixed four threads per supernode
    factorization_.compute(restricted(laplacian, numbering_, free_count_));
    if (factorization_.info() != Eigen::Success)
      // Validation has accepted the mesh (connected, no degenerate faces): what is left is
      // geometry whose cotangent weights span more than double precision can factor.
      throw InputError("the cotangent Laplacian could not be factored: the triangles' sizes or "
                       "angles span more than double precision resolves (a vertex far from the "
                       "rest, a spike?)");
  }
  Eigen::VectorXd solve(const Eigen::VectorXd &b) const override {
    Eigen::VectorXd free_b(free_count_);
    for (size_t v = 0; v < numbering_.size(); ++v)
      if (numbering_[v] >= 0) free_b[numbering_[v]] = b[long(v)];
    const Eigen::VectorXd free_x = factorization_.solve(free_b);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
    for (size_t v = 0; v < numbering_.size(); ++v)
      if (numbering_[v] >= 0) x[long(v)] = free_x[numbering_[v]];
    return x;
  }

private:
  std::vector<int> numbering_;
  int free_count_;
  // Eigen's solve() is const, but CHOLMOD's wrapper keeps workspace in the object.
  mutable Factorization factorization_;
};

} // namespace

std::unique_ptr<LaplacianSolver> factor_laplacian(const Eigen::SparseMatrix<double> &laplacian,
                                                  SolverKind kind, const std::vector<int> &pinned) {
  using Matrix = Eigen::SparseMatrix<double>;
  if (kind == SolverKind::cholmod)
    return std::make_unique<PinnedSolver<Eigen::CholmodSupernodalLLT<Matrix>>>(laplacian, pinned);
  return std::make_unique<PinnedSolver<Eigen::SimplicialLDLT<Matrix>>>(laplacian, pinned);
}

} // namespace meromorph
