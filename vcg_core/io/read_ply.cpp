// A strict PLY reader of our own (vcglib's importer crashes on lying counts, out-of-range
// indices and long lists): the header is parsed completely, every count and index is checked
// against the file before anything is allocated, and every value is read with a bounds check.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "common/errors.h"
#include "io/format_readers.h"
#include "io/polygon_triangulation.h"

namespace meromorph {
namespace {

enum class Encoding { ascii, binary_little_endian, binary_big_endian };
enum class ScalarType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

struct Property {
  std::string name;
  bool list = false;
  ScalarType count_type = ScalarType::uint8; // lists only
  ScalarType type = ScalarType::float32;     // the value (or the list's items)
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
  size_t header_line = 0;
};

struct Header {
  Encoding encoding = Encoding::ascii;
  std::vector<Element> elements;
  size_t data_start = 0; // byte offset of the first byte after "end_header\n"
  size_t lines = 0;      // header lines, so ASCII data lines can be numbered as in the file
};

int size_of(ScalarType type) {
  switch (type) {
  case ScalarType::int8:
  case ScalarType::uint8:
    return 1;
  case ScalarType::int16:
  case ScalarType::uint16:
    return 2;
  case ScalarType::int32:
  case ScalarType::uint32:
  case ScalarType::float32:
    return 4;
  case ScalarType::float64:
    return 8;
  }
  return 0;
}

bool is_integer(ScalarType type) {
  return type != ScalarType::float32 && type != ScalarType::float64;
}

bool parse_type(std::string_view name, ScalarType &type) {
  static const std::pair<const char *, ScalarType> names[] = {
      {"char", ScalarType::int8},      {"int8", ScalarType::int8},
      {"uchar", ScalarType::uint8},    {"uint8", ScalarType::uint8},
      {"short", ScalarType::int16},    {"int16", ScalarType::int16},
      {"ushort", ScalarType::uint16},  {"uint16", ScalarType::uint16},
      {"int", ScalarType::int32},      {"int32", ScalarType::int32},
      {"uint", ScalarType::uint32},    {"uint32", ScalarType::uint32},
      {"float", ScalarType::float32},  {"float32", ScalarType::float32},
      {"double", ScalarType::float64}, {"float64", ScalarType::float64}};
  for (const auto &[text, value] : names)
    if (name == text) {
      type = value;
      return true;
    }
  return false;
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
      ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r')
      ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

// A non-negative decimal count, strictly (no sign, no spaces, no overflow).
bool parse_count(std::string_view text, uint64_t &value) {
  if (text.empty() || text.front() < '0' || text.front() > '9') return false;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

// Reads the header line by line; each keyword's line fills its part of `header`.
class HeaderParser {
public:
  HeaderParser(const std::string &path, const std::string &bytes)
      : path_(path), bytes_(bytes), position_(bytes.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0) {}

  Header parse() {
    std::string_view line;
    if (!next_line(line) || line != "ply")
      throw InputError(path_ + ": not a PLY file (its first line is not 'ply')");
    for (bool ended = false; !ended;) {
      if (!next_line(line))
        throw InputError(path_ + ": the file ends inside its PLY header (no 'end_header' line)");
      const std::vector<std::string_view> words = split_words(line);
      if (words.empty()) continue;
      const std::string_view keyword = words[0];
      if (keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "end_header")
        ended = true;
      else if (keyword == "format")
        format(words);
      else if (keyword == "element")
        element(words);
      else if (keyword == "property")
        property(words);
      else
        fail("unknown PLY header line '" + std::string(line.substr(0, 60)) + "'");
    }
    if (!format_seen_) throw InputError(path_ + ": the PLY header has no 'format' line");
    header_.data_start = std::min(position_, bytes_.size());
    header_.lines = line_number_;
    return header_;
  }

private:
  [[noreturn]] void fail(const std::string &message) const {
    throw InputError(path_ + ":" + std::to_string(line_number_) + ": " + message);
  }

  bool next_line(std::string_view &line) {
    if (position_ >= bytes_.size()) return false;
    size_t end = bytes_.find('\n', position_);
    if (end == std::string::npos) end = bytes_.size();
    line = std::string_view(bytes_.data() + position_, end - position_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    position_ = end + 1;
    ++line_number_;
    return true;
  }

  void format(const std::vector<std::string_view> &words) {
    if (format_seen_) fail("a second 'format' line");
    format_seen_ = true;
    if (words.size() != 3 || words[2] != "1.0")
      fail("expected 'format ascii 1.0' (or binary_little_endian / binary_big_endian)");
    if (words[1] == "ascii")
      header_.encoding = Encoding::ascii;
    else if (words[1] == "binary_little_endian")
      header_.encoding = Encoding::binary_little_endian;
    else if (words[1] == "binary_big_endian")
      header_.encoding = Encoding::binary_big_endian;
    else
      fail("unknown PLY format '" + std::string(words[1]) + "'");
  }

  void element(const std::vector<std::string_view> &words) {
    if (!format_seen_) fail("'element' before the 'format' line");
    Element element;
    if (words.size() != 3) fail("expected 'element NAME COUNT'");
    element.name = std::string(words[1]);
    if (!parse_count(words[2], element.count) || element.count > uint64_t(INT32_MAX))
      fail("element '" + element.name + "' has the count '" + std::string(words[2]) +
           "', which is not a whole number from 0 to " + std::to_string(INT32_MAX));
    for (const Element &other : header_.elements)
      if (other.name == element.name) fail("element '" + element.name + "' is declared twice");
    element.header_line = line_number_;
    header_.elements.push_back(element);
  }

  void property(const std::vector<std::string_view> &words) {
    if (header_.elements.empty()) fail("'property' before any 'element'");
    Property property;
    if (words.size() == 5 && words[1] == "list") {
      property.list = true;
      if (!parse_type(words[2], property.count_type) || !is_integer(property.count_type))
        fail("a list's count type must be an integer type, not '" + std::string(words[2]) + "'");
      if (!parse_type(words[3], property.type))
        fail("unknown property type '" + std::string(words[3]) + "'");
      property.name = std::string(words[4]);
    } else if (words.size() == 3) {
      if (!parse_type(words[1], property.type))
        fail("unknown property type '" + std::string(words[1]) + "'");
      property.name = std::string(words[2]);
    } else {
      fail("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
    }
    for (const Property &other : header_.elements.back().properties)
      if (other.name == property.name) fail("property '" + property.name + "' is declared twice");
    header_.elements.back().properties.push_back(property);
  }

  const std::string &path_;
  const std::string &bytes_;
  size_t position_, line_number_ = 0;
  bool format_seen_ = false;
  Header header_;
};

// Reads the values of the data section one at a time, ASCII or binary, and names where a
// problem is: the file line (ASCII) or the byte offset (binary).
class ValueReader {
public:
  ValueReader(const std::string &path, const std::string &bytes, const Header &header)
      : path_(path), bytes_(bytes), encoding_(header.encoding), position_(header.data_start),
        line_(header.lines + 1) {}

  // The next value as a double; an integer type must hold a whole number in its range.
  double value(ScalarType type, const std::string &what) {
    return encoding_ == Encoding::ascii ? ascii_value(type, what) : binary_value(type, what);
  }

  // The next value as a list count: a whole number from 0 to `maximum`.
  uint64_t count(ScalarType type, uint64_t maximum, const std::string &what) {
    const double number = value(type, what);
    if (number < 0 || number > double(maximum))
      fail(what + " has the list count " + format(number) + " (allowed: 0 to " +
           std::to_string(maximum) + ")");
    return uint64_t(number);
  }

  [[noreturn]] void fail(const std::string &message) const {
    if (encoding_ == Encoding::ascii)
      throw InputError(path_ + ":" + std::to_string(line_) + ": " + message);
    throw InputError(path_ + ": at byte " + std::to_string(position_) + ": " + message);
  }

  size_t remaining() const { return bytes_.size() - std::min(position_, bytes_.size()); }

private:
  static std::string format(double number) {
    std::string text = std::to_string(number);
    if (number == std::floor(number) && std::abs(number) < 1e15)
      text = std::to_string(int64_t(number));
    return text;
  }

  double ascii_value(ScalarType type, const std::string &what) {
    while (position_ < bytes_.size() && std::strchr(" \t\r\n\f\v", bytes_[position_])) {
      if (bytes_[position_] == '\n') ++line_;
      ++position_;
    }
    if (position_ >= bytes_.size())
      fail("the file ends inside " + what + " (truncated, or the header's counts are wrong)");
    const size_t start = position_;
    while (position_ < bytes_.size() && !std::strchr(" \t\r\n\f\v", bytes_[position_]))
      ++position_;
    std::string_view text(bytes_.data() + start, position_ - start);
    std::string_view digits = text;
    if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+')
      digits.remove_prefix(1);
    double number = 0;
    if (is_integer(type)) {
      int64_t whole = 0;
      auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), whole);
      if (error != std::errc() || end != digits.data() + digits.size())
        fail("'" + std::string(text.substr(0, 40)) + "' in " + what + " is not a whole number");
      number = double(whole);
      check_range(type, number, what);
    } else {
      auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), number,
                                          std::chars_format::general);
      if (error == std::errc::result_out_of_range)
        fail("'" + std::string(text.substr(0, 40)) + "' in " + what +
             " is beyond what double precision holds");
      if (error != std::errc() || end != digits.data() + digits.size())
        fail("'" + std::string(text.substr(0, 40)) + "' in " + what + " is not a number");
    }
    return number;
  }

  void check_range(ScalarType type, double number, const std::string &what) const {
    double low = 0, high = 0;
    switch (type) {
    case ScalarType::int8:
      low = -128, high = 127;
      break;
    case ScalarType::uint8:
      high = 255;
      break;
    case ScalarType::int16:
      low = -32768, high = 32767;
      break;
    case ScalarType::uint16:
      high = 65535;
      break;
    case ScalarType::int32:
      low = -2147483648.0, high = 2147483647.0;
      break;
    case ScalarType::uint32:
      high = 4294967295.0;
      break;
    default:
      return;
    }
    if (number < low || number > high)
      fail(format(number) + " in " + what + " does not fit its declared type");
  }

  double binary_value(ScalarType type, const std::string &what) {
    const int size = size_of(type);
    if (remaining() < size_t(size))
      fail("the file ends inside " + what + " (truncated, or the header's counts are wrong)");
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + position_, size_t(size));
    if (encoding_ == Encoding::binary_big_endian)
      for (int i = 0; i < size / 2; ++i)
        std::swap(raw[i], raw[size - 1 - i]);
    position_ += size_t(size);
    switch (type) {
    case ScalarType::int8:
      return double(int8_t(raw[0]));
    case ScalarType::uint8:
      return double(raw[0]);
    case ScalarType::int16: {
      int16_t v;
      std::memcpy(&v, raw, 2);
      return v;
    }
    case ScalarType::uint16: {
      uint16_t v;
      std::memcpy(&v, raw, 2);
      return v;
    }
    case ScalarType::int32: {
      int32_t v;
      std::memcpy(&v, raw, 4);
      return v;
    }
    case ScalarType::uint32: {
      uint32_t v;
      std::memcpy(&v, raw, 4);
      return v;
    }
    case ScalarType::float32: {
      float v;
      std::memcpy(&v, raw, 4);
      return v;
    }
    case ScalarType::float64: {
      double v;
      std::memcpy(&v, raw, 8);
      return v;
    }
    }
    return 0;
  }

