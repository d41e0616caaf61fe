// Benchmark on meshes like users': the shared meshes of genus 0, 1 and 2 (maxplanck, kitten,
// eight) and generated genus-5 and genus-10 surfaces (no shared mesh has those), each subdivided
// flat (every face into four, the same surface) three times, the largest nearest 1M vertices (so
// about 50k, 200k and 800k: each step multiplies by four). Per mesh, each job in a process of its
// own (so its peak memory is its own):
// - the floor: reading the file, the cotangent Laplacian, one CHOLMOD factorization (supernodal,
//   CHOLMOD's default ordering, every OpenMP region through libgomp as in any program) and 2g
//   solves (two for genus 0, the map's two coordinates);
// - the main job as `meromorph param` runs it: reading the file and `parameterize_surface`, with
//   the time of every stage, the rest (validation) and the total, the ratio of the total to the
//   floor, the peak memory, and the longest time without a call of the progress callback.
// Both jobs run with the process settings of the CLI (cli/process_settings.h), each
// REPEATS times (default 3), one after the other in turns; the run with the least total of each
// is shown (a shared virtual machine's run-to-run noise is 10-30%, always upwards).
// Then per genus and stage the scaling exponent: the slope of log time against log vertices over
// the sizes (least squares). Prints Markdown tables.
//
// Usage: bench_meshes SHARED_MESHES_DIR [SIZES LARGEST_VERTICES [REPEATS]]
//        bench_meshes --mesh MESH_FILE [REPEATS]: the same row for one mesh of one's own (one
//        closed surface; its genus from its Euler characteristic).
//        bench_meshes --large [REPEATS]: the same row for the generated genus-5 surface at 2.7M
//        vertices (default one run: about a minute and a half each).
//        bench_meshes --threads SHARED_MESHES_DIR [REPEATS]: `param` with the default threads
//        against one thread, on an idle machine and beside one and two busy processes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <csignal>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/CholmodSupport>
#if defined(_OPENMP)
#include <omp.h>
#endif

#include "cli/process_settings.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "job/surface_map.h"
#include "mesh/cotan_laplacian.h"
#include "mesh/mesh_edges.h"
#include "shapes/generated_surfaces.h"

using namespace meromorph;

// OpenBLAS's own call, where it is the BLAS (null otherwise).
extern "C" void openblas_set_num_threads(int threads) __attribute__((weak));

