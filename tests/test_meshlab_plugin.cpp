// The MeshLab plugin in the real MeshLab: meshlabserver under xvfb-run loads it from the build tree
// the way a user without root runs it (scripts/meshlab_user.sh).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <sys/wait.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/mesh_reader.h"
#include "test_support.h"
#include "written_map.h"

namespace meromorph {
namespace {

namespace fs = std::filesystem;

class MeshLab {
public:
  // Runs meshlabserver with `arguments` as a user without root does (scripts/meshlab_user.sh: a
  // copy of meshlabserver beside a plugins/ folder with the system's plugins and the build tree's
  // meromorph plugin, never an installed copy); returns the exit code, the output in `log`.
  int run(const std::string &arguments, std::string &log) const {
    const std::string command = "cd '" + dir_.path("") + "' && timeout 300 xvfb-run -a bash '" +
                                MEROMORPH_SOURCE_DIR + "/scripts/meshlab_user.sh' --home '" +
                                dir_.path("meshlab") + "' --plugin '" + MEROMORPH_MESHLAB_PLUGIN +
                                "' meshlabserver " + arguments + " > run.log 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream stream(dir_.path("run.log"));
    std::stringstream text;
    text << stream.rdbuf();
    log = text.str();
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string path(const std::string &name) const { return dir_.path(name); }

private:
  test::TempDir dir_;
};

const std::string script = std::string(MEROMORPH_SOURCE_DIR) +
                           "/meshlab_plugin/examples/conformal_spherical_parameterization.mlx";
// The example script of the transfer: from layer 0 (the first -i) to layer 1, everything.
const std::string transfer_script =
    std::string(MEROMORPH_SOURCE_DIR) +
    "/meshlab_plugin/examples/transfer_through_conformal_sphere.mlx";

void expect_same_as_cli(const MeshLab &meshlab, const std::string &input, int branch_points) {
  std::string log;
  // MeshLab's own float copy of the input, so that MeshLab and the CLI see the same numbers.
  ASSERT_EQ(meshlab.run("-i " + input + " -o " + meshlab.path("input.ply"), log), 0) << log;
  ASSERT_EQ(meshlab.run("-i " + meshlab.path("input.ply") + " -o " + meshlab.path("meshlab.ply") +
                            " -m vt vq vf -s " + script,
                        log),
            0)
      << log;
  EXPECT_NE(log.find("Conformal spherical parameterization: genus"), std::string::npos) << log;
  const test::RunResult cli =
      test::run_cli({"param", meshlab.path("input.ply"), "-o", meshlab.path("cli.ply"), "--report",
                     meshlab.path("cli.json"), "--quiet"});
  ASSERT_EQ(cli.exit_code, 0) << cli.err;

  Mesh from_meshlab, from_cli;
  test::load_ply_attributes(meshlab.path("meshlab.ply"), from_meshlab);
  test::load_ply_attributes(meshlab.path("cli.ply"), from_cli);
  ASSERT_EQ(from_meshlab.VN(), from_cli.VN());
  std::ifstream report_stream(meshlab.path("cli.json"));
  const nlohmann::json report = nlohmann::json::parse(report_stream);
  std::set<int> branch;
  for (const auto &b : report["branch_points"])
    branch.insert(b["vertex"].get<int>());
  EXPECT_EQ(int(branch.size()), branch_points);
  std::set<int> selected;
  for (size_t v = 0; v < from_meshlab.vert.size(); ++v) {
    const MeshVertex &a = from_meshlab.vert[v], &b = from_cli.vert[v];
    EXPECT_NEAR(a.cT().U(), b.cT().U(), 1e-6) << v;
    EXPECT_NEAR(a.cT().V(), b.cT().V(), 1e-6) << v;
    EXPECT_EQ(a.cQ(), b.cQ()) << "quality holds the layer, vertex " << v;
    if (a.IsS()) selected.insert(int(v));
  }
  EXPECT_EQ(selected, branch) << "the selected vertices are the branch vertices";
}

TEST(MeshLabPlugin, TorusAndGenusTwoMatchTheCommandLine) {
  const MeshLab meshlab;
  const test::RunResult made = test::run_cli({"make", "torus", "-R", "2", "-r", "1", "--resolution",
                                              "20", "-o", meshlab.path("torus.ply")});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  expect_same_as_cli(meshlab, meshlab.path("torus.ply"), 4);
  expect_same_as_cli(meshlab, test::data_path("eight.off"), 6);
}

TEST(MeshLabPlugin, CadPartsGetTheVerticesTheMapNeeds) {
  // A plate with a hole as CAD programs export it: its own triangles cannot carry the map, so
  // the filter adds the vertices it needs, as the command line does (the same count, the same
  // texture coordinates at every vertex).
  const MeshLab meshlab;
  const test::RunResult made =
      test::run_cli({"make", "cad", "--holes", "1", "--segments", "64", "--thickness", "0.05", "-o",
                     meshlab.path("plate.ply")});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  expect_same_as_cli(meshlab, meshlab.path("plate.ply"), 4);
  Mesh plate, mapped;
  test::load_ply_attributes(meshlab.path("plate.ply"), plate);
  test::load_ply_attributes(meshlab.path("meshlab.ply"), mapped);
  EXPECT_GT(mapped.VN(), plate.VN()) << "vertices were added";
}

// The example script with one text replaced (it must be there), written as `name` beside the
// MeshLab copy; returns its path.
std::string script_with(const MeshLab &meshlab, const std::string &name, const std::string &from,
                        const std::string &to) {
  std::ifstream script_stream(script);
  std::stringstream script_text;
  script_text << script_stream.rdbuf();
  std::string text = script_text.str();
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  std::ofstream(meshlab.path(name)) << text;
  return meshlab.path(name);
}

TEST(MeshLabPlugin, HolesAreClosedForTheComputationOrRefused) {
  const MeshLab meshlab;
  std::string log;
  // Close holes off: refused, with the reason in the log, nothing written.
  const std::string refusing_script =
      script_with(meshlab, "refusing.mlx", "value=\"true\" name=\"closeHoles\"",
                  "value=\"false\" name=\"closeHoles\"");
  EXPECT_NE(meshlab.run("-i " + test::data_path("eight.hole.off") + " -o " + meshlab.path("x.ply") +
                            " -s " + refusing_script,
                        log),
            0);
  EXPECT_NE(log.find("Conformal Spherical Parameterization failed: the surface is open"),
            std::string::npos)
      << log;
  // What to do, in MeshLab's words: this filter's own parameter.
  EXPECT_NE(log.find("tick 'Close holes' in this filter's parameters"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(meshlab.path("x.ply")));
  // Close holes on (the default): mapped, every vertex keeps its texture coordinates, the log
  // says what was closed.
  ASSERT_EQ(meshlab.run("-i " + test::data_path("eight.hole.off") + " -o " +
                            meshlab.path("holed.ply") + " -m vt vq vf -s " + script,
                        log),
            0)
      << log;
  EXPECT_NE(log.find("genus 2, degree 2, 6 branch points"), std::string::npos) << log;
  EXPECT_NE(log.find("1 hole was closed for the computation only"), std::string::npos) << log;
  Mesh input, holed;
  test::load(test::data_path("eight.hole.off"), input);
  test::load_ply_attributes(meshlab.path("holed.ply"), holed);
  EXPECT_EQ(holed.VN(), input.VN());
  EXPECT_EQ(holed.FN(), input.FN());
}

TEST(MeshLabPlugin, NonManifoldSpotsAreSplitForTheComputation) {
  const MeshLab meshlab;
  std::string log;
  const std::string input = meshlab.path("cubes.off");
  std::ofstream(input) << test::cubes_sharing_an_edge_off();
  // With the layered sphere: a second layer, with copies of the shared edge's two vertices.
  const std::string sphere_script =
      script_with(meshlab, "sphere.mlx", "value=\"false\" name=\"layeredSphere\"",
                  "value=\"true\" name=\"layeredSphere\"");
  // Then MeshLab's own "Delete Current Mesh", so the layered sphere is what gets saved.
  std::ifstream sphere_stream(sphere_script);
  std::stringstream sphere_text;
  sphere_text << sphere_stream.rdbuf();
  std::string sphere_only = sphere_text.str();
  sphere_only.replace(sphere_only.find("</FilterScript>"), 15,
                      " <filter name=\"Delete Current Mesh\"/>\n</FilterScript>");
  const std::string sphere_only_script = meshlab.path("sphere_only.mlx");
  std::ofstream(sphere_only_script) << sphere_only;
  ASSERT_EQ(meshlab.run("-i " + input + " -o " + meshlab.path("cubes.ply") + " -m vt vq wt -s " +
                            sphere_script,
                        log),
            0)
      << log;
  EXPECT_NE(log.find("non-manifold spots taken apart for the computation: 2 vertices split into "
                     "4, 1 edge"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("2 separate parts"), std::string::npos) << log;
  Mesh cubes, sphere;
  test::load_ply_attributes(meshlab.path("cubes.ply"), cubes);
  EXPECT_EQ(cubes.VN(), 14);
  EXPECT_EQ(cubes.FN(), 24);
  std::string sphere_log;
  ASSERT_EQ(meshlab.run("-i " + input + " -o " + meshlab.path("cubes.sphere.ply") + " -s " +
                            sphere_only_script,
                        sphere_log),
            0)
      << sphere_log;
  test::load_ply_attributes(meshlab.path("cubes.sphere.ply"), sphere);
  EXPECT_EQ(sphere.VN(), 16);
  EXPECT_EQ(sphere.FN(), 24);
  for (const MeshVertex &v : sphere.vert) { // each cube on its own unit sphere, side by side
    const double x = v.cP()[0] - 2.5 * std::round(v.cP()[0] / 2.5);
    EXPECT_NEAR(std::sqrt(x * x + v.cP()[1] * v.cP()[1] + v.cP()[2] * v.cP()[2]), 1.0, 1e-5);
  }
}

TEST(MeshLabPlugin, FiltersAreListedWithTheirParameters) {
  const MeshLab meshlab;
  std::string log;
  ASSERT_EQ(meshlab.run("-d " + meshlab.path("filters.txt"), log), 0) << log;
  std::ifstream stream(meshlab.path("filters.txt"));
  std::stringstream text;
  text << stream.rdbuf();
  const std::string dump = text.str();
  const std::map<std::string, std::vector<std::string>> filters = {
      {"Conformal Spherical Parameterization",
       {"Texture coordinates", "Moebius normalization", "Genus 1: pole vertex",
        "Genus 0: pole face", "Genus >= 2: first form", "Genus >= 2: second form",
        "Seam-correct wedge texture coordinates", "Create the layered sphere", "Layer gap",
        "Close holes", "Split non-manifold spots", "Pack the parts' texture coordinates"}},
      {"Remesh through the Conformal Sphere",
       {"Vertices", "Edge length", "Max. surface distance (%)", "Even out the sampling"}}};
  for (const auto &[filter, labels] : filters) {
    const size_t at = dump.find(filter);
    ASSERT_NE(at, std::string::npos) << filter;
    const std::string section = dump.substr(at, dump.find("\\section", at + 1) - at);
    for (const std::string &label : labels)
      EXPECT_NE(section.find(label), std::string::npos) << filter << ": " << label;
  }
}

// The remesh filter on the genus-2 eight: a new current layer, closed with the same genus, about
// the asked vertex count, its quality the layer (0 or 1) and the six branch vertices selected.
TEST(MeshLabPlugin, RemeshThroughTheConformalSphereMakesANewLayerOfTheSameGenus) {
  const MeshLab meshlab;
  const std::string remesh_script = std::string(MEROMORPH_SOURCE_DIR) +
                                    "/meshlab_plugin/examples/remesh_through_conformal_sphere.mlx";
  std::string log;
  ASSERT_EQ(meshlab.run("-i " + test::data_path("eight.off") + " -o " +
                            meshlab.path("remeshed.ply") + " -m vq vf -s " + remesh_script,
                        log),
            0)
      << log;
  EXPECT_NE(log.find("Remesh through the conformal sphere: the mesh: remeshed through 2 layers"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("Hausdorff distance"), std::string::npos) << log;
  Mesh remeshed;
  test::load_ply_attributes(meshlab.path("remeshed.ply"), remeshed);
  EXPECT_NEAR(remeshed.VN(), 800, 80);
  std::set<std::pair<int, int>> sides;
  for (const auto &face : remeshed.face)
    for (int k = 0; k < 3; ++k) {
      const int a = int(vcg::tri::Index(remeshed, face.cV(k))),
                b = int(vcg::tri::Index(remeshed, face.cV((k + 1) % 3)));
      sides.insert({std::min(a, b), std::max(a, b)});
    }
  EXPECT_EQ(2 * int(sides.size()), 3 * remeshed.FN()) << "closed: every side on two faces";
  EXPECT_EQ(remeshed.VN() - int(sides.size()) + remeshed.FN(), -2) << "genus 2";
  int selected = 0;
  for (const auto &vertex : remeshed.vert) {
    EXPECT_TRUE(vertex.cQ() == 0 || vertex.cQ() == 1) << "quality holds the layer";
    selected += vertex.IsS();
  }
  EXPECT_EQ(selected, 6) << "the branch vertices are selected";
}

// The remesh filter sized by the largest distance instead of a vertex count: the summary in the
// log gives the Hausdorff distance both ways, each within the 0.5% asked.
TEST(MeshLabPlugin, RemeshWithinAMaxSurfaceDistance) {
  const MeshLab meshlab;
  std::ofstream(meshlab.path("within.mlx"))
      << "<!DOCTYPE FilterScript>\n<FilterScript>\n"
         " <filter name=\"Remesh through the Conformal Sphere\">\n"
         "  <Param type=\"RichInt\" value=\"800\" name=\"targetVertices\"/>\n"
         "  <Param type=\"RichFloat\" value=\"0\" name=\"edgeLength\"/>\n"
         "  <Param type=\"RichFloat\" value=\"0.5\" name=\"maxError\"/>\n"
         "  <Param type=\"RichBool\" value=\"true\" name=\"areaCorrect\"/>\n"
         " </filter>\n</FilterScript>\n";
  std::string log;
  ASSERT_EQ(meshlab.run("-i " + test::data_path("eight.off") + " -o " +
                            meshlab.path("remeshed.ply") + " -s " + meshlab.path("within.mlx"),
                        log),
            0)
      << log;
  const size_t at = log.find("Hausdorff distance ");
  ASSERT_NE(at, std::string::npos) << log;
  std::istringstream figures(log.substr(at + std::string("Hausdorff distance ").size()));
  double to = 0, from = 0;
  char percent = 0, slash = 0;
  figures >> to >> percent >> slash >> from;
  EXPECT_GT(to, 0.0) << log;
  EXPECT_LE(to, 0.5) << log;
  EXPECT_LE(from, 0.5) << log;
}

// Filters > Sampling > Transfer Attributes through the Conformal Sphere: a head with colours,
// texture coordinates and quality per vertex (functions of the position) copied onto the same head
// subdivided (every face into four), turned, shrunk and moved, as a second scan comes. Each of the
// subdivision's first vertices is a vertex of the head, so its true values are the head's.
// Beside it, MeshLab's own Vertex Attribute Transfer (closest point) on the same pair.
TEST(MeshLabPlugin, TransferAttributesThroughTheConformalSphereOntoAMovedRetriangulation) {
  const MeshLab meshlab;
  Mesh head;
  read_mesh(test::data_path("maxplanck.nf25k.off"), head);
  const size_t n = head.vert.size();
  vcg::Box3d box;
  for (const auto &v : head.vert)
    box.Add(v.cP());
  const auto unit = [&](const MeshVertex &v, int k) {
    return (v.cP()[k] - box.min[k]) / (box.max[k] - box.min[k]);
  };
  {
    std::ofstream ply(meshlab.path("painted.ply"));
    ply << "ply\nformat ascii 1.0\nelement vertex " << n
        << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
           "property uchar green\nproperty uchar blue\nproperty uchar alpha\nproperty float "
           "quality\nproperty float texture_u\nproperty float texture_v\nelement face "
        << head.face.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto &v : head.vert)
      ply << v.cP()[0] << " " << v.cP()[1] << " " << v.cP()[2] << " "
          << std::lround(255 * unit(v, 0)) << " " << std::lround(255 * unit(v, 1)) << " "
          << std::lround(255 * unit(v, 2)) << " 255 " << unit(v, 2) << " " << unit(v, 0) << " "
          << unit(v, 1) << "\n";
    for (const auto &f : head.face)
      ply << "3 " << vcg::tri::Index(head, f.cV(0)) << " " << vcg::tri::Index(head, f.cV(1)) << " "
          << vcg::tri::Index(head, f.cV(2)) << "\n";
  }
  ASSERT_EQ(
      test::run_cli({"make", "subdivide", test::data_path("maxplanck.nf25k.off"), "-o",
                     meshlab.path("scan.ply"), "--rigid-motion", "--seed", "3", "--scale", "0.5"})
          .exit_code,
      0);
  // The painted head as layer 0, the scan as layer 1 (the current one, written).
  const auto run_script = [&](const std::string &script_file, const std::string &output) {
    std::string log;
    EXPECT_EQ(meshlab.run("-i " + meshlab.path("painted.ply") + " -i " + meshlab.path("scan.ply") +
                              " -o " + meshlab.path(output) + " -m vc vq vt -s " + script_file,
                          log),
              0)
        << log;
    return log;
  };
  const std::string log = run_script(transfer_script, "ours.ply");
  EXPECT_NE(log.find("vertex colors, vertex texture coordinates, vertex quality"),
            std::string::npos)
      << log;
  std::ofstream(meshlab.path("meshlab_transfer.mlx"))
      << "<!DOCTYPE FilterScript>\n<FilterScript>\n <filter name=\"Vertex Attribute Transfer\">\n"
      << "  <Param type=\"RichMesh\" value=\"0\" name=\"SourceMesh\"/>\n"
         "  <Param type=\"RichMesh\" value=\"1\" name=\"TargetMesh\"/>\n"
         "  <Param type=\"RichBool\" value=\"false\" name=\"GeomTransfer\"/>\n"
         "  <Param type=\"RichBool\" value=\"false\" name=\"NormalTransfer\"/>\n"
         "  <Param type=\"RichBool\" value=\"true\" name=\"ColorTransfer\"/>\n"
         "  <Param type=\"RichBool\" value=\"true\" name=\"QualityTransfer\"/>\n"
         "  <Param type=\"RichBool\" value=\"false\" name=\"SelectionTransfer\"/>\n"
         "  <Param type=\"RichBool\" value=\"false\" name=\"QualityDistance\"/>\n"
         "  <Param type=\"RichAbsPerc\" value=\"1000\" min=\"0\" max=\"1000\" "
         "name=\"UpperBound\"/>\n"
         "  <Param type=\"RichBool\" value=\"false\" name=\"onSelected\"/>\n"
         " </filter>\n</FilterScript>\n";
  run_script(meshlab.path("meshlab_transfer.mlx"), "meshlabs.ply");
  double figures[2][3] = {};
  const char *files[2] = {"ours.ply", "meshlabs.ply"};
  for (int which = 0; which < 2; ++which) {
    const auto columns = test::read_written_mesh(meshlab.path(files[which]), false).columns;
    ASSERT_EQ(columns.at("x").size(), n + head.face.size() * 3 / 2) << "the scan's vertices";
    for (size_t v = 0; v < n; ++v) {
      const MeshVertex &truth = head.vert[v];
      for (int k = 0; k < 3; ++k)
        figures[which][0] += std::abs(columns.at(k == 0   ? "red"
                                                 : k == 1 ? "green"
                                                          : "blue")[v] -
                                      255 * unit(truth, k)) /
                             (3.0 * n);
      figures[which][1] += std::abs(columns.at("quality")[v] - unit(truth, 2)) / double(n);
      if (which == 0)
        figures[which][2] += std::hypot(columns.at("texture_u")[v] - unit(truth, 0),
                                        columns.at("texture_v")[v] - unit(truth, 1)) /
                             double(n);
    }
    std::cout << files[which] << ": colour error mean " << figures[which][0]
              << " of 255, quality error mean " << figures[which][1]
              << (which == 0 ? ", texture coordinate error mean " : "")
              << (which == 0 ? std::to_string(figures[which][2]) : "") << "\n";
  }
  EXPECT_LT(figures[0][0], 1.5);
  EXPECT_LT(figures[0][1], 0.005);
  EXPECT_LT(figures[0][2], 0.005);
  EXPECT_LT(figures[0][0], 0.1 * figures[1][0]) << "closer than MeshLab's closest-point transfer";
}

// The vertices, faces and per-face wedge texture coordinates of a binary little-endian PLY that
// MeshLab wrote with `-m wt` (vertex x, y, z floats; face lists vertex_indices and texcoord).
struct WedgePly {
  size_t vertices = 0;
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<float, 6>> texcoords;
};

WedgePly read_wedge_ply(const std::string &path) {
  std::ifstream stream(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(stream)), {});
  const size_t end = bytes.find("end_header\n");
  std::istringstream header(bytes.substr(0, end));
  WedgePly out;
  size_t faces = 0, vertex_bytes = 0;
  std::string line, element;
  std::vector<std::string> face_lists;
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string keyword, type;
    words >> keyword;
    if (keyword == "element") {
      size_t count = 0;
      words >> element >> count;
      (element == "vertex" ? out.vertices : faces) = count;
    } else if (keyword == "property" && element == "vertex") {
      words >> type;
      vertex_bytes += type == "double" ? 8 : type == "uchar" ? 1 : 4;
    } else if (keyword == "property" && element == "face") {
      std::string list, count, item, name;
      words >> list >> count >> item >> name;
      face_lists.push_back(name);
    }
  }
  size_t at = end + std::strlen("end_header\n") + out.vertices * vertex_bytes;
  for (size_t f = 0; f < faces; ++f) {
    std::array<int, 3> corners{};
    std::array<float, 6> uv{};
    for (const std::string &name : face_lists) {
      const int count = static_cast<unsigned char>(bytes.at(at++));
      for (int k = 0; k < count; ++k, at += 4) {
        if (name == "vertex_indices" && k < 3) std::memcpy(&corners[size_t(k)], &bytes[at], 4);
        if (name == "texcoord" && k < 6) std::memcpy(&uv[size_t(k)], &bytes[at], 4);
      }
    }
    out.faces.push_back(corners);
    out.texcoords.push_back(uv);
  }
  return out;
}

// The same filter with texture coordinates per wedge (a cylindrical map around the head's height
// axis, with its seam), as textured models carry them: each face of the receiving scan reads
// them from one side of the seam. Judged on the face corners at the scan's first vertices (the
// head's own). (The donor is PLY: Debian's meshlabserver 2020.09 aborts on every OBJ file.)
TEST(MeshLabPlugin, TransferredWedgeTextureCoordinatesKeepEachFaceOnOneSideOfTheSeam) {
  const MeshLab meshlab;
  Mesh head;
  read_mesh(test::data_path("maxplanck.nf25k.off"), head);
  const size_t n = head.vert.size();
  vcg::Box3d box;
  for (const auto &v : head.vert)
    box.Add(v.cP());
  const Point3 centre = box.Center();
  const auto cylinder_u = [&](const Point3 &p) {
    return std::atan2(p[1] - centre[1], p[0] - centre[0]) / (2 * M_PI) + 0.5;
  };
  const auto height = [&](const Point3 &p) { return (p[2] - box.min[2]) / box.DimZ(); };
  const auto near_axis = [&](const Point3 &p) {
    return std::hypot(p[0] - centre[0], p[1] - centre[1]) < 0.15 * box.DimX();
  };
  {
    std::ofstream ply(meshlab.path("painted.ply"));
    ply.precision(9);
    ply << "ply\nformat ascii 1.0\nelement vertex " << n
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
        << head.face.size()
        << "\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n"
           "end_header\n";
    for (const auto &v : head.vert)
      ply << v.cP()[0] << " " << v.cP()[1] << " " << v.cP()[2] << "\n";
    for (const auto &f : head.face) { // u on one side of the seam per face
      double u[3];
      for (int k = 0; k < 3; ++k)
        u[k] = cylinder_u(f.cV(k)->cP());
      if (*std::max_element(u, u + 3) - *std::min_element(u, u + 3) > 0.5)
        for (double &x : u)
          x += x < 0.5 ? 1 : 0;
      ply << "3 " << vcg::tri::Index(head, f.cV(0)) << " " << vcg::tri::Index(head, f.cV(1)) << " "
          << vcg::tri::Index(head, f.cV(2)) << " 6";
      for (int k = 0; k < 3; ++k)
        ply << " " << u[k] << " " << height(f.cV(k)->cP());
      ply << "\n";
    }
  }
  ASSERT_EQ(
      test::run_cli({"make", "subdivide", test::data_path("maxplanck.nf25k.off"), "-o",
                     meshlab.path("scan.ply"), "--rigid-motion", "--seed", "5", "--scale", "2"})
          .exit_code,
      0);
  std::string log;
  ASSERT_EQ(meshlab.run("-i " + meshlab.path("painted.ply") + " -i " + meshlab.path("scan.ply") +
                            " -o " + meshlab.path("textured.ply") + " -m wt -s " + transfer_script,
                        log),
            0)
      << log;
  EXPECT_NE(log.find("wedge texture coordinates"), std::string::npos) << log;
  const WedgePly scan = read_wedge_ply(meshlab.path("textured.ply"));
  ASSERT_EQ(scan.faces.size(), 4 * head.face.size());
  double error = 0;
  int corners = 0, straddling = 0;
  for (size_t f = 0; f < scan.faces.size(); ++f) {
    double low = 1e9, high = -1e9;
    bool axis = false;
    for (int k = 0; k < 3; ++k) {
      const double u = scan.texcoords[f][size_t(2 * k)], v = scan.texcoords[f][size_t(2 * k + 1)];
      low = std::min(low, u), high = std::max(high, u);
      const size_t vertex = size_t(scan.faces[f][size_t(k)]);
      if (vertex >= n) continue;
      const Point3 &p = head.vert[vertex].cP();
      axis = axis || near_axis(p);
      if (near_axis(p)) continue;
      const double du = std::fmod(std::abs(u - cylinder_u(p)), 1.0);
      error += std::hypot(std::min(du, 1 - du), v - height(p));
      ++corners;
    }
    straddling += !axis && high - low > 0.5;
  }
  error /= std::max(corners, 1);
  std::cout << "wedge texture coordinates: error mean " << error << " over " << corners
            << " corners, " << straddling << " faces across the seam\n";
  EXPECT_GT(corners, int(n / 2));
  EXPECT_LT(error, 0.003);
  EXPECT_EQ(straddling, 0);
}

} // namespace
} // namespace meromorph