  const std::string &path_;
  const std::string &bytes_;
  Encoding encoding_;
  size_t position_;
  size_t line_;
};

// The fewest bytes one instance of `element` can take: a lower bound that lets lying counts be
// refused before anything is allocated (ASCII: a digit and a separator per value).
double smallest_size(const Element &element, Encoding encoding) {
  double bytes = 0;
  for (const Property &property : element.properties)
    bytes += encoding == Encoding::ascii
                 ? 2.0
                 : double(size_of(property.list ? property.count_type : property.type));
  return bytes;
}

const Property *find_property(const Element &element, std::initializer_list<const char *> names) {
  for (const Property &property : element.properties)
    for (const char *name : names)
      if (property.name == name) return &property;
  return nullptr;
}

// The elements and properties a mesh is read from.
struct MeshLayout {
  const Element *vertices = nullptr, *faces = nullptr, *strips = nullptr;
  const Property *coordinates[3] = {nullptr, nullptr, nullptr};
  const Property *corner_list = nullptr; // faces only
  const Property *strip_list = nullptr;  // triangle strips: vertices, -1 between strips
};

MeshLayout mesh_layout(const std::string &path, const std::string &bytes, const Header &header,
                       std::vector<std::string> &notes) {
  MeshLayout layout;
  double smallest = 0;
  for (const Element &element : header.elements) {
    if (element.name == "vertex") layout.vertices = &element;
    if (element.name == "face") layout.faces = &element;
    if (element.name == "tristrips") layout.strips = &element;
    smallest += smallest_size(element, header.encoding) * double(element.count);
  }
  if (smallest > double(bytes.size() - header.data_start))
    throw InputError(path + ": the PLY header announces more vertices and faces than a file of " +
                     std::to_string(bytes.size()) +
                     " bytes can hold (truncated, or a wrong header)");
  if (!layout.vertices) throw InputError(path + ": the PLY file has no 'vertex' element");
  for (int k = 0; k < 3; ++k) {
    const char *name[] = {"x", "y", "z"};
    layout.coordinates[k] = find_property(*layout.vertices, {name[k]});
    if (!layout.coordinates[k] || layout.coordinates[k]->list)
      throw InputError(path + ":" + std::to_string(layout.vertices->header_line) +
                       ": the vertex element has no scalar property '" + name[k] + "'");
  }
  if (layout.faces) {
    layout.corner_list = find_property(*layout.faces, {"vertex_indices", "vertex_index"});
    if (!layout.corner_list || !layout.corner_list->list || !is_integer(layout.corner_list->type))
      throw InputError(path + ":" + std::to_string(layout.faces->header_line) +
                       ": the face element has no integer list 'vertex_indices'");
  }
  if (layout.strips) {
    layout.strip_list = find_property(*layout.strips, {"vertex_indices", "vertex_index"});
    if (!layout.strip_list || !layout.strip_list->list || !is_integer(layout.strip_list->type))
      throw InputError(path + ":" + std::to_string(layout.strips->header_line) +
                       ": the tristrips element has no integer list 'vertex_indices'");
  }
  if (!layout.faces && !layout.strips)
    notes.push_back("the PLY file has no face element (a point cloud?)");
  return layout;
}

// One instance of `element`: a vertex's position, a face's corners, or values passed over.
// `scalars`: when not null, a vertex's scalar values in the order of its properties.
void read_instance(ValueReader &reader, const MeshLayout &layout, const Element &element,
                   const std::string &what, Point3 &position, std::vector<int> &polygon,
                   std::vector<double> *scalars) {
  const uint64_t vertex_count = layout.vertices->count;
  for (const Property &property : element.properties) {
    if (!property.list) {
      const double number = reader.value(property.type, what);
      if (&element == layout.vertices) {
        for (int k = 0; k < 3; ++k)
          if (&property == layout.coordinates[k]) position[k] = number;
        if (scalars) scalars->push_back(number);
      }
      continue;
    }
    // A list can hold no more values than bytes are left in the file.
    const bool strip = &property == layout.strip_list;
    const bool corners = &property == layout.corner_list || strip;
    const uint64_t length = reader.count(
        property.count_type,
        &property == layout.corner_list ? vertex_count : uint64_t(reader.remaining()), what);
    if (&property == layout.corner_list && length < 3)
      reader.fail(what + " has " + std::to_string(length) + (length == 1 ? " corner" : " corners") +
                  "; a face needs at least 3");
    for (uint64_t k = 0; k < length; ++k) {
      const double number = reader.value(property.type, what);
      if (!corners) continue;
      if (strip && number == -1) { // the end of a strip
        polygon.push_back(-1);
        continue;
      }
      if (number < 0 || number >= double(vertex_count))
        reader.fail(what + " refers to vertex " + std::to_string(int64_t(number)) +
                    ", but the file has vertices 0.." + std::to_string(vertex_count - 1));
      polygon.push_back(int(number));
    }
  }
}

// The triangles of triangle strips (vertices, -1 between strips): the k-th triangle of a strip
// is (v[k], v[k+1], v[k+2]), its first two corners swapped when k is odd so that all face the
// same way; triangles that use a vertex twice (the stitches between strips) are left out.
void strips_to_triangles(const std::vector<int> &strips, std::vector<std::array<int, 3>> &out) {
  size_t start = 0;
  for (size_t i = 0; i <= strips.size(); ++i) {
    if (i < strips.size() && strips[i] >= 0) continue;
    for (size_t k = start; k + 2 < i; ++k) {
      std::array<int, 3> triangle{strips[k], strips[k + 1], strips[k + 2]};
      if ((k - start) % 2 == 1) std::swap(triangle[0], triangle[1]);
      if (triangle[0] != triangle[1] && triangle[1] != triangle[2] && triangle[0] != triangle[2])
        out.push_back(triangle);
    }
    start = i + 1;
  }
}

} // namespace

