// Benchmark: each stage of the holomorphic-forms pipeline on generated tori of about 10k, 100k
// and 1M vertices, next to the floor (reading the mesh, assembling the Laplacian, one CHOLMOD
// factorization with 2g solves). Prints a Markdown table.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>

#include "forms/harmonic_forms.h"
#include "forms/holomorphic_pipeline.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "mesh/cotan_laplacian.h"
#include "mesh/mesh_edges.h"
#include "shapes/test_surfaces.h"

using namespace meromorph;

static double milliseconds(const std::function<void()> &work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

int main(int argc, char **argv) {
  std::vector<int> sizes = {10000, 100000, 1000000};
  if (argc > 1) sizes = {std::atoi(argv[1])};
  const std::string path =
      (std::filesystem::temp_directory_path() / "meromorph-bench.ply").string();
  std::printf(
      "| vertices | read | laplacian | factor (cholmod) | 2g solves | floor | forms total | "
      "homology | harmonic | holomorphic + periods |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (int target : sizes) {
    const int minor = int(std::lround(std::sqrt(target / 2.0)));
    Mesh generated;
    make_grid_torus(generated, 2.0, 1.0, 2 * minor, minor);
    write_mesh(generated, path);

    Mesh mesh;
    const double read = milliseconds([&] { read_mesh(path, mesh); });
    MeshEdges edges;
    std::vector<double> weights;
    Eigen::SparseMatrix<double> laplacian;
    const double assemble = milliseconds([&] {
      edges = build_mesh_edges(mesh);
      weights = cotan_weights(mesh, edges);
      laplacian = cotan_laplacian(mesh.VN(), edges, weights);
    });
    std::unique_ptr<LaplacianSolver> solver;
    const double factor = milliseconds([&] { solver = factor_laplacian(laplacian); });
    Eigen::VectorXd right = Eigen::VectorXd::Random(mesh.VN());
    right.array() -= right.mean();
    const double solves = milliseconds([&] {
      for (int k = 0; k < 2; ++k)
        solver->solve(right);
    });
    HolomorphicForms forms;
    const double total = milliseconds([&] { forms = compute_holomorphic_forms(mesh); });
    auto stage = [&](const char *name) {
      for (auto &[n, ms] : forms.timings_ms)
        if (n == name) return ms;
      return 0.0;
    };
    std::printf("| %d | %.0f ms | %.0f ms | %.0f ms | %.0f ms | %.0f ms | %.0f ms | %.0f ms | %.0f "
                "ms | %.0f ms |\n",
                mesh.VN(), read, assemble, factor, solves, read + assemble + factor + solves,
                read + total, stage("homology"), stage("harmonic"), stage("holomorphic"));
    std::fflush(stdout);
  }
  std::filesystem::remove(path);
  return 0;
}