namespace {

using Figures = std::map<std::string, double>;

// The stages of the table, in the order `parameterize_surface` runs them.
const std::vector<std::string> stages = {
    "read",          "prepare",          "laplacian",   "homology",
    "factorization", "harmonic",         "holomorphic", "meromorphic",
    "mobius",        "branch_placement", "branching",   "texture_and_quality",
    "rest"};

double milliseconds(const std::function<void()> &work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

double peak_megabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0; // kilobytes on Linux
}

// `job` in a child process; the figures it returns come back through a pipe.
Figures in_child(const std::function<Figures()> &job) {
  int ends[2];
  if (pipe(ends) != 0) std::abort();
  std::fflush(stdout);
  const pid_t child = fork();
  if (child == 0) {
    close(ends[0]);
    std::ostringstream text;
    text.precision(17); // every digit (a vertex count of seven digits came back rounded to six)
    try {
      for (const auto &[name, value] : job())
        text << name << " " << value << "\n";
    } catch (const std::exception &error) {
      std::fprintf(stderr, "bench: %s\n", error.what());
      std::_Exit(1);
    }
    text << "peak_mb " << peak_megabytes() << "\n";
    const std::string bytes = text.str();
    if (write(ends[1], bytes.data(), bytes.size()) != ssize_t(bytes.size())) std::_Exit(1);
    std::_Exit(0);
  }
  close(ends[1]);
  std::string bytes;
  char buffer[4096];
  for (ssize_t n; (n = read(ends[0], buffer, sizeof buffer)) > 0;)
    bytes.append(buffer, size_t(n));
  close(ends[0]);
  int status = 0;
  waitpid(child, &status, 0);
  Figures figures;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return figures;
  std::istringstream lines(bytes);
  std::string name;
  for (double value; lines >> name >> value;)
    figures[name] = value;
  return figures;
}

struct Source {
  std::string name;
  int genus;
  std::function<void(Mesh &)> make;
};

Figures floor_job(const std::string &path, int genus) {
  // OpenBLAS as any program has it: a thread per CPU.
  if (openblas_set_num_threads) openblas_set_num_threads(int(std::thread::hardware_concurrency()));
  Figures out;
  Mesh mesh;
  out["read"] = milliseconds([&] { read_mesh(path, mesh); });
  Eigen::SparseMatrix<double> laplacian;
  out["laplacian"] = milliseconds([&] {
    const MeshEdges edges = build_mesh_edges(mesh);
    laplacian = cotan_laplacian(mesh.VN(), edges, cotan_weights(mesh, edges));
  });
  // CHOLMOD as anyone calls it: supernodal, its default ordering (AMD, and METIS too where the
  // fill looks high), not the settings meromorph chose for itself.
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> solver;
  laplacian.coeffRef(0, 0) += laplacian.coeff(0, 0); // grounded at vertex 0: positive definite
  out["factorization"] = milliseconds([&] { solver.compute(laplacian); });
  if (solver.info() != Eigen::Success) throw std::runtime_error("the floor's factorization failed");
  Eigen::VectorXd right = Eigen::VectorXd::Random(mesh.VN());
  right.array() -= right.mean();
  out["solves"] = milliseconds([&] {
    for (int k = 0; k < std::max(2, 2 * genus); ++k)
      right = solver.solve(right);
  });
  out["floor"] = out["read"] + out["laplacian"] + out["factorization"] + out["solves"];
  return out;
}

Figures param_job(const std::string &path) {
  Figures out;
  const auto start = std::chrono::steady_clock::now();
  Mesh mesh;
  out["read"] = milliseconds([&] { read_mesh(path, mesh); });
  cli::tune_blas_for_job(mesh.VN()); // as the CLI does once it has read the mesh
  // The longest time without a progress report (from the start, between reports, to the end):
  // what a MeshLab or Blender user waits without the bar moving or a chance to cancel.
  auto last_report = std::chrono::steady_clock::now();
  double longest_silence = 0;
  const auto note_silence = [&] {
    const auto now = std::chrono::steady_clock::now();
    longest_silence = std::max(
        longest_silence, std::chrono::duration<double, std::milli>(now - last_report).count());
    last_report = now;
  };
  const Parameterization map =
      parameterize_surface(mesh, {}, Progress([&](double, const std::string &) {
                             note_silence();
                             return true;
                           }));
  note_silence();
  out["silence"] = longest_silence;
  out["total"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  double staged = out["read"];
  for (const auto &[stage, ms] : map.timings_ms) {
    out[stage] += ms;
    staged += ms;
  }
  out["rest"] = out["total"] - staged;
  out["vertices"] = mesh.VN();
  out["degree"] = map.degree;
  out["valid"] = map.valid;
  return out;
}

// Least-squares slope of log y against log x.
double slope(const std::vector<double> &x, const std::vector<double> &y) {
  const size_t n = x.size();
  double mx = 0, my = 0;
  for (size_t i = 0; i < n; ++i) {
    mx += std::log(x[i]) / double(n);
    my += std::log(std::max(y[i], 1e-3)) / double(n);
  }
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < n; ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(std::max(y[i], 1e-3)) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxx > 0 ? sxy / sxx : 0.0;
}

// `sizes` subdivision steps one after the other, the last one's vertex count (about 4^k times
// the base) nearest `largest` on a log scale.
std::vector<int> steps_for(double base_vertices, int sizes, double largest) {
  const int top = std::max(0, int(std::lround(std::log(largest / base_vertices) / std::log(4.0))));
  std::vector<int> steps;
  for (int k = std::max(0, top - sizes + 1); k <= top; ++k)
    steps.push_back(k);
  return steps;
}

// Each job `repeats` times, one after the other in turns; the run with the least total of each.
// Both empty where a run failed.
void best_of(const std::string &path, int genus, int repeats, Figures &floor, Figures &param) {
  floor = param = {};
  for (int run = 0; run < repeats; ++run) {
    const Figures floor_run = in_child([&] { return floor_job(path, genus); });
    const Figures param_run = in_child([&] { return param_job(path); });
    if (floor_run.empty() || param_run.empty()) {
      floor = param = {};
      return;
    }
    if (floor.empty() || floor_run.at("floor") < floor.at("floor")) floor = floor_run;
    if (param.empty() || param_run.at("total") < param.at("total")) param = param_run;
  }
}

void print_header() {
  std::printf("| mesh | vertices | genus |");
  for (const std::string &stage : stages)
    std::printf(" %s |", stage.c_str());
  std::printf(" param | floor | ratio | factorization | degree | peak memory | longest silence "
              "|\n|---|---|---|");
  for (size_t i = 0; i < stages.size() + 7; ++i)
    std::printf("---|");
  std::printf("\n");
}

void print_row(const std::string &name, int genus, const Figures &floor, Figures &param) {
  std::printf("| %s | %.0f | %d |", name.c_str(), param["vertices"], genus);
  for (const std::string &stage : stages)
    std::printf(" %.0f |", param[stage]);
  std::printf(" %.0f ms | %.0f ms | %.1f | %.0f ms | %.0f%s | %.0f MB | %.0f ms |\n",
              param["total"], floor.at("floor"), param["total"] / floor.at("floor"),
              floor.at("factorization"), param["degree"], param["valid"] ? "" : " (invalid)",
              param["peak_mb"], param["silence"]);
}

// One mesh of the user's: its genus from its Euler characteristic (one closed surface).
int mesh_file_row(const std::string &path, int repeats, const std::string &name) {
  // Read in a child of its own: a forked job's resident set starts with what this process holds
  // (and freed memory is kept), which would count in every job's peak.
  const Figures shape = in_child([&]() -> Figures {
    Mesh mesh;
    read_mesh(path, mesh);
    const MeshEdges edges = build_mesh_edges(mesh);
    return {{"genus", (2 - (mesh.VN() - edges.edge_count() + mesh.FN())) / 2},
            {"vertices", mesh.VN()}};
  });
  if (shape.empty()) {
    std::printf("| %s | could not be read |\n", path.c_str());
    return 1;
  }
  const int genus = int(shape.at("genus"));
  Figures floor, param;
  best_of(path, genus, repeats, floor, param);
  print_header();
  if (floor.empty() || param.empty()) {
    std::printf("| %s | %.0f | failed |\n", path.c_str(), shape.at("vertices"));
    return 1;
  }
  print_row(name, genus, floor, param);
  return 0;
}

// The largest size: the generated genus-5 surface at 34 edges per ring (10,518
// vertices) subdivided flat four times, 2,694,648 vertices, written to `path` and measured.
int large_row(const std::string &path, int repeats) {
  const Figures made = in_child([&]() -> Figures {
    Mesh mesh;
    make_genus_surface(mesh, 5, 34);
    subdivide_flat(mesh, 4);
    write_mesh(mesh, path);
    return {{"vertices", double(mesh.VN())}};
  });
  if (made.empty()) {
    std::printf("the large genus-5 mesh could not be made\n");
    return 1;
  }
  const int status = mesh_file_row(path, repeats, "genus 5 (generated, 34 per ring) x256");
  std::filesystem::remove(path);
  return status;
}

// Processes that keep a core busy (a loop with nothing to wait for), as other work on the machine
// does, until `stop_busy` ends them.
std::vector<pid_t> start_busy(int count) {
  std::vector<pid_t> busy;
  for (int k = 0; k < count; ++k) {
    const pid_t child = fork();
    if (child == 0) {
      volatile double x = 1;
      while (true)
        x = x * 1.0000001 + 1e-9;
    }
    busy.push_back(child);
  }
  return busy;
}

void stop_busy(const std::vector<pid_t> &busy) {
  for (pid_t child : busy) {
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
  }
}

// `param` with the default threads and with one thread (omp_set_num_threads(1) in the job's
// process: the threads policy, common/job_threads.h, then has one to give), on an idle machine
// and beside one and two busy processes; the least of `repeats` runs each, in turns.
int threads_table(const std::string &shared, int repeats) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("meromorph-bench-threads-" + std::to_string(getpid()) + ".ply"))
                               .string();
  struct Case {
    std::string name;
    std::function<void(Mesh &)> make;
  };
  const std::vector<Case> cases = {
      {"maxplanck x1", [&](Mesh &m) { read_mesh(shared + "/maxplanck.nf25k.off", m); }},
      {"maxplanck x4",
       [&](Mesh &m) { read_mesh(shared + "/maxplanck.nf25k.off", m), subdivide_flat(m, 1); }},
      {"kitten x1", [&](Mesh &m) { read_mesh(shared + "/kitten.nv40k.off", m); }},
      {"kitten x4",
       [&](Mesh &m) { read_mesh(shared + "/kitten.nv40k.off", m), subdivide_flat(m, 1); }},
      {"eight x64", [&](Mesh &m) { read_mesh(shared + "/eight.off", m), subdivide_flat(m, 3); }},
      {"eight x256", [&](Mesh &m) { read_mesh(shared + "/eight.off", m), subdivide_flat(m, 4); }},
      {"genus 5 (generated) x16",
       [](Mesh &m) { make_genus_surface(m, 5, 24), subdivide_flat(m, 2); }},
  };
  std::printf("| mesh | vertices | idle: default | idle: one thread | ratio | one busy "
              "process: default | one thread | ratio | two busy: default | one thread | ratio "
              "|\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Case &c : cases) {
    const Figures made = in_child([&]() -> Figures {
      Mesh mesh;
      c.make(mesh);
      write_mesh(mesh, path);
      return {{"vertices", double(mesh.VN())}};
    });
    if (made.empty()) continue;
    std::printf("| %s | %.0f |", c.name.c_str(), made.at("vertices"));
    for (int busy_count : {0, 1, 2}) {
      double least[2] = {1e300, 1e300};
      for (int run = 0; run < repeats; ++run)
        for (int one : {0, 1}) {
          const std::vector<pid_t> busy = start_busy(busy_count);
          const Figures figures = in_child([&] {
#if defined(_OPENMP)
            if (one) omp_set_num_threads(1);
#endif
            return param_job(path);
          });
          stop_busy(busy);
          if (!figures.empty()) least[one] = std::min(least[one], figures.at("total"));
        }
      std::printf(" %.0f ms | %.0f ms | %.2f |", least[0], least[1], least[0] / least[1]);
    }
    std::printf("\n");
    std::fflush(stdout);
  }
  std::filesystem::remove(path);
  return 0;
}

