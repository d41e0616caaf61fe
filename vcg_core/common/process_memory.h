// Process-wide allocator policy for the programs that own their process (the CLI, the bench).
//
// In:  the number of bytes the job is expected to need at most (an estimate; the CLI takes it
//      from the input file's size, heap_bytes_for_files). Out: glibc's malloc keeps freed memory
//      for reuse instead of handing it back at every free, uses one heap for all threads (the job
//      runs on a worker thread), and the heap's first `expected_bytes` are reserved (address
//      space only: nothing is touched) and asked for transparent huge pages (madvise).
//      OpenBLAS's idle threads may be ended at a job's start (common/blas_threads.h).
// Why: the stages allocate and free arrays of the mesh's size one after another; on a virtual
// machine every 4 KiB page touched for the first time costs a page fault. Measured on a
// 200k-vertex genus-2 `param`: 13.8 s as it was, 7.2 s keeping freed memory (474k -> 240k page
// faults), 5.8 s with huge pages too (2.5k page faults). Huge pages were first had from glibc's
// tunable `glibc.malloc.hugetlb=1`, which is read at start-up only, by the process restarting
// itself with it set: that restart (loading CHOLMOD and OpenBLAS twice) cost 15 ms of every run,
// a quarter of a 4k-vertex map's time. Memory beyond the reservation comes in ordinary pages.
// `GLIBC_TUNABLES` with `glibc.malloc.hugetlb` in it, set by the user, is followed instead (no
// reservation, no advice). Libraries must not call it: a host program (MeshLab, Blender) keeps
// its own policy.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace meromorph {

void tune_process_memory(size_t expected_bytes);

// A generous estimate of a job's peak memory from the sizes of the files it reads (100 times the
// largest, at least `at_least`, at most half the machine's memory): a closed mesh's `param` peaks
// at about 50 times its binary PLY's size and 25 times its text OFF's. Names that are not regular
// files count 0.
size_t heap_bytes_for_files(const std::vector<std::string> &paths, size_t at_least = size_t(256)
                                                                                     << 20);

// For one large array not yet touched, in any process (a host's too: it changes nothing but how
// these pages come): the whole 2 MiB blocks inside [data, data + bytes) asked for transparent huge
// pages (madvise), so that first touching them costs one page fault a block instead of one a
// 4 KiB page. Where the pages already come huge (the CLI's heap) or the system has no such
// pages, nothing changes.
void advise_huge_pages(void *data, size_t bytes);

} // namespace meromorph
