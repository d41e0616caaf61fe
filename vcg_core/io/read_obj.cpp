#include <string>

#include "io/format_readers.h"
#include "io/polygon_triangulation.h"
#include "io/text_lines.h"

namespace meromorph {

MeshArrays read_obj(const std::string &path, const std::string &text,
                    std::vector<std::string> &notes) {
  TextLines lines(path, text);
  MeshArrays arrays;
  // Faces are kept as polygons until every vertex is known (a face may precede later `v` lines
  // only with negative indices, which are relative to the vertices read so far).
  std::vector<int> polygon;
  PolygonTriangulation triangulation(arrays.positions, arrays.triangles);
  size_t ignored_lines = 0;
  while (lines.next()) {
    const auto &tokens = lines.tokens();
    if (tokens[0] == "v") {
      if (tokens.size() < 4) lines.fail("a vertex ('v') needs three coordinates");
      arrays.positions.emplace_back(lines.number(1), lines.number(2), lines.number(3));
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4)
        lines.fail("a face ('f') needs at least 3 vertices, this one has " +
                   std::to_string(tokens.size() - 1));
      polygon.clear();
      const long known = long(arrays.positions.size());
      for (size_t c = 1; c < tokens.size(); ++c) {
        std::string_view corner = tokens[c];
        corner = corner.substr(0, corner.find('/'));
        long index = lines.integer(corner);
        if (index < 0)
          index = known + index; // relative: -1 is the last vertex read
        else if (index > 0)
          index -= 1; // OBJ counts from 1
        else
          lines.fail("vertex index 0 in a face; OBJ counts vertices from 1");
        if (index < 0 || index >= known)
          lines.fail("face refers to vertex " +
                     std::string(tokens[c].substr(0, tokens[c].find('/'))) + ", but only " +
                     std::to_string(known) + " vertices are defined before it");
        polygon.push_back(int(index));
      }
      triangulation.add(polygon);
    } else if (tokens[0] == "l" || tokens[0] == "p") {
      ++ignored_lines;
    }
  }
  triangulation.finish(arrays.triangle_face, notes);
  if (ignored_lines)
    notes.push_back("ignored " + std::to_string(ignored_lines) + " line and point elements");
  return arrays;
}

} // namespace meromorph