// The scaling exponents per genus and stage, over the sizes of the main table.
void print_exponents(const std::map<int, std::vector<Figures>> &by_genus) {
  std::printf("\nScaling exponent (time ~ vertices^p, fitted over the sizes):\n\n| genus |");
  for (const std::string &stage : stages)
    std::printf(" %s |", stage.c_str());
  std::printf(" param | floor | floor factorization |\n|---|");
  for (size_t i = 0; i < stages.size() + 3; ++i)
    std::printf("---|");
  std::printf("\n");
  for (const auto &[genus, rows] : by_genus) {
    if (rows.size() < 2) continue;
    std::vector<double> vertices;
    for (const Figures &row : rows)
      vertices.push_back(row.at("vertices"));
    auto exponent = [&](const std::string &key) {
      std::vector<double> times;
      for (const Figures &row : rows)
        times.push_back(row.count(key) ? row.at(key) : 0.0);
      return slope(vertices, times);
    };
    std::printf("| %d |", genus);
    for (const std::string &stage : stages) {
      // A stage this genus does not have, or under 10 ms at every size (whose exponent would be
      // the clock's noise: genus 0's Moebius centring, 0.03 to 3 ms), is shown as "-".
      bool ran = false;
      for (const Figures &row : rows)
        ran = ran || (row.count(stage) && row.at(stage) >= 10);
      if (ran)
        std::printf(" %.2f |", exponent(stage));
      else
        std::printf(" - |");
    }
    std::printf(" %.2f | %.2f | %.2f |\n", exponent("total"), exponent("floor"),
                exponent("floor_factorization"));
  }
}

