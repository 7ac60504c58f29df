#include "md/event_queue.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace coldblast::md {

// ---------------------------------------------------------------- HeapEventQueue

HeapEventQueue::HeapEventQueue(std::size_t capacity) : position_(capacity, -1) {}

void HeapEventQueue::clear() {
  for (const Entry& e : heap_) position_[e.id] = -1;
  heap_.clear();
}

std::size_t HeapEventQueue::bytes() const {
  return heap_.capacity() * sizeof(Entry) + position_.capacity() * sizeof(std::int32_t);
}

void HeapEventQueue::sift_up(std::size_t k) {
  const Entry e = heap_[k];
  while (k > 0) {
    const std::size_t parent = (k - 1) / 2;
    if (!before(e, heap_[parent])) break;
    place(k, heap_[parent]);
    k = parent;
  }
  place(k, e);
}

void HeapEventQueue::sift_down(std::size_t k) {
  const Entry e = heap_[k];
  const std::size_t n = heap_.size();
  while (true) {
    std::size_t child = 2 * k + 1;
    if (child >= n) break;
    if (child + 1 < n && before(heap_[child + 1], heap_[child])) ++child;
    if (!before(heap_[child], e)) break;
    place(k, heap_[child]);
    k = child;
  }
  place(k, e);
}

void HeapEventQueue::set(std::int32_t id, double time) {
  assert(id >= 0 && static_cast<std::size_t>(id) < position_.size());
  const std::int32_t k = position_[id];
  if (k < 0) {
    heap_.push_back({time, id});
    position_[id] = static_cast<std::int32_t>(heap_.size() - 1);
    sift_up(heap_.size() - 1);
    return;
  }
  const double old = heap_[k].time;
  heap_[k].time = time;
  if (time < old)
    sift_up(k);
  else
    sift_down(k);
}

void HeapEventQueue::remove(std::int32_t id) {
  const std::int32_t k = position_[id];
  if (k < 0) return;
  position_[id] = -1;
  const Entry last = heap_.back();
  heap_.pop_back();
  if (static_cast<std::size_t>(k) == heap_.size()) return;
  place(k, last);
  if (k > 0 && before(last, heap_[(k - 1) / 2]))
    sift_up(k);
  else
    sift_down(k);
}

// ------------------------------------------------------------ CalendarEventQueue

namespace {
std::size_t bucket_count_for(std::size_t capacity) {
  std::size_t count = 1024;
  while (count < capacity && count < (std::size_t{1} << 22)) count *= 2;
  return count;
}
constexpr double target_per_bucket = 2.0;  // events popped per bucket visited (2: sorted buckets stay short)
}  // namespace

CalendarEventQueue::CalendarEventQueue(std::size_t capacity)
    : heap_(capacity),
      head_(bucket_count_for(capacity), -1),
      next_(capacity, -1),
      prev_(capacity, -1),
      where_(capacity, absent),
      time_(capacity, 0.0),
      mask_(static_cast<std::int64_t>(head_.size()) - 1) {}

std::size_t CalendarEventQueue::bytes() const {
  return sizeof(sorted_) + heap_.bytes() +
         (head_.capacity() + next_.capacity() + prev_.capacity() + where_.capacity()) * 4 + time_.capacity() * 8;
}

void CalendarEventQueue::clear() {
  heap_.clear();
  sorted_size_ = 0;
  std::fill(head_.begin(), head_.end(), -1);
  std::fill(where_.begin(), where_.end(), absent);
  overflow_ = -1;
  size_ = in_lists_ = overflow_size_ = 0;
  pops_ = advances_ = 0;
  width_known_ = false;
  current_ = window_end_ = unknown_bucket;
}

std::int64_t CalendarEventQueue::bucket_of_slow(double scaled) {
  if (scaled >= 1e18) return std::int64_t{1} << 60;
  const double q = std::floor(scaled);
  if (q <= -1e18) return -(std::int64_t{1} << 60);
  return static_cast<std::int64_t>(q);
}

void CalendarEventQueue::insert(std::int32_t id, double time) {
  time_[id] = time;
  const std::int64_t b = bucket_of(time);  // > unknown_bucket: overflow until the width is known
  if (b <= current_) {
    add_to_current(id, time);
    return;
  }
  std::int32_t* list = nullptr;
  if (b < window_end_) {
    const std::int32_t slot = static_cast<std::int32_t>(b & mask_);
    where_[id] = slot;
    list = &head_[slot];
    ++in_lists_;
  } else {
    where_[id] = in_overflow;
    list = &overflow_;
    ++overflow_size_;
  }
  prev_[id] = -1;
  next_[id] = *list;
  if (*list >= 0) prev_[*list] = id;
  *list = id;
}

void CalendarEventQueue::unlink(std::int32_t id) {
  const std::int32_t w = where_[id];
  std::int32_t& list = w == in_overflow ? overflow_ : head_[w];
  if (w == in_overflow)
    --overflow_size_;
  else
    --in_lists_;
  if (prev_[id] >= 0)
    next_[prev_[id]] = next_[id];
  else
    list = next_[id];
  if (next_[id] >= 0) prev_[next_[id]] = prev_[id];
  where_[id] = absent;
}

void CalendarEventQueue::move_sorted_to_heap() {
  for (std::size_t k = 0; k < sorted_size_; ++k) {
    heap_.set(sorted_[k].id, sorted_[k].time);
    where_[sorted_[k].id] = in_heap;
  }
  sorted_size_ = 0;
}

