// Outputs are all-or-nothing and never clash; results do not depend on the unit; odd but valid
// meshes (pillows, coincident vertices, huge and tiny coordinates) get a map or a clear refusal.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace meromorph {
namespace {

using test::run_cli;
using test::TempDir;

bool exists(const std::string &path) {
  return std::filesystem::exists(path);
}

// What is in `dir`, files, folders and links alike: no output and no partial file or staging
// folder is left.
size_t files_in(const TempDir &dir) {
  size_t count = 0;
  for ([[maybe_unused]] const auto &entry : std::filesystem::directory_iterator(dir.path("")))
    ++count;
  return count;
}

std::string file_text(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

nlohmann::json read_json(const std::string &path) {
  std::ifstream stream(path);
  return nlohmann::json::parse(stream);
}

// eight.off with every coordinate multiplied by `scale`, as a new OFF file.
std::string scaled_eight(const TempDir &dir, double scale) {
  std::ifstream in(test::data_path("eight.off"));
  std::string keyword;
  size_t vertices = 0, faces = 0, edges = 0;
  in >> keyword >> vertices >> faces >> edges;
  std::ostringstream out;
  out.precision(17);
  out << "OFF\n" << vertices << " " << faces << " 0\n";
  for (size_t v = 0; v < vertices; ++v) {
    double x, y, z;
    in >> x >> y >> z;
    out << x * scale << " " << y * scale << " " << z * scale << "\n";
  }
  for (size_t f = 0; f < faces; ++f) {
    int n, a, b, c;
    in >> n >> a >> b >> c;
    out << "3 " << a << " " << b << " " << c << "\n";
  }
  std::ostringstream name;
  name << "eight_" << scale << ".off";
  return dir.write(name.str(), out.str());
}

TEST(Outputs, AllOrNothing) {
  TempDir dir;
  const std::string input = dir.write("eight.off", [] {
    std::ifstream in(test::data_path("eight.off"));
    return std::string(std::istreambuf_iterator<char>(in), {});
  }());
  // A report in a folder that does not exist: exit 4 with the system's reason, and neither the
  // surface nor the sphere is left behind.
  const test::RunResult missing_folder =
      run_cli({"param", input, "-o", dir.path("out.ply"), "--sphere", dir.path("sphere.ply"),
               "--report", dir.path("no/such/folder/r.json"), "--quiet"});
  EXPECT_EQ(missing_folder.exit_code, 4) << missing_folder.err;
  EXPECT_NE(missing_folder.err.find("No such file or directory"), std::string::npos)
      << missing_folder.err;
  EXPECT_EQ(files_in(dir), 1u) << "only the input is left";

  // Two outputs naming the same file, or an output that is a folder: exit 2, nothing written.
  for (const std::vector<std::string> &clash :
       {std::vector<std::string>{"-o", dir.path("a.ply"), "--sphere", dir.path("a.ply")},
        {"-o", dir.path("a.ply"), "--report", dir.path("./a.ply")},
        {"-o", dir.path("")}}) {
    std::vector<std::string> arguments = {"param", input, "--quiet"};
    arguments.insert(arguments.end(), clash.begin(), clash.end());
    const test::RunResult r = run_cli(arguments);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(files_in(dir), 1u);
  }
  EXPECT_EQ(run_cli({"param", input, "-o", dir.path("a.ply"), "--layer-gap", "nan"}).exit_code, 2);
  EXPECT_EQ(run_cli({"param", input, "-o", dir.path("a.ply"), "--layer-gap", "inf"}).exit_code, 2);

  // A successful run writes all three.
  const test::RunResult ok =
      run_cli({"param", input, "-o", dir.path("out.ply"), "--sphere", dir.path("sphere.ply"),
               "--report", dir.path("r.json"), "--quiet"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(files_in(dir), 4u);
  EXPECT_TRUE(exists(dir.path("out.ply")) && exists(dir.path("sphere.ply")) &&
              exists(dir.path("r.json")));
}

// The staging files cannot be aimed elsewhere: a link planted where an earlier release staged
// its output (OUT.meromorph-partial, pointing to the input) is left alone and the input keeps
// its bytes; outputs that exist and are not regular files (a FIFO, a socket, a folder) are
// refused with exit 2 before any work and stay what they were; one new file spelled two ways
// (relative, through `.` or `..`) is refused; written outputs get the permissions of any new
// file (the umask), and no staging folder is left behind.
// A write that fails half-way (here: a file size limit, as a full disk) is reported under the
// output's own name, not the temporary one it was being written to, and leaves nothing behind.
TEST(Outputs, AFailedWriteNamesTheOutput) {
  TempDir dir;
  const std::string command = "ulimit -f 8; trap '' XFSZ; exec '" + std::string(MEROMORPH_CLI) +
                              "' param '" + test::data_path("kitten.nv40k.off") + "' -o '" +
                              dir.path("big.ply") + "' --quiet 2>'" + dir.path("err") + "'";
  const int status = std::system(("sh -c \"" + command + "\"").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 4);
  std::ifstream err_stream(dir.path("err"));
  const std::string err((std::istreambuf_iterator<char>(err_stream)), {});
  EXPECT_NE(err.find(dir.path("big.ply") + ": could not be written"), std::string::npos) << err;
  EXPECT_EQ(err.find(".big.ply.meromorph-"), std::string::npos) << "no temporary name: " << err;
  size_t left = 0;
  for (const auto &entry : std::filesystem::directory_iterator(dir.path("")))
    left += entry.path().filename() != "err";
  EXPECT_EQ(left, 0u) << "nothing but the captured error is left";
}

TEST(Outputs, StagingCannotBeRedirected) {
  TempDir dir;
  const std::string original = file_text(test::data_path("eight.off"));
  const std::string input = dir.write("eight.off", original);
  std::filesystem::create_symlink(input, dir.path("out.ply.meromorph-partial"));
  const test::RunResult planted = run_cli({"param", input, "-o", dir.path("out.ply"), "--quiet"});
  EXPECT_EQ(planted.exit_code, 0) << planted.err;
  EXPECT_EQ(file_text(input), original) << "the input was written into";
  EXPECT_TRUE(std::filesystem::is_symlink(dir.path("out.ply.meromorph-partial")));
  EXPECT_EQ(files_in(dir), 3u); // the input, the link, out.ply
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(std::filesystem::status(dir.path("out.ply")).permissions(),
            std::filesystem::perms(0666 & ~mask));

  ASSERT_EQ(::mkfifo(dir.path("pipe.ply").c_str(), 0600), 0);
  const int listening = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string socket_path = dir.path("socket.json");
  ASSERT_LT(socket_path.size(), sizeof(address.sun_path));
  std::strcpy(address.sun_path, socket_path.c_str());
  ASSERT_EQ(::bind(listening, reinterpret_cast<sockaddr *>(&address), sizeof(address)), 0);
  std::filesystem::create_directory(dir.path("folder.ply"));
  for (const auto &[option, path, what] :
       {std::tuple<std::string, std::string, std::string>{"-o", dir.path("pipe.ply"), "FIFO"},
        {"--sphere", dir.path("pipe.ply"), "FIFO"},
        {"--report", socket_path, "socket"},
        {"-o", dir.path("folder.ply"), "folder"}}) {
    std::vector<std::string> arguments = {"param", input, "--quiet"};
    if (option != "-o") arguments.insert(arguments.end(), {"-o", dir.path("new.ply")});
    arguments.insert(arguments.end(), {option, path});
    const test::RunResult r = run_cli(arguments);
    EXPECT_EQ(r.exit_code, 2) << path << ": " << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_FALSE(exists(dir.path("new.ply")));
  }
  ::close(listening);
  EXPECT_TRUE(std::filesystem::is_fifo(dir.path("pipe.ply")));
  EXPECT_TRUE(std::filesystem::is_socket(socket_path));
  EXPECT_TRUE(std::filesystem::is_directory(dir.path("folder.ply")));
  EXPECT_EQ(files_in(dir), 6u);

  // Relative spellings of one new file, from inside the folder.
  const std::filesystem::path previous = std::filesystem::current_path();
  std::filesystem::current_path(dir.path(""));
  for (const std::vector<std::string> &clash :
       {std::vector<std::string>{"-o", "same.ply", "--sphere", "./same.ply"},
        {"-o", "same.ply", "--report", "folder.ply/../same.ply"},
        {"-o", "eight.off.ply", "--sphere",
         "../" + std::filesystem::path(dir.path("")).parent_path().filename().string() +
             "/eight.off.ply"}}) {
    std::vector<std::string> arguments = {"param", "eight.off", "--quiet"};
    arguments.insert(arguments.end(), clash.begin(), clash.end());
    const test::RunResult r = run_cli(arguments);
    EXPECT_EQ(r.exit_code, 2) << clash[3] << ": " << r.err;
    EXPECT_NE(r.err.find("two outputs"), std::string::npos) << r.err;
  }
  const test::RunResult into_input = run_cli({"param", "eight.off", "-o", "./eight.off"});
  std::filesystem::current_path(previous);
  EXPECT_EQ(into_input.exit_code, 2) << into_input.err;
  EXPECT_EQ(file_text(input), original);
  EXPECT_EQ(files_in(dir), 6u);
}

TEST(Outputs, AnInvalidMapWritesNothing) {
  TempDir dir;
  // Limbs 20 times longer than thick: their images shrink below what doubles resolve.
  const test::RunResult made = run_cli(
      {"make", "blob", "--hole", "--tentacles", "4", "--length", "5.8", "-o", dir.path("g3.ply")});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  const test::RunResult refused =
      run_cli({"param", dir.path("g3.ply"), "-o", dir.path("out.ply"), "--report",
               dir.path("r.json"), "--sphere", dir.path("s.ply"), "--quiet"});
  EXPECT_EQ(refused.exit_code, 3) << refused.err;
  EXPECT_NE(refused.err.find("nothing was written"), std::string::npos) << refused.err;
  EXPECT_EQ(files_in(dir), 1u);
}

TEST(Outputs, InfoJsonAlwaysPrintsJson) {
  TempDir dir;
  for (const auto &[name, content, code] :
       {std::tuple<const char *, const char *, int>{"cut.off", "OFF\n3 1 0\n0 0 0\n", 3},
        {"bad.ply", "ply\nformat ascii 1.0\nelement vertex\nend_header\n", 3},
        // A token that is not UTF-8, quoted in the message: replaced, still JSON.
        {"latin.off", "OFF\n3 1 0\n0 0 \xe9\xfa\n1 0 0\n0 1 0\n3 0 1 2\n", 3}}) {
    const test::RunResult r = run_cli({"info", dir.write(name, content), "--json"});
    EXPECT_EQ(r.exit_code, code);
    const nlohmann::json report = nlohmann::json::parse(r.out);
    EXPECT_FALSE(report["ok"].get<bool>());
    EXPECT_EQ(report["error"]["exit_code"], code);
    EXPECT_NE(report["error"]["message"].get<std::string>().find(name), std::string::npos);
  }
  const test::RunResult missing = run_cli({"info", dir.path("missing.off"), "--json"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(nlohmann::json::parse(missing.out)["error"]["exit_code"], 2);
}

// The map does not depend on the unit: the same branch vertices and the same angle error for
// eight.off in any unit from 1e-20 to 1e20 (the core computes at a power-of-two unit scale).
TEST(Outputs, TheMapDoesNotDependOnTheUnit) {
  TempDir dir;
  std::set<int> branch_at_one;
  double error_at_one = 0;
  for (double scale : {1.0, 1e-20, 1e-7, 3e9, 1e20}) {
    const std::string input = scaled_eight(dir, scale);
    const test::RunResult r =
        run_cli({"param", input, "-o", input + ".uv.ply", "--report", input + ".json", "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << scale << ": " << r.err;
    const nlohmann::json report = read_json(input + ".json");
    std::set<int> branch;
    for (const auto &b : report["branch_points"])
      branch.insert(b["vertex"].get<int>());
    const double error = report["distortion"]["overall"]["angle_error_mean_degrees"].get<double>();
    if (scale == 1.0) {
      branch_at_one = branch;
      error_at_one = error;
      EXPECT_EQ(branch.size(), 6u);
    }
    EXPECT_EQ(branch, branch_at_one) << "scale " << scale;
    EXPECT_NEAR(error, error_at_one, 1e-9) << "scale " << scale;
  }
}

// The remesh does not depend on the unit either, from 1e-200 to 1e200: the same vertex and face
// counts, the same Hausdorff distance over the diagonal, its positions at the input's scale.
TEST(Outputs, TheRemeshDoesNotDependOnTheUnit) {
  TempDir dir;
  nlohmann::json at_one;
  for (double scale : {1.0, 1e-200, 1e-50, 1e40, 1e200}) {
    const std::string input = scaled_eight(dir, scale);
    const test::RunResult r = run_cli({"remesh", input, "-o", input + ".remesh.off", "--vertices",
                                       "400", "--report", input + ".json", "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << scale << ": " << r.err;
    const nlohmann::json quality = read_json(input + ".json")["remesh"];
    if (scale == 1.0) at_one = quality;
    EXPECT_EQ(quality["vertices"], at_one["vertices"]) << scale;
    EXPECT_EQ(quality["faces"], at_one["faces"]) << scale;
    EXPECT_NEAR(quality["hausdorff_over_diagonal"]["to_input"].get<double>(),
                at_one["hausdorff_over_diagonal"]["to_input"].get<double>(), 1e-6)
        << scale;
    Mesh remeshed;
    test::load(input + ".remesh.off", remeshed);
    double largest = 0;
    for (const MeshVertex &v : remeshed.vert)
      largest = std::max(largest, std::abs(v.cP()[0]) / scale);
    EXPECT_GT(largest, 0.1) << scale; // eight.off spans about [-1, 1]
    EXPECT_LT(largest, 2.0) << scale;
  }
}

TEST(Outputs, ExtremeCoordinatesAndPillows) {
  TempDir dir;
  const std::string faces = "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n"
                            "3 0 3 5\n";
  auto octahedron = [&](const char *name, double scale, double stray) {
    std::ostringstream text;
    text.precision(17);
    text << "OFF\n6 8 0\n"
         << stray << " 0 0\n"
         << -scale << " 0 0\n0 " << scale << " 0\n0 " << -scale << " 0\n0 0 " << scale << "\n0 0 "
         << -scale << "\n"
         << faces;
    return dir.write(name, text.str());
  };
  for (double scale : {1e-200, 1e200, 1e300}) {
    const test::RunResult r = run_cli(
        {"param", octahedron("octahedron.off", scale, scale), "-o", dir.path("o.ply"), "--quiet"});
    EXPECT_EQ(r.exit_code, 0) << scale << ": " << r.err;
  }
  const test::RunResult stray =
      run_cli({"param", octahedron("stray.off", 1, 1e308), "-o", dir.path("s.ply")});
  EXPECT_EQ(stray.exit_code, 3);
  EXPECT_NE(stray.err.find("too small for double precision"), std::string::npos) << stray.err;
  // A pillow of two faces on the same three vertices: one is left out of the computation by
  // default (a doubled face); --strict refuses it, naming both.
  const std::string pillow_path = dir.write("pillow.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n"
                                                          "3 0 1 2\n3 0 2 1\n");
  const test::RunResult pillow = run_cli({"param", pillow_path, "-o", dir.path("p.ply")});
  EXPECT_EQ(pillow.exit_code, 0) << pillow.err;
  const test::RunResult strict_pillow =
      run_cli({"param", pillow_path, "-o", dir.path("strict_p.ply"), "--strict"});
  EXPECT_EQ(strict_pillow.exit_code, 3);
  EXPECT_NE(strict_pillow.err.find("faces 0 and 1"), std::string::npos) << strict_pillow.err;

  // A pillowcase: apexes 4 and 5 at the same point, kept apart by the surface. Mapped, with a
  // note; --repair leaves them apart.
  std::ostringstream pillowcase;
  pillowcase << "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 0\n0 0 0\n" << faces;
  const std::string input = dir.write("pillowcase.off", pillowcase.str());
  for (const char *repair : {"--quiet", "--repair"}) {
    const test::RunResult r =
        run_cli({"param", input, "-o", dir.path("c.ply"), "--report", dir.path("c.json"), repair});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json report = read_json(dir.path("c.json"));
    EXPECT_EQ(report["degree"], 1);
    ASSERT_EQ(report["notes"].size(), 1u);
    EXPECT_NE(report["notes"][0].get<std::string>().find("keeps apart"), std::string::npos);
    EXPECT_TRUE(report["repairs"].empty()) << report["repairs"];
  }
}

} // namespace
} // namespace meromorph
