#include "solvers/laplacian_solver.h"

#include <algorithm>

#include <cholmod.h>

#include <Eigen/SparseCholesky>

#include "common/errors.h"
#include "common/parallel_for.h"
#include "solvers/factorization_threads.h"
#include "solvers/metis_order.h"

namespace meromorph {

SolverKind solver_from_name(const std::string &name) {
  if (name == "cholmod") return SolverKind::cholmod;
  if (name == "ldlt") return SolverKind::eigen_ldlt;
  throw ArgumentError("unknown solver '" + name + "' (cholmod or ldlt)");
}

const char *solver_name(SolverKind kind) {
  return kind == SolverKind::cholmod ? "cholmod" : "ldlt";
}

Eigen::VectorXd LaplacianSolver::solve(const Eigen::VectorXd &right_hand_side) const {
  return solve_columns(right_hand_side);
}

Eigen::MatrixXd LaplacianSolver::solve_columns_releasing(Eigen::MatrixXd &&right_hand_sides) const {
  const Eigen::MatrixXd b = std::move(right_hand_sides);
  return solve_columns(b);
}

Eigen::MatrixXd LaplacianSolver::solve_columns_without_last(const Eigen::MatrixXd &, int) const {
  throw std::logic_error("this factorization has no leading-block solves");
}

namespace {

// Validation has accepted the mesh (connected, no degenerate faces): what is left is geometry
// whose cotangent weights span more than double precision can factor.
InputError not_factored() {
  return InputError("the cotangent Laplacian could not be factored: the triangles' sizes or "
                    "angles span more than double precision resolves (a vertex far from the "
                    "rest, a spike?)");
}

// The free vertices numbered densely in increasing order (pinned ones get -1), and back.
struct FreeVertices {
  std::vector<int> number, vertex;

  FreeVertices(int size, const std::vector<int> &pinned) : number(size_t(size), 0) {
    for (int p : pinned)
      number.at(size_t(p)) = -1;
    for (int v = 0; v < size; ++v)
      if (number[size_t(v)] == 0) {
        number[size_t(v)] = int(vertex.size());
        vertex.push_back(v);
      }
  }
  int count() const { return int(vertex.size()); }

  Eigen::MatrixXd gathered(const Eigen::MatrixXd &b) const {
    Eigen::MatrixXd out(count(), b.cols());
    for (int i = 0; i < count(); ++i)
      out.row(i) = b.row(vertex[size_t(i)]);
    return out;
  }
  Eigen::MatrixXd scattered(const Eigen::MatrixXd &x, long rows) const {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(rows, x.cols());
    for (int i = 0; i < count(); ++i)
      out.row(vertex[size_t(i)]) = x.row(i);
    return out;
  }
  // Positions (free numbers) in the order of `vertices`, pinned ones skipped; all free ones.
  std::vector<int> positions(const std::vector<int> &vertices) const {
    std::vector<int> out;
    for (int v : vertices)
      if (number.at(size_t(v)) >= 0) out.push_back(number[size_t(v)]);
    if (int(out.size()) != count())
      throw std::logic_error("an elimination order must list every free vertex once");
    return out;
  }
};

// The upper triangle of L restricted to the free vertices, compressed by columns: the free
// numbering keeps the vertices' order, so every column's rows stay sorted. (The upper one: from it
// CHOLMOD makes the permuted lower triangle its supernodal factorization reads in one transpose;
// from the lower one it takes two, both held at once.)
struct UpperTriangle {
  std::vector<int> column_start, rows;
  std::vector<double> values;

