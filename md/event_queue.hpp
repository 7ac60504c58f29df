#pragma once
// Event calendars holding at most one event per particle (Smallenburg's EDMD): an indexed binary
// heap (the baseline) and a bucketed calendar (time buckets of adaptive width whose current bucket
// is a small sorted array; far events wait in an overflow list). Both order events by (time, id), so the
// earliest event is unique and both queues agree exactly (tests compare them with a brute force).
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "md/huge_pages.hpp"

namespace coldblast::md {

/// Indexed binary min-heap of (time, id); ids in [0, capacity).
class HeapEventQueue {
 public:
  explicit HeapEventQueue(std::size_t capacity = 0);
  /// Inserts the event of `id` or moves it to `time` (any finite time).
  void set(std::int32_t id, double time);
  /// Removes the event of `id` if it has one.
  void remove(std::int32_t id);
  bool contains(std::int32_t id) const { return position_[id] >= 0; }
  /// The time of the event of `id`, which must have one (contains).
  double time_of(std::int32_t id) const { return heap_[static_cast<std::size_t>(position_[id])].time; }
  bool empty() const { return heap_.empty(); }
  std::size_t size() const { return heap_.size(); }
  /// Earliest event (time, id); the queue must not be empty.
  std::pair<double, std::int32_t> top() const { return {heap_[0].time, heap_[0].id}; }
  void pop() { remove(heap_[0].id); }
  /// The id of the event after the earliest one, or -1 (a prefetch hint, as CalendarEventQueue's).
  std::int32_t second_hint() const {
    if (heap_.size() < 3) return heap_.size() == 2 ? heap_[1].id : -1;
    return before(heap_[1], heap_[2]) ? heap_[1].id : heap_[2].id;
  }
  void clear();
  /// Bytes held per particle of capacity (for the memory budget).
  std::size_t bytes() const;

 private:
  struct Entry {
    double time;
    std::int32_t id;
  };
  static bool before(const Entry& x, const Entry& y) { return x.time < y.time || (x.time == y.time && x.id < y.id); }
  void sift_up(std::size_t k);
  void sift_down(std::size_t k);
  void place(std::size_t k, const Entry& e) {
    heap_[k] = e;
    position_[e.id] = static_cast<std::int32_t>(k);
  }
  HugeVector<Entry> heap_;
  HugeVector<std::int32_t> position_;  // index in heap_, -1 when absent
};

/// Bucketed event calendar: bucket k holds events with floor(time/width) = k. The bucket being
/// processed is a sorted array of at most 32 events (an indexed heap beyond that); the next
/// `bucket_count` buckets are doubly linked lists; later events sit in an overflow list that is
/// redistributed once per sweep. The width adapts so that about 2 events are popped per bucket
/// (it is rebuilt when the pop-per-bucket ratio leaves [1/4, 8]).
class CalendarEventQueue {
 public:
  explicit CalendarEventQueue(std::size_t capacity = 0);
  void set(std::int32_t id, double time);
  void remove(std::int32_t id);
  bool contains(std::int32_t id) const { return where_[id] != absent; }
  /// The time of the event of `id`, which must have one (contains).
  double time_of(std::int32_t id) const { return time_[id]; }
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  /// Earliest event (time, id); the queue must not be empty (not const: it may advance buckets).
  std::pair<double, std::int32_t> top() {
    if (sorted_size_ > 0)
      return {sorted_[sorted_size_ - 1].time, sorted_[sorted_size_ - 1].id};  // every event's fast path
    if (!heap_.empty()) return heap_.top();
    return top_slow();
  }
  void pop() {
    const std::int32_t id = top().second;
    if (sorted_size_ > 0)
      --sorted_size_;
    else
      heap_.pop();
    where_[id] = absent;
    --size_;
    if (++pops_ == adapt_interval) adapt();
  }
  /// The id of the event after the earliest one if it is known without work (it is in the current
  /// bucket), else -1: a hint for prefetching, not an order guarantee.
  std::int32_t second_hint() const { return sorted_size_ >= 2 ? sorted_[sorted_size_ - 2].id : -1; }
  void clear();
  std::size_t bytes() const;

