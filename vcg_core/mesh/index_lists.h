// Lists of indices per owner (the faces at each vertex, the edges at each vertex) in one array.
//
// In:  the number of owners and a visitor that emits every (owner, item) pair, the same pairs in
//      the same order each time it is called (it is called twice: to count, then to fill).
// Out: `IndexLists`: list v is items[start[v] .. start[v + 1]), in the order emitted; `lists[v]`
//      is a range over it (begin, end, size, empty, operator[]). One allocation for all the lists
//      instead of one a vertex: at a million vertices, half the memory and no allocator traffic.
#pragma once

#include <cstddef>
#include <vector>

namespace meromorph {

struct IndexRange {
  const int *first = nullptr, *last = nullptr;
  const int *begin() const { return first; }
  const int *end() const { return last; }
  std::size_t size() const { return std::size_t(last - first); }
  bool empty() const { return first == last; }
  int operator[](std::size_t i) const { return first[i]; }
};

struct IndexLists {
  std::vector<int> start, items;

  IndexRange operator[](std::size_t owner) const {
    return {items.data() + start[owner], items.data() + start[owner + 1]};
  }
  std::size_t size() const { return start.empty() ? 0 : start.size() - 1; }

  template <class Visit> static IndexLists grouped(std::size_t owners, const Visit &visit) {
    IndexLists out;
    out.start.assign(owners + 1, 0);
    visit([&](int owner, int) { ++out.start[std::size_t(owner) + 1]; });
    for (std::size_t v = 0; v < owners; ++v)
      out.start[v + 1] += out.start[v];
    out.items.resize(std::size_t(out.start[owners]));
    std::vector<int> next(out.start.begin(), out.start.end() - 1);
    visit([&](int owner, int item) { out.items[std::size_t(next[std::size_t(owner)]++)] = item; });
    return out;
  }
};

} // namespace meromorph
