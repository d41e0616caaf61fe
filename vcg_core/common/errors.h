// Errors the core raises.
//
// In:  what is wrong and where (file line, vertex / edge / face indices), in words that name no
//      tool, flag or menu, and the remedies (remedy.h) as codes.
// Out: exceptions of five kinds that every adapter catches at its boundary and words for its
//      users: the CLI turns the kind into an exit code (cli/exit_codes.h) and the remedies into
//      its flags, the C ABI into a status and remedy codes, MeshLab and Blender into their menus.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "common/remedy.h"

namespace meromorph {

enum class ErrorKind {
  internal,  // a bug: an assumption of the mathematics failed
  arguments, // wrong use: a missing file, a bad option, an output that would overwrite the input
  input,     // the input cannot be parameterized: a broken file, an open surface, ...
  write,     // an output file cannot be written
  cancelled, // the user cancelled through the progress callback
};

class Error : public std::runtime_error {
public:
  Error(ErrorKind kind, const std::string &message, std::vector<Remedy> remedies = {},
        std::vector<int> faces = {})
      : std::runtime_error(message), kind_(kind), remedies_(std::move(remedies)),
        faces_(std::move(faces)) {}
  ErrorKind kind() const { return kind_; }
  const std::vector<Remedy> &remedies() const { return remedies_; }
  // The input's faces the message names by number (empty when it names none, or names faces of
  // a mesh derived from the input).
  const std::vector<int> &faces() const { return faces_; }

private:
  ErrorKind kind_;
  std::vector<Remedy> remedies_;
  std::vector<int> faces_;
};

// An assumption of the mathematics failed (periods parallel, an odd number of generators).
class InternalError : public Error {
public:
  explicit InternalError(const std::string &message) : Error(ErrorKind::internal, message) {}
};

// Wrong use: a missing file, an unsupported extension, an output that would overwrite the input.
class ArgumentError : public Error {
public:
  explicit ArgumentError(const std::string &message, std::vector<Remedy> remedies = {})
      : Error(ErrorKind::arguments, message, std::move(remedies)) {}
};

// The input cannot be parameterized: a broken file, an open or non-manifold surface, ...
class InputError : public Error {
public:
  explicit InputError(const std::string &message, std::vector<Remedy> remedies = {},
                      std::vector<int> faces = {})
      : Error(ErrorKind::input, message, std::move(remedies), std::move(faces)) {}
};

// An output file cannot be written (no such folder, no permission, disk full): the system's reason.
class WriteError : public Error {
public:
  explicit WriteError(const std::string &message) : Error(ErrorKind::write, message) {}
};

// The user cancelled through the progress callback.
class Cancelled : public Error {
public:
  Cancelled() : Error(ErrorKind::cancelled, "cancelled by the user") {}
};

// "vertices 3, 8, 12 and 40 more": at most `shown` indices, then how many were left out.
std::string list_indices(const std::vector<int> &indices, size_t shown = 10);

// Phrases joined by "; ", as messages list several reasons or causes.
std::string join_phrases(const std::vector<std::string> &phrases);

} // namespace meromorph
