#include "io/staged_outputs.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/errors.h"

namespace meromorph {
namespace {

namespace fs = std::filesystem;

std::string system_reason(int error) {
  return std::strerror(error);
}

// What an existing output path is, where it is not a regular file (links followed); empty
// otherwise.
std::string not_a_regular_file(const std::string &path) {
  struct stat status;
  if (::stat(path.c_str(), &status) != 0) return ""; // it does not exist (yet)
  if (S_ISREG(status.st_mode)) return "";
  if (S_ISDIR(status.st_mode)) return "a folder";
  if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode)) return "a device";
  if (S_ISFIFO(status.st_mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(status.st_mode)) return "a socket";
  return "not a regular file";
}

// The file `path` names, whether or not it exists: absolute, with `.`, `..` and the links of its
// existing part resolved.
fs::path resolved(const std::string &path) {
  std::error_code error;
  fs::path absolute = fs::absolute(path, error);
  if (error) return fs::path(path).lexically_normal();
  const fs::path canonical = fs::weakly_canonical(absolute, error);
  return error ? absolute.lexically_normal() : canonical;
}

bool same_file(const std::string &a, const std::string &b) {
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) return fs::equivalent(a, b, error);
  return resolved(a) == resolved(b);
}

} // namespace

StagedOutputs::StagedOutputs(std::vector<std::string> inputs) : inputs_(std::move(inputs)) {}

StagedOutputs::~StagedOutputs() {
  for (const std::string &temporary : temporaries_)
    ::unlink(temporary.c_str());
  for (const std::string &folder : folders_)
    ::rmdir(folder.c_str());
}

std::string StagedOutputs::add(const std::string &path) {
  if (path.empty()) throw ArgumentError("an output path is empty");
  const std::string kind = not_a_regular_file(path);
  if (!kind.empty())
    throw ArgumentError(path + ": is " + kind +
                        ", not a file; meromorph writes its outputs to regular files only: "
                        "give a file name for the output");
  for (const std::string &input : inputs_)
    if (same_file(path, input))
      throw ArgumentError(path + ": this is the input file; meromorph never writes over its "
                                 "input, choose another output name");
  for (const std::string &other : outputs_)
    if (same_file(path, other))
      throw ArgumentError(path + ": named for two outputs (as " + other +
                          " too); give each output its own file");

  // A folder of our own beside the target: nobody else can put a link or a file into it.
  const fs::path target = fs::path(path);
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string pattern =
      (parent / ("." + target.filename().string() + ".meromorph-XXXXXX")).string();
  if (!::mkdtemp(pattern.data()))
    throw WriteError(path + ": could not be written (" + system_reason(errno) + ")");
  folders_.push_back(pattern);
  const std::string temporary = pattern + "/" + target.filename().string();
  const int file = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                          0666); // the user's umask applies, as to any new file
  if (file < 0) throw WriteError(path + ": could not be written (" + system_reason(errno) + ")");
  ::close(file);
  outputs_.push_back(path);
  temporaries_.push_back(temporary);
  return temporary;
}

void StagedOutputs::commit() {
  // Checked again at the end: an output that became a folder or a device meanwhile fails here,
  // before anything is moved.
  for (const std::string &output : outputs_) {
    const std::string kind = not_a_regular_file(output);
    if (!kind.empty()) throw WriteError(output + ": could not be written (it is now " + kind + ")");
  }
  for (size_t i = 0; i < outputs_.size(); ++i)
    if (::rename(temporaries_[i].c_str(), outputs_[i].c_str()) != 0)
      throw WriteError(outputs_[i] + ": could not be written (" + system_reason(errno) + ")");
  temporaries_.clear();
}

std::string StagedOutputs::in_output_names(std::string message) const {
  for (size_t i = 0; i < temporaries_.size() && i < outputs_.size(); ++i)
    for (size_t at = message.find(temporaries_[i]); at != std::string::npos;
         at = message.find(temporaries_[i], at + outputs_[i].size()))
      message.replace(at, temporaries_[i].size(), outputs_[i]);
  return message;
}

void write_text_file(const std::string &path, const std::string &text) {
  std::FILE *file = std::fopen(path.c_str(), "wb");
  if (!file) throw WriteError(path + ": could not be written (" + std::strerror(errno) + ")");
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  const int saved = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed) {
    std::remove(path.c_str());
    throw WriteError(path + ": could not be written (" + std::strerror(written ? errno : saved) +
                     ")");
  }
}

} // namespace meromorph
