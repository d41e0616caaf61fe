// Exit codes of the command-line tool (design.md section 3), from the kind of error.
//
// In:  an error kind (common/errors.h).
// Out: 0 done, 1 internal failure or cancelled, 2 bad arguments, 3 the input cannot be
//      parameterized (or the map is not valid), 4 an output cannot be written.
#pragma once

#include "common/errors.h"

namespace meromorph::cli {

enum class ExitCode : int {
  done = 0,
  internal_failure = 1,
  bad_arguments = 2,
  cannot_parameterize = 3,
  cannot_write = 4,
};

inline ExitCode exit_code(ErrorKind kind) {
  switch (kind) {
  case ErrorKind::arguments:
    return ExitCode::bad_arguments;
  case ErrorKind::input:
    return ExitCode::cannot_parameterize;
  case ErrorKind::write:
    return ExitCode::cannot_write;
  default:
    return ExitCode::internal_failure;
  }
}

} // namespace meromorph::cli
