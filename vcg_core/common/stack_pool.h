// Memory for the nodes of a small map that lives in one function: a buffer on the stack, handed
// out in order and given back all at once when the pool goes (std::pmr's monotonic resource).
//
// In:  nothing. Out: `StackPool pool; std::pmr::map<K, V> map(&pool);`: no allocation per node
//      while the buffer lasts (32 KiB: a branch spot's few hundred vertices), the heap after.
// Why: branch snapping builds thousands of such maps per pass, and allocating their nodes was 41%
// of its time on raw marching cubes with needles.
#pragma once

#include <cstddef>
#include <memory_resource>

namespace meromorph {

class StackPool : public std::pmr::monotonic_buffer_resource {
public:
  StackPool() : std::pmr::monotonic_buffer_resource(buffer_, sizeof buffer_) {}

private:
  alignas(std::max_align_t) char buffer_[32768];
};

} // namespace meromorph
