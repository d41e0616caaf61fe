// The command-line tool's settings for its own process (the bench's too). The library never
// calls this: in a host (MeshLab, Blender, Python) the host's settings stay as they are.
//
// In:  nothing. Out: glibc's malloc keeps the memory a job frees for the job's next arrays
//      instead of handing it back to the system at every free (M_TRIM_THRESHOLD, M_TOP_PAD,
//      M_MMAP_THRESHOLD), with one heap for all threads (M_ARENA_MAX: the job runs on a worker
//      thread). `tune_blas_for_job`: OpenBLAS, where it is the BLAS, on one thread for a mesh
//      below `parallel_blas_vertices`, and on the CPUs free now (common/job_threads.h) above.
// Why: the stages allocate and free arrays of the mesh's size one after another, and on a
// virtual machine every 4 KiB page touched for the first time costs a page fault (a 200k-vertex
// genus-2 `param`: 13.8 s as glibc's defaults have it, 7.2 s keeping freed memory). OpenBLAS's
// second thread spins on the core that our loops need after every call (a 4k-vertex map took
// 100-130 ms instead of 21-25 in a third of the runs); it pays in the dense products of the
// factorizations of large meshes only (a 333k-vertex genus-5 map 25% faster with it).
// (Transparent huge pages for the heap, GLIBC_TUNABLES=glibc.malloc.hugetlb=1, were tried and
// dropped: on a machine up for hours, whose memory is fragmented, they made `param` 30-40% slower
// from 200k to 800k vertices, 2.34-2.64 s against 1.74-1.98 s and 12.0-12.7 s against 8.6-8.8 s.)
#pragma once

namespace meromorph::cli {

void tune_command_line_process();

constexpr long parallel_blas_vertices = 300000;
void tune_blas_for_job(long vertices);

} // namespace meromorph::cli