MeshArrays read_ply(const std::string &path, const std::string &bytes,
                    std::vector<std::string> &notes, bool vertex_values) {
  if (bytes.empty()) throw InputError(path + ": the file is empty");
  const Header header = HeaderParser(path, bytes).parse();
  const MeshLayout layout = mesh_layout(path, bytes, header, notes);

  MeshArrays arrays;
  arrays.positions.reserve(size_t(layout.vertices->count));
  ValueReader reader(path, bytes, header);
  // Faces are triangulated once all positions are known (an element order of faces first is
  // legal PLY).
  std::vector<std::vector<int>> polygon_list;
  if (layout.faces) {
    arrays.triangles.reserve(size_t(layout.faces->count));
    polygon_list.reserve(size_t(layout.faces->count));
  }
  std::vector<int> polygon;
  std::vector<std::array<int, 3>> strip_triangles;
  // The vertex element's scalar properties other than the coordinates, by their place in it.
  std::vector<std::pair<size_t, size_t>> kept; // (place among the scalars, values index)
  if (vertex_values) {
    size_t place = 0;
    for (const Property &property : layout.vertices->properties) {
      if (property.list) continue;
      if (&property != layout.coordinates[0] && &property != layout.coordinates[1] &&
          &property != layout.coordinates[2]) {
        kept.emplace_back(place, arrays.vertex_values.size());
        arrays.vertex_values.push_back(
            {property.name, is_integer(property.type), size_of(property.type) == 1, {}});
        arrays.vertex_values.back().values.reserve(size_t(layout.vertices->count));
      }
      ++place;
    }
  }
  std::vector<double> scalars;
  for (const Element &element : header.elements) {
    if (element.properties.empty()) continue; // its instances take no bytes: nothing to read
    for (uint64_t i = 0; i < element.count; ++i) {
      Point3 position(0, 0, 0);
      polygon.clear();
      scalars.clear();
      read_instance(reader, layout, element, element.name + " " + std::to_string(i), position,
                    polygon, kept.empty() ? nullptr : &scalars);
      if (&element == layout.vertices) arrays.positions.push_back(position);
      if (&element == layout.vertices)
        for (const auto &[place, index] : kept)
          arrays.vertex_values[index].values.push_back(scalars[place]);
      if (&element == layout.faces) polygon_list.push_back(polygon);
      if (&element == layout.strips) strips_to_triangles(polygon, strip_triangles);
    }
  }
  PolygonTriangulation triangulation(arrays.positions, arrays.triangles);
  for (const std::vector<int> &corners : polygon_list) {
    triangulation.add(corners);
  }
  triangulation.finish(arrays.triangle_face, notes);
  if (layout.strips) {
    notes.push_back("read " + std::to_string(strip_triangles.size()) +
                    " triangles from triangle strips (numbered after the faces)");
    arrays.triangles.insert(arrays.triangles.end(), strip_triangles.begin(), strip_triangles.end());
  }
  return arrays;
}

} // namespace meromorph
