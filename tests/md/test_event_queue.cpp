// Event calendars against a brute-force next-event search on random operation sequences
// (DynamO's sorter-versus-sort test): the heap and the bucketed calendar must pop exactly the
// (time, id) minimum at every step, through inserts, moves earlier and later, removals and pops;
// their prefetch hint, when given, must be the second event.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>

#include "md/event_queue.hpp"

using namespace coldblast::md;

namespace {
std::pair<double, std::int32_t> brute_force_min(const std::map<std::int32_t, double>& events) {
  std::pair<double, std::int32_t> best{INFINITY, -1};
  for (const auto& [id, t] : events)
    if (t < best.first || (t == best.first && id < best.second)) best = {t, id};
  return best;
}

// Returns how many times the queue gave a prefetch hint (each was checked).
template <class Queue>
int compare_with_brute_force(std::uint64_t seed, double spread, int ties) {
  INFO("seed " << seed << ", spread " << spread);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const std::int32_t capacity = 500;
  Queue queue(capacity);
  std::map<std::int32_t, double> events;
  double now = 0.0;
  int hints = 0;
  for (int step = 0; step < 60000; ++step) {
    const double r = uniform(rng);
    const std::int32_t id = static_cast<std::int32_t>(rng() % capacity);
    // Future times: mostly near, sometimes very far (exercises the overflow list).
    double t = now + spread * (uniform(rng) < 0.05 ? 1000.0 * uniform(rng) : uniform(rng));
    if (ties) t = now + std::floor(t - now);  // many equal times
    if (r < 0.55) {
      queue.set(id, t);
      events[id] = t;
    } else if (r < 0.7) {
      queue.remove(id);
      events.erase(id);
    } else if (!events.empty()) {
      const auto expected = brute_force_min(events);
      REQUIRE(queue.size() == events.size());
      const auto got = queue.top();
      REQUIRE(got.first == expected.first);
      REQUIRE(got.second == expected.second);
      // The prefetch hint, when the queue gives one, is the second event in (time, id) order.
      if (const std::int32_t hint = queue.second_hint(); hint >= 0) {
        std::map<std::int32_t, double> rest = events;
        rest.erase(expected.second);
        REQUIRE(hint == brute_force_min(rest).second);
        ++hints;
      }
      queue.pop();
      events.erase(expected.second);
      now = expected.first;
    }
    REQUIRE(queue.contains(id) == (events.count(id) == 1));
  }
  while (!events.empty()) {
    const auto expected = brute_force_min(events);
    REQUIRE(queue.top() == expected);
    queue.pop();
    events.erase(expected.second);
  }
  REQUIRE(queue.empty());
  return hints;
}
}  // namespace

TEST_CASE("HeapEventQueue matches a brute-force minimum search", "[fast]") {
  int hints = 0;
  for (std::uint64_t seed : {1u, 2u, 3u}) hints += compare_with_brute_force<HeapEventQueue>(seed, 1.0, 0);
  hints += compare_with_brute_force<HeapEventQueue>(4, 10.0, 1);
  REQUIRE(hints > 10000);  // the heap always knows its second event
}

TEST_CASE("CalendarEventQueue matches a brute-force minimum search", "[fast]") {
  int hints = 0;
  for (std::uint64_t seed : {1u, 2u, 3u}) hints += compare_with_brute_force<CalendarEventQueue>(seed, 1.0, 0);
  hints += compare_with_brute_force<CalendarEventQueue>(5, 1e-6, 0);  // tiny spread: width must shrink
  hints += compare_with_brute_force<CalendarEventQueue>(6, 1e6, 0);   // huge spread: width must grow
  hints += compare_with_brute_force<CalendarEventQueue>(4, 10.0, 1);
  INFO("calendar hints checked: " << hints);
  REQUIRE(hints > 20);  // only when the current bucket holds two events or more
}
