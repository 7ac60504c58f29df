// Scene files: TOML parsing with overrides, dotted keys, rejected keys and ranges, the round trip of
// the scene's TOML text, and the typed options --realizations and --seed.
#include <catch2/catch.hpp>
#include <optional>
#include <string>
#include <vector>

#include "md/blast_config.hpp"
#include "run/scene_file.hpp"

using namespace coldblast::run;
using coldblast::md::BlastConfig;
using coldblast::md::resolve_scene;

TEST_CASE("scene parsing: overrides, dotted keys, unknown keys and ranges", "[fast]") {
  const BlastConfig c = parse_scene(default_scene_toml(), {"E=20", "impurities.count=3", "name=x"});
  CHECK(c.E == 20.0);
  CHECK(c.impurities.count == 3);
  CHECK(c.name == "x");
  CHECK(c.d == 2);
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"bogus=1"}), Catch::Contains("unknown scene key bogus"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"impurities.colour=1"}), Catch::Contains("impurities.colour"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"n=-1"}), Catch::Contains("n = -1"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"E=0"}), Catch::Contains("E = 0"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"n=0.8"}), Catch::Contains("phi"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"d=3", "n=0.8"}), Catch::Contains("0.3841"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {R"(observables=["R_imp","magic"])"}), Catch::Contains("magic"));
  CHECK_THROWS_WITH(resolve_scene(parse_scene(default_scene_toml(), {"impurities.count=100000", "A_d=0.3"})),
                    Catch::Contains("impurities.count"));
  // The resolved TOML reads back to the same scene.
  const BlastConfig again = parse_scene(scene_toml(c));
  CHECK(scene_toml(again) == scene_toml(c));
}

TEST_CASE("scene [start]: read from a table or --set, written only when not the kick", "[fast]") {
  const std::string text = default_scene_toml() + "\n[start]\nkind = \"hotspot\"\nr0 = 6.5\n";
  const BlastConfig hot = parse_scene(text);
  CHECK(hot.start.kind == coldblast::md::StartKind::hotspot);
  CHECK(hot.start.r0 == 6.5);
  const BlastConfig single = parse_scene(default_scene_toml(), {"start.kind=single"});
  CHECK(single.start.kind == coldblast::md::StartKind::single);
  // Round trips: the hot spot's text names its start and reads back to the same scene; a kick
  // scene's text is what it was before starts existed (no [start]: merges and resumes compare it).
  CHECK(scene_toml(parse_scene(scene_toml(hot))) == scene_toml(hot));
  CHECK(scene_toml(hot).find("[start]\nkind = \"hotspot\"\nr0 = 6.5\n") != std::string::npos);
  CHECK(scene_toml(parse_scene(scene_toml(single))) == scene_toml(single));
  const BlastConfig kick = parse_scene(default_scene_toml(), {"start.kind=kick"});
  CHECK(scene_toml(kick) == scene_toml(parse_scene(default_scene_toml())));
  CHECK(scene_toml(kick).find("start") == std::string::npos);
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"start.colour=1"}),
                    Catch::Contains("unknown scene key start.colour (allowed: kind, r0)"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"start=3"}), Catch::Contains("start must be a table"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"start.kind=3"}),
                    Catch::Contains("start.kind must be a string"));
}