 private:
  static constexpr std::uint64_t adapt_interval = 1 << 15;
  std::pair<double, std::int32_t> top_slow();
  void adapt();
  static constexpr std::int32_t absent = -3, in_heap = -1, in_overflow = -2;
  static constexpr std::int64_t unknown_bucket = INT64_MIN;
  // where_ of an event in sorted_: -4 - (its index), so that where_ <= -4.
  static constexpr std::int32_t sorted_code(std::size_t index) { return -4 - static_cast<std::int32_t>(index); }
  static constexpr std::size_t sorted_index(std::int32_t where) { return static_cast<std::size_t>(-4 - where); }
  // A current bucket of more events than this lives in heap_ instead of sorted_ (an insertion
  // into a sorted array costs its length: a huge bucket, before the width adapts, must not).
  static constexpr std::size_t sorted_limit = 32;
  struct Entry {
    double time;
    std::int32_t id;
  };
  static bool before(double t, std::int32_t i, const Entry& y) { return t < y.time || (t == y.time && i < y.id); }
  void add_to_current(std::int32_t id, double time) {
    if (sorted_size_ == sorted_limit) move_sorted_to_heap();
    if (!heap_.empty()) {
      heap_.set(id, time);
      where_[id] = in_heap;
      return;
    }
    // Insertion from the back (the earliest end).
    std::size_t k = sorted_size_++;
    while (k > 0 && !before(time, id, sorted_[k - 1])) {
      sorted_[k] = sorted_[k - 1];
      where_[sorted_[k].id] = sorted_code(k);
      --k;
    }
    sorted_[k] = {time, id};
    where_[id] = sorted_code(k);
  }
  void move_sorted_to_heap();
  void remove_sorted(std::int32_t where);
  void insert(std::int32_t id, double time);
  void unlink(std::int32_t id);
  void advance();  // moves to the next non-empty bucket; heap_ must be empty
  void redistribute_overflow();
  void rebuild(double new_width);
  std::int64_t bucket_of(double time) const {
    const double scaled = time * inverse_width_;
    if (scaled >= 0.0 && scaled < 1e18) return static_cast<std::int64_t>(scaled);  // truncation = floor
    return bucket_of_slow(scaled);
  }
  static std::int64_t bucket_of_slow(double scaled);

  // The current bucket: sorted_ (latest first, so the earliest event is popped from the back)
  // while it holds at most sorted_limit events, else heap_; the other one is empty.
  std::array<Entry, sorted_limit> sorted_;
  std::size_t sorted_size_ = 0;
  HeapEventQueue heap_;
  HugeVector<std::int32_t> head_;         // bucket lists, circular over bucket_count
  HugeVector<std::int32_t> next_, prev_;  // doubly linked lists (buckets and overflow)
  HugeVector<std::int32_t> where_;        // bucket slot, in_heap, in_overflow or absent
  HugeVector<double> time_;               // event time per id
  std::int32_t overflow_ = -1;            // overflow list head
  std::int64_t mask_ = 0;                 // bucket_count - 1 (a power of two)
  // Before the width is known both are at their minimum, so every event goes to the overflow list.
  std::int64_t current_ = unknown_bucket;     // absolute index of the current bucket
  std::int64_t window_end_ = unknown_bucket;  // lists hold buckets < window_end_, overflow the rest
  double width_ = 1.0;                        // bucket width (time)
  double inverse_width_ = 1.0;
  std::size_t size_ = 0, in_lists_ = 0, overflow_size_ = 0;
  std::uint64_t pops_ = 0, advances_ = 0;
  bool width_known_ = false;
};

}  // namespace coldblast::md
