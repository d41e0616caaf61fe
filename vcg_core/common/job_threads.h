// How many threads a job's parallel loops use: decided by the project's own code when a job
// starts, for the thread that runs it; no process-wide setting is touched.
//
// In:  the machine as the job starts: the CPUs this process may run on (its affinity mask),
//      capped by OpenMP's limit for this thread (OMP_NUM_THREADS), and the threads of other
//      processes that are running or waiting to run right now (the system's count of runnable
//      threads in /proc/loadavg, less this process's own).
// Out: `JobThreads`: while it lives, the loops of common/parallel_for.h started on this thread
//      run teams of `job_team_size()` threads, the free CPUs (at least one); a JobThreads made
//      while another lives on the same thread keeps the first one's count. Without one, loops
//      use OpenMP's maximum. `team_size_for` is the rule itself. `parallel_regions_opened`: how
//      many parallel regions (teams of more than one thread) the loops started on this thread
//      have opened, for a test that a stage does not open hundreds of short ones.
// Why: OpenMP's waiting threads spin. With another busy process on two cores, a team of two
//      waits at every barrier for the thread the system put aside: a 118k-vertex genus-1 map took
//      1.9-2.4 s with two threads against 0.9-1.0 s with one. A core busy with other work is left
//      to it; on an idle machine every core works.
#pragma once

namespace meromorph {

// The team for `cpus` usable CPUs (capped by `openmp_limit`) when `runnable` threads of the
// whole system are runnable now, `own_runnable` of them this process's.
int team_size_for(int cpus, int openmp_limit, int runnable, int own_runnable);

// The team size for loops started on this thread.
int job_team_size();

// The CPUs free for a job started now: team_size_for over this machine as it is (the rule
// JobThreads applies).
int free_cpus();

// Counted by common/parallel_for.h.
long parallel_regions_opened();
void count_parallel_region();

class JobThreads {
public:
  JobThreads();
  explicit JobThreads(int team); // a team of this size (at least 1) instead of the free CPUs
  ~JobThreads();
  JobThreads(const JobThreads &) = delete;
  JobThreads &operator=(const JobThreads &) = delete;
  int threads() const;

private:
  bool outermost_ = false;
};

} // namespace meromorph
