// The command-line tool's settings for its own process (the bench's too). The library never
// calls this: in a host (MeshLab, Blender, Python) the host's settings stay as they are.
//
// In:  nothing. Out: glibc's malloc keeps the memory a job frees for the job's next arrays
//      instead of handing it back to the system at every free (M_TRIM_THRESHOLD, M_TOP_PAD,
//      M_MMAP_THRESHOLD), with one heap for all threads (M_ARENA_MAX: the job runs on a worker
//      thread); OpenBLAS, where it is the BLAS, on one thread.
// Why: the stages allocate and free arrays of the mesh's size one after another, and on a
// virtual machine every 4 KiB page touched for the first time costs a page fault (a 200k-vertex
// genus-2 `param`: 13.8 s as glibc's defaults have it, 7.2 s keeping freed memory). OpenBLAS's
// second thread spins on the core that our loops need after every call (a 4k-vertex map took
// 100-130 ms instead of 21-25 in a third of the runs); its gain, 10% of the dense products of an
// 800k-unknown factorization, is less than that costs below a few hundred thousand unknowns.
// Huge pages are a system's and a user's choice, not set here: `GLIBC_TUNABLES=
// glibc.malloc.hugetlb=1` (README) gives the heap transparent huge pages.
#pragma once

namespace meromorph::cli {

void tune_command_line_process();

} // namespace meromorph::cli
