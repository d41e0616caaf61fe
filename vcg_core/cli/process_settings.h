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
// `run_with_huge_pages`: where the job is large (an argument names a file of more than 1 MB, or
// `always`), the program runs again at once with glibc's own setting for transparent huge pages
// on its heap (GLIBC_TUNABLES=glibc.malloc.hugetlb=1, which glibc reads at start only), unless
// the user's GLIBC_TUNABLES says glibc.malloc.hugetlb already; it returns where it does not.
// Measured: a 50k-vertex genus-0 `param` took 0.49-0.55 s with 35k page faults, 0.39-0.42 s with
// 1.3k; the second start costs a few milliseconds (the tool links its solvers statically).
#pragma once

namespace meromorph::cli {

void run_with_huge_pages(int argc, char **argv, bool always = false);

void tune_command_line_process();

constexpr long parallel_blas_vertices = 300000;
void tune_blas_for_job(long vertices);

} // namespace meromorph::cli