// The main table: five meshes at `sizes` sizes up to `largest` vertices, then the exponents.
int main_table(const std::string &shared, int sizes, double largest, int repeats) {
  const std::vector<Source> sources = {
      {"maxplanck", 0, [&](Mesh &m) { read_mesh(shared + "/maxplanck.nf25k.off", m); }},
      {"kitten", 1, [&](Mesh &m) { read_mesh(shared + "/kitten.nv40k.off", m); }},
      {"eight", 2, [&](Mesh &m) { read_mesh(shared + "/eight.off", m); }},
      {"genus 5 (generated)", 5, [](Mesh &m) { make_genus_surface(m, 5, 24); }},
      {"genus 10 (generated)", 10, [](Mesh &m) { make_genus_surface(m, 10, 24); }},
  };
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("meromorph-bench-" + std::to_string(getpid()) + ".ply"))
                               .string();
  print_header();
  std::map<int, std::vector<Figures>> by_genus;
  for (const Source &source : sources) {
    Mesh base;
    source.make(base);
    for (int steps : steps_for(base.VN(), sizes, largest)) {
      const std::string name = source.name + " x" + std::to_string(1 << (2 * steps));
      const Figures made = in_child([&]() -> Figures {
        Mesh mesh;
        source.make(mesh);
        subdivide_flat(mesh, steps);
        write_mesh(mesh, path);
        return {{"vertices", double(mesh.VN())}};
      });
      if (made.empty()) {
        std::printf("| %s | could not be made |\n", name.c_str());
        continue;
      }
      Figures floor, param;
      best_of(path, source.genus, repeats, floor, param);
      if (floor.empty() || param.empty()) {
        std::printf("| %s | %.0f | failed |\n", name.c_str(), made.at("vertices"));
        continue;
      }
      print_row(name, source.genus, floor, param);
      param["floor"] = floor.at("floor");
      param["floor_factorization"] = floor.at("factorization");
      by_genus[source.genus].push_back(param);
    }
  }
  std::filesystem::remove(path);
  print_exponents(by_genus);
  return 0;
}

} // namespace

