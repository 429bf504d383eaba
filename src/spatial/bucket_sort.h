// The one counting sort: items into numbered buckets, stable, no comparisons. Grids file
// points and boxes into cells with it; range and bearing orders a device's occluders by
// distance with it, the sensor rays their candidates.
#pragma once
#include <vector>

namespace essaim {

/// Sorts items 0..n-1 into buckets 0..B-1, B = bucket_start->size() - 1.
/// `buckets_of(i, file)` calls file(b) for each bucket b item i goes into (a point one, a
/// box every cell it covers, each at most once); `place(slot, i)` stores item i at `slot`.
/// After the call bucket b holds slots [(*bucket_start)[b], (*bucket_start)[b + 1]), its
/// items in ascending order, and the return value is the number of slots. Items are
/// placed last to first, each bucket filled from its end, so the order is stable and
/// `bucket_start` ends up holding the starts without a second pass. Allocates nothing.
template <class BucketsOf, class Place>
int BucketSort(int n, std::vector<int>* bucket_start, BucketsOf&& buckets_of, Place&& place) {
  std::vector<int>& start = *bucket_start;
  const size_t buckets = start.size() - 1;
  std::fill(start.begin(), start.end(), 0);
  for (int i = 0; i < n; ++i) buckets_of(i, [&](int b) { ++start[b]; });
  for (size_t b = 1; b < buckets; ++b) start[b] += start[b - 1];  // each bucket's end
  const int total = buckets > 0 ? start[buckets - 1] : 0;
  start[buckets] = total;
  for (int i = n - 1; i >= 0; --i) buckets_of(i, [&](int b) { place(--start[b], i); });
  return total;
}

}  // namespace essaim
