#include "io/mesh_format.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>

#include "common/errors.h"

namespace meromorph {

const char *format_name(MeshFormat format) {
  switch (format) {
  case MeshFormat::ply:
    return "PLY";
  case MeshFormat::obj:
    return "OBJ";
  case MeshFormat::off:
    return "OFF";
  case MeshFormat::stl:
    return "STL";
  }
  return "?";
}

const char *format_extension(MeshFormat format) {
  switch (format) {
  case MeshFormat::ply:
    return ".ply";
  case MeshFormat::obj:
    return ".obj";
  case MeshFormat::off:
    return ".off";
  case MeshFormat::stl:
    return ".stl";
  }
  return "";
}

namespace {

std::optional<MeshFormat> format_named(const std::string &path, std::string &extension) {
  extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == ".ply") return MeshFormat::ply;
  if (extension == ".obj") return MeshFormat::obj;
  if (extension == ".off") return MeshFormat::off;
  if (extension == ".stl") return MeshFormat::stl;
  return std::nullopt;
}

} // namespace

MeshFormat format_from_extension(const std::string &path) {
  std::string extension;
  if (const auto format = format_named(path, extension)) return *format;
  throw ArgumentError(path + ": meromorph reads .ply, .obj, .off and .stl files, not '" +
                      (extension.empty() ? std::string("(no extension)") : extension) + "'");
}

MeshFormat output_format(const std::string &path) {
  std::error_code error;
  if (!path.empty() && (path.back() == '/' || std::filesystem::is_directory(path, error)))
    throw ArgumentError(path + ": is a folder; give the output a file name in it, like " +
                        (path.back() == '/' ? path : path + "/") + "out.ply");
  std::string extension;
  if (const auto format = format_named(path, extension)) return *format;
  throw ArgumentError(path +
                      ": meromorph writes .ply, .obj, .off and .stl files; this output's "
                      "name ends in '" +
                      (extension.empty() ? std::string("(no extension)") : extension) +
                      "': give it one of those");
}

namespace {

bool starts_with_word(const std::string &head, const char *word) {
  size_t start = head.find_first_not_of(" \t\r\n");
  if (start == std::string::npos) return false;
  const size_t length = std::strlen(word);
  if (head.compare(start, length, word) != 0) return false;
  return start + length == head.size() || std::isspace((unsigned char)head[start + length]) ||
         std::isdigit((unsigned char)head[start + length]);
}

bool looks_like_off(const std::string &head) {
  size_t start = head.find_first_not_of(" \t\r\n");
  if (start == std::string::npos) return false;
  size_t end = head.find_first_of(" \t\r\n", start);
  std::string token =
      head.substr(start, end == std::string::npos ? std::string::npos : end - start);
  // OFF, COFF, NOFF, CNOFF, STOFF, ... (the keyword may be followed directly by the counts).
  const size_t at = token.find("OFF");
  return at != std::string::npos && at <= 4 && token.find_first_not_of("STCN4n") >= at;
}

bool is_binary_stl(const std::string &head, std::uintmax_t size) {
  if (size < 84 || head.size() < 84) return false;
  std::uint32_t count = 0;
  std::memcpy(&count, head.data() + 80, 4);
  return std::uintmax_t(84) + std::uintmax_t(50) * count == size;
}

bool has_binary_bytes(const std::string &head) {
  return std::any_of(head.begin(), head.end(), [](char c) {
    unsigned char u = (unsigned char)c;
    return u == 0 || (u < 32 && u != '\n' && u != '\r' && u != '\t' && u != '\f' && u != '\v');
  });
}

// What the first bytes say, where they are unambiguous.
std::optional<MeshFormat> format_from_content(const std::string &head, std::uintmax_t size) {
  if (head.compare(0, 3, "ply") == 0) return MeshFormat::ply;
  if (is_binary_stl(head, size)) return MeshFormat::stl;
  if (looks_like_off(head)) return MeshFormat::off;
  if (starts_with_word(head, "solid")) return MeshFormat::stl;
  return std::nullopt;
}

} // namespace

MeshFormat detect_format(const std::string &path) {
  const MeshFormat named = format_from_extension(path);
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw ArgumentError(path + ": no such file");
  if (std::filesystem::is_directory(path, error))
    throw ArgumentError(path + ": is a folder, not a mesh file");
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw ArgumentError(path + ": cannot be opened for reading");
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (size == 0) throw InputError(path + ": the file is empty");

  std::string head(std::min<std::uintmax_t>(size, 4096), '\0');
  stream.read(head.data(), std::streamsize(head.size()));
  head.resize(size_t(stream.gcount()));
  if (head.compare(0, 3, "\xEF\xBB\xBF") == 0) head.erase(0, 3); // a UTF-8 byte-order mark

  const std::optional<MeshFormat> content = format_from_content(head, size);
  if (content && *content != named)
    throw InputError(path + ": the file is named " + std::string(format_extension(named)) +
                     " but its content is " + format_name(*content) + "; rename it to " +
                     format_extension(*content));
  if (named == MeshFormat::ply && !content)
    throw InputError(path + ": not a PLY file (it does not start with 'ply')");
  if (named == MeshFormat::off && !content)
    throw InputError(path + ": not an OFF file (it does not start with the OFF keyword)");
  if (named == MeshFormat::stl && !content)
    throw InputError(path + ": not an STL file (neither 'solid ...' text nor a binary STL whose "
                            "size matches its triangle count)");
  if ((named == MeshFormat::obj || named == MeshFormat::off) && has_binary_bytes(head))
    throw InputError(path + ": holds binary data, but " + format_name(named) +
                     " files are text; is it a different format with the wrong extension?");
  return named;
}

} // namespace meromorph