  UpperTriangle(const Eigen::SparseMatrix<double> &laplacian, const FreeVertices &free) {
    column_start.reserve(size_t(free.count()) + 1);
    rows.reserve(size_t(laplacian.nonZeros()) / 2 + size_t(free.count()));
    values.reserve(rows.capacity());
    column_start.push_back(0);
    for (int v : free.vertex) {
      const int column = free.number[size_t(v)];
      for (Eigen::SparseMatrix<double>::InnerIterator it(laplacian, v); it; ++it) {
        const int row = free.number[size_t(it.row())];
        if (row < 0 || row > column) continue; // pinned or below the diagonal
        rows.push_back(row);
        values.push_back(it.value());
      }
      column_start.push_back(int(rows.size()));
    }
  }
  void release() {
    std::vector<int>().swap(column_start);
    std::vector<int>().swap(rows);
    std::vector<double>().swap(values);
  }
  cholmod_sparse view() {
    cholmod_sparse a{};
    a.nrow = a.ncol = column_start.size() - 1;
    a.nzmax = rows.size();
    a.p = column_start.data();
    a.i = rows.data();
    a.x = values.data();
    a.stype = 1; // symmetric, upper triangle stored
    a.itype = CHOLMOD_INT;
    a.xtype = CHOLMOD_REAL;
    a.dtype = CHOLMOD_DOUBLE;
    a.sorted = 1;
    a.packed = 1;
    return a;
  }
};

// values[k] = old values[source[k]] for every k (`back`: the inverse, values[source[k]] = old
// values[k]); `source` is a permutation of the indices. Through one scratch column (independent
// loads over the cores, where following the permutation's cycles in place would wait on every
// load in turn).
void permute_column(double *values, const std::vector<int> &source, bool back,
                    std::vector<double> &scratch) {
  scratch.resize(source.size());
  if (back)
    parallel_for(source.size(), [&](size_t k) { scratch[size_t(source[k])] = values[k]; });
  else
    parallel_for(source.size(), [&](size_t k) { scratch[k] = values[source[k]]; });
  std::copy(scratch.begin(), scratch.end(), values);
}

// Below `relaxed_supernode_unknowns` the supernodes are amalgamated more than CHOLMOD's default
// (nrelax 4, 16, 48): a mesh Laplacian's elimination tree has thousands of supernodes of a few
// columns, and there the fixed cost of each supernode (its BLAS calls, its parallel regions)
// outweighs its arithmetic. Measured on the two-core machine, AMD order, factorization alone,
// least of six: maxplanck x4 (50k unknowns) 101 -> 56 ms, x16 (200k) 506 -> 319 ms, the factor
// holding 60% more entries (stored zeros: 135 -> 216 MB at 200k). Above it the default stays:
// the supernodes are larger, and the memory is what the large meshes are short of (relaxing up
// to 700k gained 5% at 334k for 130 MB more).
constexpr int relaxed_supernode_unknowns = 300000;
constexpr size_t relaxed_supernodes[3] = {16, 64, 192};

// From `nested_dissection_unknowns` on, where memory is what a two-core machine runs short of,
// the order is METIS's nested dissection (solvers/metis_order.h) instead of AMD: the factor holds
// 40% fewer entries, at the cost of METIS's ordering (one core: METIS cannot run twice at once).
// Measured, factorization stage and peak memory of `param`, genus 5 at 2.7M unknowns: AMD
// 23.2 s, factor 2.8 GB; METIS 32.5 s, factor 1.8 GB, peak 4.51 GiB. At 1M (genus 2) METIS's
// order made the stage 8.4 -> 11.0 s for 200 MB less peak: below 2M AMD stays.
constexpr int nested_dissection_unknowns = 2000000;

// CHOLMOD's supernodal LL^T, ordered by AMD alone (METIS's nested dissection from two million
// unknowns, above) or by the order given. By default CHOLMOD tries AMD and, where the fill looks
// high, METIS too (on one core) and keeps the better; on these Laplacians that attempt cost more
// than its lower fill saved (measured: eight x1024, 786k vertices: factorization 10.5 s -> 5.8 s
// without it). CHOLMOD keeps workspace in its common object: solves are not to be called from
// two threads at once.
class CholmodSolver : public LaplacianSolver {
public:
  CholmodSolver(FreeVertices free, UpperTriangle upper, const std::vector<int> &order)
      : free_(std::move(free)) {
    std::vector<int> given = order.empty() ? std::vector<int>{} : free_.positions(order);
    if (given.empty() && free_.count() >= nested_dissection_unknowns)
      given = nested_dissection_order(free_.count(), upper.column_start.data(), upper.rows.data());
    cholmod_start(&common_);
    common_.nmethods = 1;
    common_.method[0].ordering = given.empty() ? CHOLMOD_AMD : CHOLMOD_GIVEN;
    common_.supernodal = CHOLMOD_SUPERNODAL;
    if (free_.count() < relaxed_supernode_unknowns)
      for (int k = 0; k < 3; ++k)
        common_.nrelax[k] = relaxed_supernodes[k];
    // A given order is kept as it is: a postorder could move vertices meant to be eliminated
    // last (solve_columns_without_last) before others.
    common_.postorder = order.empty();
    const FactorizationThreads threads; // solvers/factorization_threads.h
    {
      cholmod_sparse matrix = upper.view();
      factor_ =
          cholmod_analyze_p(&matrix, given.empty() ? nullptr : given.data(), nullptr, 0, &common_);
      if (!factor_ || !factor_numerically(matrix, upper) || common_.status != CHOLMOD_OK ||
          factor_->minor < factor_->n) {
        release();
        throw not_factored();
      }
    }
  }
  ~CholmodSolver() override { release(); }

