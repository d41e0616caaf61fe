// OpenMP parallel regions that can only have one thread, run as plain calls, in the programs that
// own their process (the command-line tool and the bench link common/serial_openmp_regions.cpp).
//
// In:  every `#pragma omp parallel` of the program, ours and CHOLMOD's: GCC compiles each into a
//      call of libgomp's GOMP_parallel(body, data, threads, flags), which the definition there
//      takes the place of, for the objects linked into the program at link time and for the
//      shared libraries it loads (CHOLMOD in the bench) through the program's exported symbol.
// Out: a region that would get a team of one thread (an `if` clause that is false, num_threads(1)
//      or OMP_NUM_THREADS=1, or no more active levels: common/factorization_threads.h lets no
//      region have a team while a factorization runs) is the call body(data); every other region
//      goes to libgomp's GOMP_parallel as before. Inside a region run so, OpenMP answers as in a
//      team of one (omp_get_thread_num() 0, omp_get_num_threads() 1; orphaned loops, barriers,
//      single and critical constructs and tasks run on this thread), but the nesting level is not
//      counted: a region inside it sees the level of the code around it, as an inactive region's
//      inner region sees the active level.
//      `hand_every_openmp_region_to_libgomp()`: from then on every region goes to libgomp, as in
//      a program without this file (the bench's floor: CHOLMOD as anyone calls it).
// Why: libgomp makes a team even for one thread and ends it by waking the team's barrier with a
//      system call: 1.3 to 1.5 microseconds a region on the two-core VMs. Debian 12's CHOLMOD
//      opens about 7.5 regions per supernode in a numeric factorization, all of them serial while
//      it runs (1085 regions at 4k unknowns: the factorization 4.8 -> 3.2 ms, least of 5).
#pragma once

namespace meromorph {

void hand_every_openmp_region_to_libgomp();

} // namespace meromorph