void CalendarEventQueue::remove_sorted(std::int32_t where) {
  const std::size_t k = sorted_index(where);
  where_[sorted_[k].id] = absent;
  for (std::size_t m = k + 1; m < sorted_size_; ++m) {
    sorted_[m - 1] = sorted_[m];
    where_[sorted_[m - 1].id] = sorted_code(m - 1);
  }
  --sorted_size_;
}

void CalendarEventQueue::set(std::int32_t id, double time) {
  const std::int32_t w = where_[id];
  if (w <= sorted_code(0)) {
    remove_sorted(w);
  } else if (w == in_heap) {
    if (bucket_of(time) <= current_) {
      heap_.set(id, time);
      time_[id] = time;
      return;
    }
    heap_.remove(id);
    where_[id] = absent;
  } else if (w != absent) {
    unlink(id);
  } else {
    ++size_;
  }
  insert(id, time);
}

void CalendarEventQueue::remove(std::int32_t id) {
  const std::int32_t w = where_[id];
  if (w == absent) return;
  if (w <= sorted_code(0)) {
    remove_sorted(w);
  } else if (w == in_heap) {
    heap_.remove(id);
    where_[id] = absent;
  } else {
    unlink(id);
  }
  --size_;
}

void CalendarEventQueue::redistribute_overflow() {
  std::int32_t id = overflow_;
  overflow_ = -1;
  overflow_size_ = 0;
  while (id >= 0) {
    const std::int32_t following = next_[id];
    insert(id, time_[id]);
    id = following;
  }
}

void CalendarEventQueue::advance() {
  assert(heap_.empty() && sorted_size_ == 0);
  while (heap_.empty() && sorted_size_ == 0) {
    if (in_lists_ == 0) {
      if (overflow_size_ == 0) return;
      // Jump over the empty buckets to the earliest overflow event.
      double earliest = std::numeric_limits<double>::infinity();
      for (std::int32_t id = overflow_; id >= 0; id = next_[id]) earliest = std::min(earliest, time_[id]);
      current_ = bucket_of(earliest);
      window_end_ = current_ + mask_ + 1;
      redistribute_overflow();
      ++advances_;
      continue;
    }
    ++current_;
    if (++advances_ > 64 * (pops_ + 1) && advances_ > adapt_interval) {
      // Mostly empty buckets: widen at once rather than waiting for the next pop-count check.
      rebuild(width_ * 64.0);
      continue;
    }
    if (current_ >= window_end_) {
      window_end_ = current_ + mask_ + 1;
      redistribute_overflow();  // lists are empty here: all their buckets are < current_
    }
    std::int32_t& list = head_[current_ & mask_];
    for (std::int32_t id = list; id >= 0; id = next_[id]) {
      add_to_current(id, time_[id]);
      --in_lists_;
    }
    list = -1;
  }
}

void CalendarEventQueue::rebuild(double new_width) {
  std::vector<std::int32_t> ids;
  ids.reserve(size_);
  double earliest = std::numeric_limits<double>::infinity();
  for (std::size_t id = 0; id < where_.size(); ++id) {
    if (where_[id] == absent) continue;
    ids.push_back(static_cast<std::int32_t>(id));
    earliest = std::min(earliest, time_[id]);
  }
  heap_.clear();
  sorted_size_ = 0;
  std::fill(head_.begin(), head_.end(), -1);
  overflow_ = -1;
  in_lists_ = overflow_size_ = 0;
  width_ = new_width > 0.0 && std::isfinite(new_width) ? new_width : 1.0;
  inverse_width_ = 1.0 / width_;
  width_known_ = true;
  current_ = ids.empty() ? 0 : bucket_of(earliest);
  window_end_ = current_ + mask_ + 1;
  for (const std::int32_t id : ids) insert(id, time_[id]);
  pops_ = advances_ = 0;
}

std::pair<double, std::int32_t> CalendarEventQueue::top_slow() {
  assert(size_ > 0);
  if (!width_known_) {
    // First use: a width giving about target_per_bucket events per bucket among the earliest
    // tenth of the events (robust to a few very late ones).
    std::vector<double> times;
    times.reserve(size_);
    for (std::int32_t id = overflow_; id >= 0; id = next_[id]) times.push_back(time_[id]);
    const std::size_t tenth = times.size() / 10;
    std::nth_element(times.begin(), times.begin() + tenth, times.end());
    const double lo = *std::min_element(times.begin(), times.begin() + tenth + 1);
    const double span = times[tenth] - lo;
    rebuild(span > 0.0 ? target_per_bucket * span / static_cast<double>(tenth + 1) : 1.0);
  }
  if (heap_.empty() && sorted_size_ == 0) advance();
  return top();
}

void CalendarEventQueue::adapt() {
  // Events per bucket visited; keep it within [1/4, 8] (target 2) by rescaling the width.
  const double ratio = static_cast<double>(pops_) / static_cast<double>(std::max<std::uint64_t>(advances_, 1));
  if (ratio > 4.0 * target_per_bucket || ratio < 0.125 * target_per_bucket)
    rebuild(width_ * std::clamp(target_per_bucket / ratio, 1.0 / 64.0, 64.0));
  else
    pops_ = advances_ = 0;
}

}  // namespace coldblast::md
