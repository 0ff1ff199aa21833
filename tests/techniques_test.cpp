// The table of shadow techniques says true things of its methods: names find their rows, the
// lights a map does not warp get the focused uniform map, and the lights it warps get views of
// its own.
#include "random_setups.hpp"
#include "shadow/techniques.hpp"
#include "shadow/uniform_map.hpp"

#include <gtest/gtest.h>

#include <set>

namespace shadow {
namespace {

constexpr float aspect = 16.0f / 9.0f;

bool same_views(const ShadowSetup& a, const ShadowSetup& b) {
  if (a.views.size() != b.views.size() || a.selection != b.selection) return false;
  for (std::size_t i = 0; i < a.views.size(); ++i) {
    if (a.views[i].view != b.views[i].view || a.views[i].projection != b.views[i].projection ||
        a.views[i].paraboloid.has_value() != b.views[i].paraboloid.has_value()) {
      return false;
    }
  }
  return true;
}

constexpr LightType light_types[] = {LightType::directional, LightType::point, LightType::spot};

TEST(ShadowTechniques, EveryNameFindsItsOwnRowAndNoOther) {
  std::set<std::string> names;
  for (const Technique& t : techniques()) {
    EXPECT_TRUE(names.insert(t.name).second) << t.name << " twice";
    ASSERT_NE(find_technique(t.name), nullptr) << t.name;
    EXPECT_EQ(find_technique(t.name)->method, t.method) << t.name;
    EXPECT_EQ(technique(t.method).name, t.name);
    EXPECT_FALSE(t.help.empty()) << t.name;
  }
  EXPECT_EQ(find_technique("shadow"), nullptr);
}

TEST(ShadowTechniques, ALightAMapDoesNotWarpGetsTheFocusedUniformMap) {
  pointgen::Random rng(17);
  int compared = 0;
  for (int i = 0; i < 300; ++i) {
    const LightType type = light_types[i % 3];
    const ShadowInputs inputs(random_camera(rng), aspect, random_light(rng, type), scene_box(), 1024);
    const ShadowSetup uniform = focused_uniform_map(inputs);
    for (const Technique& t : techniques()) {
      if (!t.setup || t.warps.has(type)) continue;
      EXPECT_TRUE(same_views(t.setup(inputs), uniform)) << t.name << ", configuration " << i;
      ++compared;
    }
  }
  EXPECT_GT(compared, 0);
}

// In most random configurations; the PSM hands about half of random point and spot lights to the
// uniform map (those among the receivers, which take the uniform cube: Stamminger and Drettakis
// 2002, Sect. 3.3), so a quarter is asked of every method.
TEST(ShadowTechniques, ALightAMapWarpsGetsViewsOfItsOwn) {
  for (const Technique& t : techniques()) {
    if (!t.setup || t.setup == focused_uniform_map) continue;  // the uniform map's views, its own
    for (LightType type : light_types) {
      if (!t.warps.has(type)) continue;
      pointgen::Random rng(23);
      int own = 0;
      for (int i = 0; i < 100; ++i) {
        const ShadowInputs inputs(random_camera(rng), aspect, random_light(rng, type), scene_box(), 1024);
        own += !same_views(t.setup(inputs), focused_uniform_map(inputs));
      }
      EXPECT_GT(own, 25) << t.name << " with light type " << static_cast<int>(type);
    }
  }
}

TEST(ShadowTechniques, AutoChoosesAmongTheMapsThatHandleTheLightThemselves) {
  for (LightType type : light_types) {
    const std::vector<Method> candidates = auto_candidates(type);
    EXPECT_GE(candidates.size(), 3u);
    for (Method m : candidates) {
      EXPECT_EQ(technique(m).lookup, Lookup::map);
      EXPECT_TRUE(technique(m).warps.has(type)) << technique(m).name;
      EXPECT_FALSE(technique(m).silhouette_map) << technique(m).name;  // the same aliasing as the map without
    }
  }
}

}  // namespace
}  // namespace shadow
