// Numbers for a few items of a large set (vertices or faces of a region), found in constant time.
//
// In:  the items, in the order to number them (each once), and the size of the whole set.
// Out: `numbers(item)`: the item's position in that order, -1 for any other item of the set.
//      One array over the whole set per thread and `Tag` (each use names its own, so that one
//      numbering can be held while another is made inside it): set by the constructor, cleared by
//      the destructor, so a numbering costs the items' count, not the set's size, after the first
//      (kept between uses as the thread's scratch: common/thread_scratch.h).
#pragma once

#include <cstddef>
#include <vector>

#include "common/thread_scratch.h"

namespace meromorph {

template <class Tag> class LocalNumbers {
public:
  template <class Items> LocalNumbers(const Items &items, std::size_t set_size) {
    std::vector<int> &numbers = thread_scratch<Tag, std::vector<int>>(); // common/thread_scratch.h
    if (numbers.size() < set_size) numbers.assign(set_size, -1);
    numbers_ = &numbers;
    for (const auto &item : items)
      items_.push_back(item);
    for (std::size_t i = 0; i < items_.size(); ++i)
      numbers[std::size_t(items_[i])] = int(i);
  }
  ~LocalNumbers() {
    for (int item : items_)
      (*numbers_)[std::size_t(item)] = -1;
  }
  LocalNumbers(const LocalNumbers &) = delete;
  LocalNumbers &operator=(const LocalNumbers &) = delete;
  int operator()(int item) const { return (*numbers_)[std::size_t(item)]; }

private:
  std::vector<int> items_;
  std::vector<int> *numbers_;
};

} // namespace meromorph
