// Scratch arrays a thread keeps between uses, and their release when a job is done.
//
// In:  a tag naming one use and the scratch's type. Out: `thread_scratch<Tag, T>()`: the calling
//      thread's own T for that tag (made empty at its first use, then as the last use left it);
//      `release_team_scratch()`: every such scratch of the calling thread and of its OpenMP
//      team's threads emptied, their memory freed (call it between jobs, with no scratch in use).
// Why: a region's numbering (mesh/local_numbers.h) and a search's marks (mesh/mesh_edges.h) are
// arrays over the whole mesh, one per thread, kept so that each use costs its region, not the
// mesh. Threads that outlive a job (the job thread kept for the next one, common/progress.h, and
// its OpenMP team, in a host that maps many meshes) would otherwise hold them until the host
// ends: 13 MB a thread at a million vertices.
#pragma once

#include <functional>
#include <vector>

namespace meromorph {

// The calling thread's ways to empty its scratch, one per scratch it has used.
std::vector<std::function<void()>> &thread_scratch_releases();

template <class Tag, class T> T &thread_scratch() {
  thread_local T scratch;
  thread_local bool known = false;
  if (!known) {
    known = true;
    thread_scratch_releases().push_back([] { T().swap(scratch); });
  }
  return scratch;
}

void release_team_scratch();

} // namespace meromorph
