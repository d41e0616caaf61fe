#include <algorithm>
#include <string>

#include "io/format_readers.h"
#include "io/polygon_triangulation.h"
#include "io/text_lines.h"

namespace meromorph {

MeshArrays read_off(const std::string &path, const std::string &text,
                    std::vector<std::string> &notes) {
  TextLines lines(path, text);
  if (!lines.next()) lines.fail_at_end("the file is empty");

  // Header keyword, possibly followed by the counts on the same line ("OFF 8 6 0").
  size_t first_count = 1;
  std::string_view keyword = lines.tokens()[0];
  if (keyword.find("OFF") == std::string_view::npos) lines.fail("expected the OFF keyword");
  if (keyword.find("4") != std::string_view::npos || keyword.find("nOFF") != std::string_view::npos)
    lines.fail("only three-dimensional OFF files are supported ('" + std::string(keyword) + "')");
  if (lines.tokens().size() == 1) {
    if (!lines.next()) lines.fail_at_end("the file ends before the vertex and face counts");
    first_count = 0;
  }
  if (lines.tokens().size() < first_count + 2)
    lines.fail("expected the vertex and face counts ('vertices faces edges')");
  const long vertex_count = lines.integer(first_count);
  const long face_count = lines.integer(first_count + 1);
  if (vertex_count < 0 || face_count < 0)
    lines.fail("the vertex and face counts must not be negative");
  // Each vertex takes at least 6 bytes ("0 0 0\n") and each face at least 8 ("3 0 1 2\n").
  if (double(vertex_count) * 6 + double(face_count) * 8 > double(text.size()))
    lines.fail("the header announces " + std::to_string(vertex_count) + " vertices and " +
               std::to_string(face_count) + " faces, more than a file of " +
               std::to_string(text.size()) + " bytes can hold (truncated, or a wrong header)");

  MeshArrays arrays;
  arrays.positions.reserve(size_t(vertex_count));
  for (long v = 0; v < vertex_count; ++v) {
    if (!lines.next())
      lines.fail_at_end("the file ends after " + std::to_string(v) + " of the " +
                        std::to_string(vertex_count) +
                        " vertices its header announces (truncated?)");
    if (lines.tokens().size() < 3 && lines.cut_short())
      lines.fail("the file ends in the middle of vertex " + std::to_string(v) + " of the " +
                 std::to_string(vertex_count) + " vertices its header announces (truncated?)");
    if (lines.tokens().size() < 3)
      lines.fail("vertex " + std::to_string(v) + " needs three coordinates");
    arrays.positions.emplace_back(lines.number(0), lines.number(1), lines.number(2));
  }

  arrays.triangles.reserve(size_t(face_count));
  std::vector<int> polygon;
  PolygonTriangulation triangulation(arrays.positions, arrays.triangles);
  for (long f = 0; f < face_count; ++f) {
    if (!lines.next())
      lines.fail_at_end("the file ends after " + std::to_string(f) + " of the " +
                        std::to_string(face_count) + " faces its header announces (truncated?)");
    const long corners = lines.integer(0);
    if (lines.tokens().size() < size_t(std::max(corners, 0L)) + 1 && lines.cut_short())
      lines.fail("the file ends in the middle of face " + std::to_string(f) + " of the " +
                 std::to_string(face_count) + " faces its header announces (truncated?)");
    if (corners < 3)
      lines.fail("face " + std::to_string(f) + " has " + std::to_string(corners) +
                 " vertices; a face needs at least 3");
    if (lines.tokens().size() < size_t(corners) + 1)
      lines.fail("face " + std::to_string(f) + " announces " + std::to_string(corners) +
                 " vertices but lists " + std::to_string(lines.tokens().size() - 1));
    polygon.clear();
    for (long c = 0; c < corners; ++c) {
      const long index = lines.integer(size_t(c) + 1);
      if (index < 0 || index >= vertex_count)
        lines.fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(index) +
                   ", but the file has vertices 0.." + std::to_string(vertex_count - 1));
      polygon.push_back(int(index));
    }
    triangulation.add(polygon);
  }
  triangulation.finish(arrays.triangle_face, notes);
  return arrays;
}

} // namespace meromorph
