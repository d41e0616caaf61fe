#include "laplacian_solver.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include "errors.h"

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

// L without row and column 0.
Eigen::SparseMatrix<double> pinned(const Eigen::SparseMatrix<double> &laplacian) {
  const int n = int(laplacian.rows()) - 1;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(size_t(laplacian.nonZeros()));
  for (int column = 0; column < laplacian.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator it(laplacian, column); it; ++it)
      if (it.row() > 0 && it.col() > 0)
        entries.emplace_back(int(it.row()) - 1, int(it.col()) - 1, it.value());
  Eigen::SparseMatrix<double> reduced(n, n);
  reduced.setFromTriplets(entries.begin(), entries.end());
  return reduced;
}

template <class Factorization> class PinnedSolver : public LaplacianSolver {
public:
  explicit PinnedSolver(const Eigen::SparseMatrix<double> &laplacian) {
    factorization_.compute(pinned(laplacian));
    if (factorization_.info() != Eigen::Success)
      throw Error(ExitCode::internal_failure,
                  "the Laplacian could not be factored (is the mesh connected, without "
                  "degenerate faces?)");
  }
  Eigen::VectorXd solve(const Eigen::VectorXd &b) const override {
    const Eigen::Index n = b.size();
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    x.tail(n - 1) = factorization_.solve(b.tail(n - 1));
    return x;
  }

private:
  // Eigen's solve() is const, but CHOLMOD's wrapper keeps workspace in the object.
  mutable Factorization factorization_;
};

} // namespace

std::unique_ptr<LaplacianSolver> factor_laplacian(const Eigen::SparseMatrix<double> &laplacian,
                                                  SolverKind kind) {
  if (kind == SolverKind::cholmod)
    return std::make_unique<PinnedSolver<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>>>>(
        laplacian);
  return std::make_unique<PinnedSolver<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>>(
      laplacian);
}

} // namespace meromorph
