// Scratch arrays a thread keeps between uses.
//
// In:  a tag naming one use and the scratch's type. Out: `thread_scratch<Tag, T>()`: the calling
//      thread's own T for that tag (made empty at its first use, then as the last use left it;
//      freed when the thread ends).
// Why: a region's numbering (mesh/local_numbers.h) and a search's marks (mesh/mesh_edges.h) are
// arrays over the whole mesh, one per thread, kept so that each use costs its region, not the
// mesh.
#pragma once

namespace meromorph {

template <class Tag, class T> T &thread_scratch() {
  thread_local T scratch;
  return scratch;
}

} // namespace meromorph
