#include "written_map.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "vector3.h"

namespace meromorph::test {
namespace {

using Vec = Vec3;

// Signed solid angle of the spherical triangle a, b, c (unit vectors): Van Oosterom and
// Strackee, with the triple product taken on edge differences (exact for tiny triangles).
double solid_angle(const Vec &a, const Vec &b, const Vec &c) {
  const double numerator = dot(a, cross(sub(b, a), sub(c, a)));
  const double denominator = 1 + dot(a, b) + dot(b, c) + dot(c, a);
  return 2 * std::atan2(numerator, denominator);
}

// Stereographic projection of x from -p onto the tangent plane at p, in the basis e1, e2.
std::array<double, 2> chart(const Vec &p, const Vec &e1, const Vec &e2, const Vec &x) {
  const double scale = 1 / (1 + dot(x, p));
  return {dot(x, e1) * scale, dot(x, e2) * scale};
}

template <class T> T read_value(const std::string &bytes, size_t &at) {
  if (at + sizeof(T) > bytes.size()) throw std::runtime_error("sphere file ends early");
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

} // namespace

WrittenMap read_written_map(const std::string &path, int euler, double component_spacing) {
  std::ifstream stream(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(stream)), {});
  const size_t header_end = bytes.find("end_header\n");
  if (bytes.compare(0, 4, "ply\n") != 0 || header_end == std::string::npos)
    throw std::runtime_error(path + ": not a PLY file");
  std::istringstream header(bytes.substr(0, header_end));
  std::vector<std::string> vertex_properties;
  std::string line, element;
  WrittenMap out;
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      std::string format;
      words >> format;
      if (format != "binary_little_endian") throw std::runtime_error("expected binary PLY");
    } else if (keyword == "element") {
      int count = 0;
      words >> element >> count;
      (element == "vertex" ? out.vertices : out.faces) = count;
    } else if (keyword == "property" && element == "vertex") {
      std::string type, name;
      words >> type >> name;
      vertex_properties.push_back(type + " " + name);
    }
  }
  size_t at = header_end + std::strlen("end_header\n");
  for (int v = 0; v < out.vertices; ++v) {
    Vec p{};
    int layer = 0, branch = 0, source = v, component = 0;
    for (const std::string &property : vertex_properties) {
      if (property == "double x")
        p[0] = read_value<double>(bytes, at);
      else if (property == "double y")
        p[1] = read_value<double>(bytes, at);
      else if (property == "double z")
        p[2] = read_value<double>(bytes, at);
      else if (property == "int layer")
        layer = read_value<int32_t>(bytes, at);
      else if (property == "uchar branch")
        branch = read_value<uint8_t>(bytes, at);
      else if (property == "int source_vertex")
        source = read_value<int32_t>(bytes, at);
      else if (property == "int component")
        component = read_value<int32_t>(bytes, at);
      else
        throw std::runtime_error("unexpected vertex property " + property);
    }
    p[0] -= component * component_spacing; // part k's sphere is centred at x = k * spacing
    out.source_vertex.push_back(source);
    out.component.push_back(component);
    const double r = std::sqrt(dot(p, p));
    out.sphere.push_back({p[0] / r, p[1] / r, p[2] / r});
    out.layer.push_back(layer);
    out.branch_property.push_back(branch);
  }
  for (int f = 0; f < out.faces; ++f) {
    if (read_value<uint8_t>(bytes, at) != 3) throw std::runtime_error("expected triangles");
    std::array<int, 3> t;
    for (int &index : t)
      index = read_value<int32_t>(bytes, at);
    out.triangles.push_back(t);
  }

  // Vertices on a hole of the written surface (its one-ring is not closed): no winding.
  std::map<std::pair<int, int>, int> walked;
  for (const auto &t : out.triangles)
    for (int k = 0; k < 3; ++k)
      ++walked[{t[size_t(k)], t[size_t((k + 1) % 3)]}];
  out.on_boundary.assign(size_t(out.vertices), 0);
  for (const auto &[edge, count] : walked)
    if (!walked.count({edge.second, edge.first}))
      out.on_boundary[size_t(edge.first)] = out.on_boundary[size_t(edge.second)] = 1;

  // Folds, degree and layer coverage from the faces' images.
  std::vector<double> winding(size_t(out.vertices), 0.0);
  double total = 0;
  std::map<int, double> by_layer, mixed_by_layer;
  for (int f = 0; f < out.faces; ++f) {
    const auto &t = out.triangles[size_t(f)];
    const Vec &a = out.sphere[size_t(t[0])], &b = out.sphere[size_t(t[1])],
              &c = out.sphere[size_t(t[2])];
    if (!(dot(a, cross(sub(b, a), sub(c, a))) > 0)) out.folded_faces.push_back(f);
    const double angle = solid_angle(a, b, c);
    total += angle;
    out.component_area_over_4pi[out.component[size_t(t[0])]] += angle / (4 * M_PI);
    for (int k = 0; k < 3; ++k)
      by_layer[out.layer[size_t(t[size_t(k)])]] += angle / 3;
    const int l0 = out.layer[size_t(t[0])], l1 = out.layer[size_t(t[1])],
              l2 = out.layer[size_t(t[2])];
    if (l0 != l1 || l1 != l2)
      for (int l : {l0, l1, l2})
        mixed_by_layer[l] += std::abs(angle) / 3; // thirds: a face counts once per corner
    // Winding: each face (v, a, b) adds the angle from a's image to b's around v's image.
    for (int k = 0; k < 3; ++k) {
      const Vec &p = out.sphere[size_t(t[size_t(k)])];
      const Vec &x = out.sphere[size_t(t[size_t((k + 1) % 3)])];
      const Vec &y = out.sphere[size_t(t[size_t((k + 2) % 3)])];
      Vec helper = std::abs(p[0]) < 0.9 ? Vec{1, 0, 0} : Vec{0, 1, 0};
      Vec e1 = cross(p, helper);
      const double n = std::sqrt(dot(e1, e1));
      e1 = {e1[0] / n, e1[1] / n, e1[2] / n};
      const Vec e2 = cross(p, e1);
      const auto qx = chart(p, e1, e2, x), qy = chart(p, e1, e2, y);
      winding[size_t(t[size_t(k)])] +=
          std::atan2(qx[0] * qy[1] - qx[1] * qy[0], qx[0] * qy[0] + qx[1] * qy[1]);
    }
  }
  for (int v = 0; v < out.vertices; ++v) {
    const int e =
        out.on_boundary[size_t(v)] ? 1 : int(std::lround(winding[size_t(v)] / (2 * M_PI)));
    out.local_degree.push_back(e);
    if (e >= 2) out.branch_vertices.push_back(v);
    out.ramification += e - 1;
    out.component_ramification[out.component[size_t(v)]] += e - 1;
  }
  out.area_over_4pi = total / (4 * M_PI);
  out.degree = int(std::lround(out.area_over_4pi));
  out.riemann_hurwitz =
      euler == 2 * out.degree - out.ramification && std::abs(out.area_over_4pi - out.degree) < 0.01;
  for (const auto &[layer, area] : by_layer) {
    out.layer_coverage.push_back(area / (4 * M_PI));
    out.layer_cut_area.push_back(3 * mixed_by_layer[layer] / (4 * M_PI));
  }
  return out;
}

