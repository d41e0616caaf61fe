// Remedies (common/remedy.h) in the words of a command-line user: this tool's flags, and for
// what it does not do itself, where MeshLab and Blender do it.
//
// In:  a remedy, or an error with its remedies, or a map's advice.
// Out: "run again with --repair", ...; an error's message followed by its remedies; "cause:
//      remedy; cause: remedy".
#pragma once

#include <string>
#include <vector>

#include "common/errors.h"

namespace meromorph::cli {

std::string remedy_words(Remedy remedy);

// The message, then "; " and each remedy's words.
std::string with_remedies(const std::string &message, const std::vector<Remedy> &remedies);

// Each cause with its remedy after a colon, joined by "; ".
std::string advice_words(const std::vector<Advice> &advice);

} // namespace meromorph::cli