  Eigen::MatrixXd solve_columns(const Eigen::MatrixXd &b) const override {
    Eigen::MatrixXd free_b = free_.gathered(b);
    cholmod_dense right = dense_view(free_b);
    cholmod_dense *solution = cholmod_solve(CHOLMOD_A, factor_, &right, &common_);
    if (!solution) throw not_factored();
    return scattered_and_freed(solution, b.rows());
  }

  // Each column of b permuted in place so that its first rows are y = P b (its free rows in the
  // factor's order, the pinned ones after them), y = L^-T L^-1 y solved in place there
  // (CHOLMOD's supernodal solves, the column stride left at b's), the rows put back in place and
  // the pinned ones set to 0: no array besides b and one column.
  Eigen::MatrixXd solve_columns_releasing(Eigen::MatrixXd &&b) const override {
    if (!factor_->is_super) return LaplacianSolver::solve_columns_releasing(std::move(b));
    Eigen::MatrixXd x = std::move(b);
    const long rows = x.rows(), count = free_.count();
    std::vector<int> source = elimination_order(); // row k of y is row source[k] of b
    for (long v = 0; v < rows; ++v)
      if (free_.number[size_t(v)] < 0) source.push_back(int(v));
    std::vector<double> scratch;
    for (long c = 0; c < x.cols(); ++c)
      permute_column(x.col(c).data(), source, false, scratch);
    cholmod_dense view = dense_view(x);
    view.nrow = size_t(count); // the pinned rows below stay out of the solve
    cholmod_dense *workspace = cholmod_allocate_dense(size_t(x.cols()), factor_->maxesize,
                                                      size_t(x.cols()), CHOLMOD_REAL, &common_);
    const bool solved = workspace && cholmod_super_lsolve(factor_, &view, workspace, &common_) &&
                        cholmod_super_ltsolve(factor_, &view, workspace, &common_);
    cholmod_free_dense(&workspace, &common_);
    if (!solved) throw not_factored();
    for (long c = 0; c < x.cols(); ++c) {
      permute_column(x.col(c).data(), source, true, scratch);
      for (long k = count; k < rows; ++k)
        x(source[size_t(k)], c) = 0;
    }
    return x;
  }

  // L L^T = P A P^T: with the trailing rows of y = L^-1 P b set to 0, x = P^T L^-T y solves the
  // leading block and is 0 on the trailing rows.
  Eigen::MatrixXd solve_columns_without_last(const Eigen::MatrixXd &b,
                                             int last_count) const override {
    if (last_count < 0 || last_count > free_.count())
      throw std::logic_error("more vertices to leave out than the factor has");
    Eigen::MatrixXd free_b = free_.gathered(b);
    cholmod_dense right = dense_view(free_b);
    cholmod_dense *permuted = cholmod_solve(CHOLMOD_P, factor_, &right, &common_);
    cholmod_dense *forward =
        permuted ? cholmod_solve(CHOLMOD_L, factor_, permuted, &common_) : nullptr;
    cholmod_free_dense(&permuted, &common_);
    if (!forward) throw not_factored();
    Eigen::Map<Eigen::MatrixXd> y(static_cast<double *>(forward->x), free_b.rows(), free_b.cols());
    y.bottomRows(last_count).setZero();
    cholmod_dense *backward = cholmod_solve(CHOLMOD_Lt, factor_, forward, &common_);
    cholmod_free_dense(&forward, &common_);
    cholmod_dense *solution =
        backward ? cholmod_solve(CHOLMOD_Pt, factor_, backward, &common_) : nullptr;
    cholmod_free_dense(&backward, &common_);
    if (!solution) throw not_factored();
    return scattered_and_freed(solution, b.rows());
  }

  std::vector<int> elimination_order() const override {
    const int *permutation = static_cast<const int *>(factor_->Perm);
    std::vector<int> order(size_t(free_.count()));
    for (size_t k = 0; k < order.size(); ++k)
      order[k] = free_.vertex[size_t(permutation[k])];
    return order;
  }

private:
  // What cholmod_factorize does for a supernodal factor of an upper triangle (the lower triangle
  // of P A P^T, then the numeric factorization), the triangle freed between the two: at 2.7M
  // unknowns it was 140 MB of the peak, held beside the factor's values.
  bool factor_numerically(cholmod_sparse &matrix, UpperTriangle &upper) {
    if (!factor_->is_super) return cholmod_factorize(&matrix, factor_, &common_);
    cholmod_sparse *permuted =
        cholmod_ptranspose(&matrix, 2, static_cast<int *>(factor_->Perm), nullptr, 0, &common_);
    upper.release();
    double zero[2] = {0, 0};
    const bool factored =
        permuted && cholmod_super_numeric(permuted, nullptr, zero, factor_, &common_);
    cholmod_free_sparse(&permuted, &common_);
    return factored;
  }
  static cholmod_dense dense_view(Eigen::MatrixXd &columns) {
    cholmod_dense view{};
    view.nrow = size_t(columns.rows());
    view.ncol = size_t(columns.cols());
    view.nzmax = view.nrow * view.ncol;
    view.d = view.nrow;
    view.x = columns.data();
    view.xtype = CHOLMOD_REAL;
    view.dtype = CHOLMOD_DOUBLE;
    return view;
  }
  Eigen::MatrixXd scattered_and_freed(cholmod_dense *solution, long rows) const {
    const Eigen::Map<const Eigen::MatrixXd> x(static_cast<const double *>(solution->x),
                                              long(solution->nrow), long(solution->ncol));
    Eigen::MatrixXd out = free_.scattered(x, rows);
    cholmod_free_dense(&solution, &common_);
    return out;
  }
  void release() {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }

