#include "io/staged_outputs.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "common/errors.h"
#include "io/mesh_writer.h"

namespace meromorph {

StagedOutputs::StagedOutputs(std::vector<std::string> inputs) : inputs_(std::move(inputs)) {}

StagedOutputs::~StagedOutputs() {
  std::error_code ignored;
  for (const std::string &temporary : temporaries_)
    std::filesystem::remove(temporary, ignored);
}

std::string StagedOutputs::add(const std::string &path) {
  std::error_code error;
  if (path.empty()) throw ArgumentError("an output path is empty");
  if (std::filesystem::is_directory(path, error))
    throw ArgumentError(path + ": is a folder; give a file name for the output");
  refuse_to_overwrite(path, inputs_);
  for (const std::string &other : outputs_)
    if (std::filesystem::weakly_canonical(path, error) ==
        std::filesystem::weakly_canonical(other, error))
      throw ArgumentError(path + ": named for two outputs; give each output its own file");
  outputs_.push_back(path);
  temporaries_.push_back(path + ".meromorph-partial");
  return temporaries_.back();
}

void StagedOutputs::commit() {
  for (size_t i = 0; i < outputs_.size(); ++i) {
    std::error_code error;
    std::filesystem::rename(temporaries_[i], outputs_[i], error);
    if (error) throw WriteError(outputs_[i] + ": could not be written (" + error.message() + ")");
  }
  temporaries_.clear();
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
