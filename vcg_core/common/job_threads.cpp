#include "common/job_threads.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

#include <dirent.h>
#include <sched.h>

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace meromorph {
namespace {

thread_local int team = 0; // 0: no job on this thread

int openmp_limit() {
#if defined(_OPENMP)
  return omp_get_max_threads();
#else
  return 1;
#endif
}

int usable_cpus() {
  cpu_set_t mask;
  if (sched_getaffinity(0, sizeof(mask), &mask) != 0) return 1;
  return std::max(1, CPU_COUNT(&mask));
}

// Runnable threads of the whole system now (the numerator of /proc/loadavg's fourth field);
// -1 where it cannot be read.
int system_runnable() {
  std::FILE *file = std::fopen("/proc/loadavg", "r");
  if (!file) return -1;
  double one, five, fifteen;
  int runnable = -1, total = 0;
  if (std::fscanf(file, "%lf %lf %lf %d/%d", &one, &five, &fifteen, &runnable, &total) != 5)
    runnable = -1;
  std::fclose(file);
  return runnable;
}

// This process's threads that are running or runnable now (state R in /proc/self/task/*/stat).
int own_runnable() {
  DIR *tasks = opendir("/proc/self/task");
  if (!tasks) return 1;
  int count = 0;
  while (const dirent *entry = readdir(tasks)) {
    if (entry->d_name[0] == '.') continue;
    const std::string path = std::string("/proc/self/task/") + entry->d_name + "/stat";
    std::FILE *file = std::fopen(path.c_str(), "r");
    if (!file) continue;
    char line[512] = {0};
    const size_t read = std::fread(line, 1, sizeof(line) - 1, file);
    std::fclose(file);
    line[read] = 0;
    const char *after_name = std::strrchr(line, ')'); // the name may hold spaces and parentheses
    if (after_name && after_name[1] == ' ' && after_name[2] == 'R') ++count;
  }
  closedir(tasks);
  return std::max(1, count); // this thread runs
}

} // namespace

int team_size_for(int cpus, int openmp_limit, int runnable, int own_runnable) {
  const int usable = std::max(1, std::min(cpus, openmp_limit));
  if (runnable < 0) return usable; // nothing known of the others
  const int others = std::max(0, runnable - own_runnable);
  return std::clamp(usable - others, 1, usable);
}

namespace {
thread_local long regions_opened = 0;
} // namespace

long parallel_regions_opened() {
  return regions_opened;
}

void count_parallel_region() {
  ++regions_opened;
}

int job_team_size() {
  return team > 0 ? team : openmp_limit();
}

int free_cpus() {
  return team_size_for(usable_cpus(), openmp_limit(), system_runnable(), own_runnable());
}

JobThreads::JobThreads() {
  if (team > 0) return;
  outermost_ = true;
  team = free_cpus();
}

JobThreads::JobThreads(int team_size) {
  if (team > 0) return;
  outermost_ = true;
  team = std::max(1, team_size);
}

JobThreads::~JobThreads() {
  if (outermost_) team = 0;
}

int JobThreads::threads() const {
  return job_team_size();
}

} // namespace meromorph
