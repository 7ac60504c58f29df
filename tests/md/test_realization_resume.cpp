// A realization saved mid-run (md::InFlight: the engine, the observers, what was recorded) and
// resumed from any of its saves ends bit for bit as the realization never stopped: in 2D and 3D,
// with both calendars, a region that grows, big impurities, impurity recollisions off, snapshots
// and paths. A state that is not the realization's is refused, saying why.
#include <catch2/catch.hpp>
#include <csignal>
#include <string>
#include <vector>

#include "common/interrupt.hpp"
#include "md/observers.hpp"
#include "md/realization.hpp"
#include "run/ensemble.hpp"
#include "run/scene_file.hpp"

using namespace coldblast::md;
using coldblast::run::default_scene_toml;
using coldblast::run::parse_scene;

namespace {
ResolvedScene scene_with(const std::vector<std::string>& keys) {
  return coldblast::run::resolve_blast_scene(parse_scene(default_scene_toml(), keys));
}

/// Every field of two outputs equal, bit for bit.
void require_same(const RealizationOutput& a, const RealizationOutput& b) {
  REQUIRE(a.record.size() == b.record.size());
  for (std::size_t k = 0; k < a.record.size(); ++k) {
    INFO("record entry " << k);
    REQUIRE(a.record[k] == b.record[k]);
  }
  REQUIRE(a.collisions == b.collisions);
  REQUIRE(a.energy_error == b.energy_error);
  REQUIRE(a.growths == b.growths);
  REQUIRE(a.region_radius == b.region_radius);
  REQUIRE(a.particles == b.particles);
  REQUIRE(a.snapshots.size() == b.snapshots.size());
  for (std::size_t s = 0; s < a.snapshots.size(); ++s) {
    REQUIRE(a.snapshots[s].t == b.snapshots[s].t);
    REQUIRE(a.snapshots[s].id == b.snapshots[s].id);
    REQUIRE(a.snapshots[s].position == b.snapshots[s].position);
    REQUIRE(a.snapshots[s].velocity == b.snapshots[s].velocity);
    REQUIRE(a.snapshots[s].collisions == b.snapshots[s].collisions);
    REQUIRE(a.snapshots[s].moving == b.snapshots[s].moving);
  }
  REQUIRE(a.paths.size() == b.paths.size());
  for (std::size_t p = 0; p < a.paths.size(); ++p) {
    REQUIRE(a.paths[p].id == b.paths[p].id);
    REQUIRE(a.paths[p].t == b.paths[p].t);
    REQUIRE(a.paths[p].position == b.paths[p].position);
  }
}

/// The realization run in slices of `slice` events with a save after every `every`-th slice: its saves.
std::vector<std::string> saves_of(const ResolvedScene& scene, const ObservableLayout& layout, long long index,
                                  const RealizationExtras& extras, const RealizationOutput& plain, std::uint64_t slice,
                                  int every = 1) {
  std::vector<std::string> saves;
  InFlight hooks;
  hooks.slice_events = slice;
  hooks.due = [every, polls = 0]() mutable { return ++polls % every == 0; };
  hooks.save = [&saves](std::string&& bytes) { saves.push_back(std::move(bytes)); };
  const RealizationOutput sliced = run_realization(scene, layout, index, extras, {}, &hooks);
  require_same(sliced, plain);  // slicing alone changes nothing
  return saves;
}

RealizationOutput resumed_from(const ResolvedScene& scene, const ObservableLayout& layout, long long index,
                               const RealizationExtras& extras, const std::string& bytes) {
  InFlight hooks;
  hooks.resume = bytes;
  hooks.save = [](std::string&&) {};
  return run_realization(scene, layout, index, extras, {}, &hooks);
}

/// The first realization (index < 20) of `scene` whose region grows, or -1.
long long first_growing(const ResolvedScene& scene, const ObservableLayout& layout) {
  for (long long index = 0; index < 20; ++index)
    if (run_realization(scene, layout, index).growths > 0) return index;
  return -1;
}
}  // namespace