// Every per-vertex property of a binary little-endian PLY surface, by name, as doubles.
WrittenMesh read_written_mesh(const std::string &surface_ply, bool with_faces) {
  std::ifstream stream(surface_ply, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(stream)), {});
  const size_t header_end = bytes.find("end_header\n");
  if (bytes.compare(0, 4, "ply\n") != 0 || header_end == std::string::npos)
    throw std::runtime_error(surface_ply + ": not a PLY file");
  std::istringstream header(bytes.substr(0, header_end));
  std::vector<std::pair<std::string, std::string>> vertex_properties; // type, name
  std::string line, element;
  int vertices = 0, faces = 0;
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "element") {
      int count = 0;
      words >> element >> count;
      if (element == "vertex") vertices = count;
      if (element == "face") faces = count;
    } else if (keyword == "property" && element == "vertex") {
      std::string type, name;
      words >> type >> name;
      vertex_properties.push_back({type, name});
    }
  }
  size_t at = header_end + std::strlen("end_header\n");
  WrittenMesh out;
  for (int v = 0; v < vertices; ++v)
    for (const auto &[type, name] : vertex_properties) {
      if (type == "double")
        out.columns[name].push_back(read_value<double>(bytes, at));
      else if (type == "float")
        out.columns[name].push_back(read_value<float>(bytes, at));
      else if (type == "int")
        out.columns[name].push_back(read_value<int32_t>(bytes, at));
      else if (type == "uchar")
        out.columns[name].push_back(read_value<uint8_t>(bytes, at));
      else
        throw std::runtime_error("unexpected vertex property " + type + " " + name);
    }
  for (int f = 0; with_faces && f < faces && at < bytes.size(); ++f) {
    const int corners = read_value<uint8_t>(bytes, at);
    if (corners != 3) throw std::runtime_error(surface_ply + ": a face that is no triangle");
    std::array<int, 3> triangle{};
    for (int &corner : triangle)
      corner = read_value<int32_t>(bytes, at);
    out.triangles.push_back(triangle);
  }
  return out;
}

std::map<std::string, std::vector<double>> read_vertex_columns(const std::string &surface_ply) {
  return read_written_mesh(surface_ply, false).columns;
}

double written_angle_error_degrees(const WrittenMap &map, const std::string &surface_ply) {
  const std::map<std::string, std::vector<double>> columns = read_vertex_columns(surface_ply);
  if (columns.at("x").size() != size_t(map.vertices))
    throw std::runtime_error(surface_ply + ": other vertex count");
  std::vector<Vec> position(static_cast<size_t>(map.vertices));
  for (size_t v = 0; v < position.size(); ++v)
    position[v] = {columns.at("x")[v], columns.at("y")[v], columns.at("z")[v]};
  auto corner = [](const Vec &at, const Vec &b, const Vec &c) {
    const Vec u = sub(b, at), v = sub(c, at);
    const Vec n = cross(u, v);
    return std::atan2(std::sqrt(dot(n, n)), dot(u, v));
  };
  double sum = 0;
  for (const auto &t : map.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[size_t(k)], b = t[size_t((k + 1) % 3)], c = t[size_t((k + 2) % 3)];
      sum += std::abs(corner(position[size_t(a)], position[size_t(b)], position[size_t(c)]) -
                      corner(map.sphere[size_t(a)], map.sphere[size_t(b)], map.sphere[size_t(c)]));
    }
  return sum / (3.0 * double(map.triangles.size())) * 180 / M_PI;
}

} // namespace meromorph::test
