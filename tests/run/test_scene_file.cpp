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
