// Process-wide allocator policy for the programs that own their process (the CLI, the bench).
//
// In:  nothing. Out: glibc's malloc keeps freed memory for reuse instead of handing it back to the
// system at every free: the stages allocate and free arrays of the mesh's size one after another,
// and on a virtual machine every page handed back and touched again costs a page fault (measured:
// a 200k-vertex genus-2 `param` 11.2 s -> 7.1 s, a third of it kernel time before).
// Libraries must not call it: a host program (MeshLab, Blender) keeps its own policy.
#pragma once

namespace meromorph {

void keep_freed_memory_for_reuse();

} // namespace meromorph
