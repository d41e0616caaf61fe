// Errors the core raises, and the process exit code each one maps to.
//
// In:  a message in the user's words (what is wrong and where: file line, vertex/edge/face
// indices). Out: exceptions that every adapter catches at its boundary: the CLI turns them into
// exit codes,
//      the C ABI into error codes, MeshLab into errorMessage, Blender into an ERROR report.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace meromorph {

// Exit codes of the command-line tool (design.md section 3).
enum class ExitCode : int {
  done = 0,
  internal_failure = 1,
  bad_arguments = 2,
  cannot_parameterize = 3,
  cannot_write = 4,
};

class Error : public std::runtime_error {
public:
  Error(ExitCode code, const std::string &message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

private:
  ExitCode code_;
};

// Wrong use: a missing file, an unsupported extension, an output that would overwrite the input.
class ArgumentError : public Error {
public:
  explicit ArgumentError(const std::string &message) : Error(ExitCode::bad_arguments, message) {}
};

// The input cannot be parameterized: a broken file, an open or non-manifold surface, ...
class InputError : public Error {
public:
  explicit InputError(const std::string &message) : Error(ExitCode::cannot_parameterize, message) {}
};

// An output file cannot be written (no such folder, no permission, disk full): the system's reason.
class WriteError : public Error {
public:
  explicit WriteError(const std::string &message) : Error(ExitCode::cannot_write, message) {}
};

// The user cancelled through the progress callback.
class Cancelled : public Error {
public:
  Cancelled() : Error(ExitCode::internal_failure, "cancelled by the user") {}
};

// "vertices 3, 8, 12 and 40 more": at most `shown` indices, then how many were left out.
std::string list_indices(const std::vector<int> &indices, size_t shown = 10);

// Phrases joined by "; ", as messages list several reasons or causes.
std::string join_phrases(const std::vector<std::string> &phrases);

} // namespace meromorph