TEST_CASE("a realization resumed from any mid-run save ends as the uninterrupted one, bit for bit", "[fast]") {
  const std::string observables =
      R"(observables=["R_imp","V_imp","C_imp","u_imp","u_flow","n0","T0","R","C_re","dE_first","dE_re","profiles","p_imp"])";
  struct Case {
    std::string name;
    std::vector<std::string> keys;
    bool growing;
  };
  const Case c =
      GENERATE_COPY(Case{"2D, calendar", {"t_max=120", observables}, false},
                    Case{"2D, heap", {"t_max=120", "queue=\"heap\"", observables}, false},
                    Case{"2D, big impurities", {"t_max=120", "impurities.radius=1.5", observables}, false},
                    Case{"2D, recollisions off", {"t_max=120", "impurities.recollide=false", observables}, false},
                    Case{"3D lone impurity, region grows",
                         {"d=3", "impurities.count=1", "t_max=20", "A_d=0.3", "box_margin=3", observables},
                         true});
  INFO(c.name);
  const ResolvedScene scene = scene_with(c.keys);
  const ObservableLayout layout(scene);
  const long long index = c.growing ? first_growing(scene, layout) : 3;
  REQUIRE(index >= 0);
  RealizationExtras extras;
  extras.snapshot_times = {0.25 * scene.config.t_max, 0.5 * scene.config.t_max};
  extras.paths = true;
  const RealizationOutput plain = run_realization(scene, layout, index, extras);
  if (c.growing) REQUIRE(plain.growths > 0);
  REQUIRE(plain.energy_error < 1e-12);

  INFO("collisions " << plain.collisions << ", particles " << plain.particles << ", stops " << scene.times.size());
  // Slices of a twentieth of the collisions' number of events, a save after each.
  const std::vector<std::string> saves = saves_of(scene, layout, index, extras, plain, plain.collisions / 20);
  REQUIRE(saves.size() >= 8);
  // A grown region's grid is wider: its saves are larger (the saved cell lists), so some of the
  // saves resumed below hold a grown region.
  if (c.growing) CHECK(saves.back().size() > 2 * saves.front().size());
  // What a resumed realization reports as done before it (not run in this process: the rate of
  // summary.json leaves it out) grows from save to save, within the whole realization's count.
  CHECK(plain.resumed_collisions == 0);
  std::uint64_t before = 0;
  for (std::size_t k = 0; k < saves.size(); k += saves.size() / 8) {
    INFO("resumed from save " << k << " of " << saves.size());
    const RealizationOutput resumed = resumed_from(scene, layout, index, extras, saves[k]);
    require_same(resumed, plain);
    CHECK(resumed.resumed_collisions > before);
    CHECK(resumed.resumed_collisions <= plain.collisions);  // = when the save came after the last one
    before = resumed.resumed_collisions;
  }
  require_same(resumed_from(scene, layout, index, extras, saves.back()), plain);
}

TEST_CASE("a stop requested mid-realization saves its state and ends it, and the state resumes it", "[fast]") {
  const ResolvedScene scene = scene_with({"t_max=120"});
  const ObservableLayout layout(scene);
  const RealizationOutput plain = run_realization(scene, layout, 5);
  REQUIRE(plain.collisions > 1000);
  std::string saved;
  int polls = 0, saves = 0;
  InFlight hooks;
  hooks.slice_events = 100;
  hooks.due = [&polls] {
    if (++polls == 3) coldblast::common::request_stop(SIGTERM);  // as the signal handler does
    return false;                                                // no periodic saves: only the stop's
  };
  hooks.save = [&](std::string&& bytes) {
    saved = std::move(bytes);
    ++saves;
  };
  CHECK_THROWS_AS(run_realization(scene, layout, 5, {}, {}, &hooks), coldblast::common::Interrupted);
  coldblast::common::clear_stop();
  CHECK(polls == 3);
  CHECK(saves == 1);
  const RealizationOutput resumed = resumed_from(scene, layout, 5, {}, saved);
  require_same(resumed, plain);
  // The state is that after three slices of 100 events: at most 300 of them collisions, done before.
  CHECK(resumed.resumed_collisions > 0);
  CHECK(resumed.resumed_collisions <= 300);
}

TEST_CASE("a saved state that is not the realization's is refused, saying why", "[fast]") {
  const ResolvedScene scene = scene_with({"t_max=60"});
  const ObservableLayout layout(scene);
  const RealizationOutput plain = run_realization(scene, layout, 0);
  const std::vector<std::string> saves = saves_of(scene, layout, 0, {}, plain, 200);
  REQUIRE(!saves.empty());
  const std::string& good = saves.front();
  using Catch::Matchers::Contains;

  std::string altered = good;
  altered[altered.size() / 2] ^= 1;
  CHECK_THROWS_WITH(resumed_from(scene, layout, 0, {}, altered), Contains("checksum does not match"));
  CHECK_THROWS_WITH(resumed_from(scene, layout, 0, {}, good.substr(0, good.size() - 100)),
                    Contains("checksum does not match"));
  CHECK_THROWS_WITH(resumed_from(scene, layout, 0, {}, "abc"), Contains("truncated"));
  CHECK_THROWS_WITH(resumed_from(scene, layout, 1, {}, good), Contains("of another realization"));
  const ResolvedScene other_seed = scene_with({"t_max=60", "seed=2"});
  CHECK_THROWS_WITH(resumed_from(other_seed, ObservableLayout(other_seed), 0, {}, good),
                    Contains("of another realization"));
  const ResolvedScene heap = scene_with({"t_max=60", "queue=\"heap\""});
  CHECK_THROWS_WITH(resumed_from(heap, ObservableLayout(heap), 0, {}, good), Contains("calendar"));
}