int main(int argc, char **argv) {
  if (argc < 2 || (std::string(argv[1]) == "--mesh" && argc < 3)) {
    std::fprintf(stderr,
                 "usage: bench_meshes SHARED_MESHES_DIR [SIZES LARGEST_VERTICES [REPEATS]]\n"
                 "       bench_meshes --mesh MESH_FILE [REPEATS]\n"
                 "       bench_meshes --large [REPEATS]\n"
                 "       bench_meshes --threads SHARED_MESHES_DIR [REPEATS]\n");
    return 2;
  }
  cli::tune_command_line_process();
  if (std::string(argv[1]) == "--mesh")
    return mesh_file_row(argv[2], argc > 3 ? std::max(1, std::atoi(argv[3])) : 3,
                         std::filesystem::path(argv[2]).filename().string());
  if (std::string(argv[1]) == "--threads")
    return threads_table(argc > 2 ? argv[2] : "../shared/meshes",
                         argc > 3 ? std::max(1, std::atoi(argv[3])) : 3);
  if (std::string(argv[1]) == "--large")
    return large_row((std::filesystem::temp_directory_path() /
                      ("meromorph-bench-large-" + std::to_string(getpid()) + ".ply"))
                         .string(),
                     argc > 2 ? std::max(1, std::atoi(argv[2])) : 1);
  return main_table(argv[1], argc > 2 ? std::max(1, std::atoi(argv[2])) : 3,
                    argc > 3 ? std::atof(argv[3]) : 1e6,
                    argc > 4 ? std::max(1, std::atoi(argv[4])) : 3);
}
