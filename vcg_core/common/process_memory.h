// Process-wide allocator policy for the programs that own their process (the CLI, the bench).
//
// In:  the program's argv. Out: the process runs with glibc's malloc asking the kernel for
// transparent huge pages, keeping freed memory for reuse instead of handing it back at every
// free, and one heap for all threads (the job runs on a worker thread). The stages allocate and
// free arrays of the mesh's size one after another; on a virtual machine every 4 KiB page touched
// for the first time costs a page fault. Measured on a 200k-vertex genus-2 `param`: 13.8 s as it
// was, 7.2 s keeping freed memory (474k -> 240k page faults), 5.8 s with huge pages too (2.5k page
// faults). Huge pages for malloc are a glibc tunable read at start-up only, so the process restarts
// itself once with it set (GLIBC_TUNABLES); where that cannot be done it goes on without them.
// Libraries must not call it: a host program (MeshLab, Blender) keeps its own policy.
#pragma once

namespace meromorph {

void tune_process_memory(char **argv);

} // namespace meromorph
