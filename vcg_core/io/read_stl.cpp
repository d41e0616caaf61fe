#include <cstdint>
#include <cstring>
#include <map>
#include <string>

#include "io/format_readers.h"
#include "io/text_lines.h"

namespace meromorph {
namespace {

// Corners at exactly the same position become one vertex, numbered in order of first appearance.
MeshArrays weld_corners(const std::vector<Point3> &corners, std::vector<std::string> &notes) {
  MeshArrays arrays;
  std::map<std::array<double, 3>, int> vertex_at;
  std::vector<int> corner_vertex(corners.size());
  for (size_t c = 0; c < corners.size(); ++c) {
    const std::array<double, 3> key{corners[c][0], corners[c][1], corners[c][2]};
    auto [it, inserted] = vertex_at.emplace(key, int(arrays.positions.size()));
    if (inserted) arrays.positions.push_back(corners[c]);
    corner_vertex[c] = it->second;
  }
  for (size_t t = 0; t + 2 < corners.size(); t += 3)
    arrays.triangles.push_back({corner_vertex[t], corner_vertex[t + 1], corner_vertex[t + 2]});
  if (corners.empty()) return arrays;
  notes.push_back("STL stores no shared vertices: welded " + std::to_string(corners.size()) +
                  " triangle corners at identical positions into " +
                  std::to_string(arrays.positions.size()) + " vertices");
  return arrays;
}

std::vector<Point3> binary_corners(const std::string &bytes) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  std::vector<Point3> corners;
  corners.reserve(size_t(count) * 3);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char *record = bytes.data() + 84 + size_t(t) * 50;
    for (int c = 0; c < 3; ++c) {
      float xyz[3];
      std::memcpy(xyz, record + 12 + 12 * c, 12);
      corners.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
  }
  return corners;
}

std::vector<Point3> ascii_corners(const std::string &path, const std::string &text) {
  TextLines lines(path, text);
  std::vector<Point3> corners;
  int in_facet = -1; // corners seen in the current facet, -1 outside a facet
  while (lines.next()) {
    const auto &tokens = lines.tokens();
    if (tokens[0] == "facet") {
      if (in_facet >= 0) lines.fail("'facet' inside a facet: a previous 'endfacet' is missing");
      in_facet = 0;
    } else if (tokens[0] == "vertex") {
      if (in_facet < 0) lines.fail("'vertex' outside a facet");
      if (tokens.size() < 4) lines.fail("a vertex needs three coordinates");
      corners.emplace_back(lines.number(1), lines.number(2), lines.number(3));
      ++in_facet;
    } else if (tokens[0] == "endfacet") {
      if (in_facet != 3)
        lines.fail("a facet must have exactly 3 vertices, this one has " +
                   std::to_string(std::max(in_facet, 0)));
      in_facet = -1;
    }
  }
  if (in_facet >= 0) lines.fail_at_end("the file ends inside a facet (truncated?)");
  return corners;
}

} // namespace

MeshArrays read_stl(const std::string &path, const std::string &bytes,
                    std::vector<std::string> &notes) {
  bool binary = false;
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    binary = std::uint64_t(84) + std::uint64_t(50) * count == bytes.size();
  }
  const std::vector<Point3> corners = binary ? binary_corners(bytes) : ascii_corners(path, bytes);
  return weld_corners(corners, notes);
}

} // namespace meromorph
