// All-or-nothing outputs: every file of a job is written beside its target under a temporary
// name, and moved into place only when all of them were written.
//
// In:  the job's inputs (never written over) and its output paths, one `add` each.
// Out: for each output, the temporary path to write it to: a file created exclusively (never
//      through a link) in a folder of its own with an unpredictable name (mode 0700), made in the
//      target's folder, so no other user can aim the write elsewhere; `commit` renames them all
//      into place. Whatever was not committed is removed when the object goes away, so a failed
//      job leaves no output and no partial file behind.
// Errors (from `add`, before any work): ArgumentError when an output is an input, names the same
//      file as another output (after `.`, `..` and links are resolved), or exists and is not a
//      regular file (a folder, a device, a FIFO, a socket); WriteError (with the system's reason)
//      when the target's folder cannot take a file, or a file cannot be written or moved.
#pragma once

#include <string>
#include <vector>

#include "common/errors.h"

namespace meromorph {

class StagedOutputs {
public:
  explicit StagedOutputs(std::vector<std::string> inputs);
  StagedOutputs(const StagedOutputs &) = delete;
  StagedOutputs &operator=(const StagedOutputs &) = delete;
  ~StagedOutputs();

  // Registers `path`; returns the temporary path to write it to.
  std::string add(const std::string &path);
  // Moves every temporary file into place.
  void commit();
  // Runs `write` (which writes the temporary files); a WriteError it throws names the outputs,
  // not their temporary paths.
  template <class Write> void writing(Write &&write) {
    try {
      write();
    } catch (const WriteError &error) {
      throw WriteError(in_output_names(error.what()));
    }
  }
  // `message` with every temporary path replaced by its output's path.
  std::string in_output_names(std::string message) const;

private:
  std::vector<std::string> inputs_, outputs_, folders_, temporaries_;
};

// Writes `text` to `path` (the whole file or nothing); throws WriteError with the system's reason.
void write_text_file(const std::string &path, const std::string &text);

} // namespace meromorph
