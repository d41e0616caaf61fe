// Benchmark: the whole main job (`parameterize`) on generated surfaces of genus 0 to 3 and about
// 10k to 1M vertices: the time of the forms (Laplacian, factorization, homology, harmonic and
// holomorphic forms), of the map (meromorphic function, centring, branch placement), of branching
// and layers, and of texture coordinates and distortion, with the total and the peak memory (each
// surface runs in a process of its own). Prints a Markdown table.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "maps/parameterization.h"
#include "shapes/test_surfaces.h"

using namespace meromorph;

namespace {

double peak_megabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0; // kilobytes on Linux
}

struct Case {
  std::string name;
  std::function<void(Mesh &)> make;
};

} // namespace

int main() {
  const std::vector<Case> cases = {
      {"icosphere, genus 0", [](Mesh &m) { make_icosphere(m, 5); }},
      {"icosphere, genus 0", [](Mesh &m) { make_icosphere(m, 7); }},
      {"icosphere, genus 0", [](Mesh &m) { make_icosphere(m, 8); }},
      {"grid torus, genus 1", [](Mesh &m) { make_grid_torus(m, 2.0, 1.0, 140, 70); }},
      {"grid torus, genus 1", [](Mesh &m) { make_grid_torus(m, 2.0, 1.0, 448, 224); }},
      {"grid torus, genus 1", [](Mesh &m) { make_grid_torus(m, 2.0, 1.0, 1414, 707); }},
      {"chain, genus 2", [](Mesh &m) { make_genus_surface(m, 2, 40); }},
      {"chain, genus 2", [](Mesh &m) { make_genus_surface(m, 2, 130); }},
      {"chain, genus 3", [](Mesh &m) { make_genus_surface(m, 3, 40); }},
      {"chain, genus 3", [](Mesh &m) { make_genus_surface(m, 3, 110); }},
  };
  std::printf("| surface | vertices | forms | map | branching + layers | uv + distortion | total | "
              "Riemann-Hurwitz | peak memory |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  std::fflush(stdout); // before fork, or each child prints the header again
  for (const Case &c : cases) {
    const pid_t child = fork();
    if (child > 0) {
      int status = 0;
      waitpid(child, &status, 0);
      if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        std::printf("| %s | failed (status %d) |\n", c.name.c_str(), status);
      continue;
    }
    Mesh mesh;
    c.make(mesh);
    const Parameterization map = parameterize(mesh);
    std::map<std::string, double> stage;
    double total = 0;
    for (const auto &[name, ms] : map.timings_ms) {
      total += ms;
      if (name == "meromorphic" || name == "mobius" || name == "branch_placement")
        stage["map"] += ms;
      else if (name == "branching")
        stage["branching"] += ms;
      else if (name == "texture_and_quality")
        stage["uv"] += ms;
      else
        stage["forms"] += ms;
    }
    std::printf("| %s | %d | %.0f ms | %.0f ms | %.0f ms | %.0f ms | %.0f ms | %s | %.0f MB |\n",
                c.name.c_str(), mesh.VN(), stage["forms"], stage["map"], stage["branching"],
                stage["uv"], total, map.riemann_hurwitz_ok ? "holds" : "FAILS", peak_megabytes());
    std::fflush(stdout);
    std::_Exit(0);
  }
}