  FreeVertices free_;
  mutable cholmod_common common_;
  cholmod_factor *factor_ = nullptr;
};

// Eigen's simplicial LDL^T, its own AMD ordering (to check CHOLMOD against).
class EigenSolver : public LaplacianSolver {
public:
  EigenSolver(FreeVertices free, UpperTriangle upper) : free_(std::move(free)) {
    const Eigen::Map<const Eigen::SparseMatrix<double>> matrix(
        free_.count(), free_.count(), long(upper.rows.size()), upper.column_start.data(),
        upper.rows.data(), upper.values.data());
    factorization_.compute(matrix);
    if (factorization_.info() != Eigen::Success) throw not_factored();
  }
  Eigen::MatrixXd solve_columns(const Eigen::MatrixXd &b) const override {
    return free_.scattered(factorization_.solve(free_.gathered(b)), b.rows());
  }
  std::vector<int> elimination_order() const override {
    std::vector<int> order(size_t(free_.count()));
    const auto &position = factorization_.permutationP().indices(); // of each free vertex
    for (int k = 0; k < free_.count(); ++k)
      order[size_t(position[k])] = free_.vertex[size_t(k)];
    return order;
  }

private:
  FreeVertices free_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper> factorization_;
};

} // namespace

namespace {

std::unique_ptr<LaplacianSolver> factored(FreeVertices free, UpperTriangle upper, SolverKind kind,
                                          const std::vector<int> &elimination_order) {
  if (kind == SolverKind::cholmod)
    return std::make_unique<CholmodSolver>(std::move(free), std::move(upper), elimination_order);
  return std::make_unique<EigenSolver>(std::move(free), std::move(upper));
}

} // namespace

std::unique_ptr<LaplacianSolver> factor_laplacian(const Eigen::SparseMatrix<double> &laplacian,
                                                  SolverKind kind, const std::vector<int> &pinned,
                                                  const std::vector<int> &elimination_order) {
  FreeVertices free(int(laplacian.rows()), pinned);
  UpperTriangle upper(laplacian, free);
  return factored(std::move(free), std::move(upper), kind, elimination_order);
}

std::vector<int> elimination_order_with_last(const Eigen::SparseMatrix<double> &laplacian,
                                             const std::vector<int> &pinned,
                                             const std::vector<char> &eliminate_last) {
  const FreeVertices free(int(laplacian.rows()), pinned);
  UpperTriangle upper(laplacian, free);
  std::vector<int> group(size_t(free.count())), permutation(size_t(free.count()));
  for (int i = 0; i < free.count(); ++i)
    group[size_t(i)] = eliminate_last.at(size_t(free.vertex[size_t(i)])) ? 1 : 0;
  cholmod_common common;
  cholmod_start(&common);
  cholmod_sparse matrix = upper.view();
  const int ordered = cholmod_camd(&matrix, nullptr, 0, group.data(), permutation.data(), &common);
  cholmod_finish(&common);
  if (!ordered) return {}; // (out of memory) the factorization orders by AMD instead
  std::vector<int> order(permutation.size());
  for (size_t k = 0; k < order.size(); ++k)
    order[k] = free.vertex[size_t(permutation[k])];
  return order;
}

std::unique_ptr<LaplacianSolver> factor_laplacian(Eigen::SparseMatrix<double> &&laplacian,
                                                  SolverKind kind, const std::vector<int> &pinned,
                                                  const std::vector<int> &elimination_order) {
  FreeVertices free(int(laplacian.rows()), pinned);
  UpperTriangle upper(laplacian, free);
  Eigen::SparseMatrix<double>().swap(laplacian); // freed before the factor is allocated
  return factored(std::move(free), std::move(upper), kind, elimination_order);
}

} // namespace meromorph
