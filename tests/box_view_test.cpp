// Boxes left out of a view (shadow::outside_view) against points of them the test projects itself:
// a box with a point inside the view is never left out, one wholly beyond a side of it is.
#include "pointgen/random.hpp"
#include "shadow/box.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace shadow {
namespace {

bool inside_clip_volume(const glm::mat4& view_projection, const glm::vec3& p) {
  const glm::vec4 clip = view_projection * glm::vec4(p, 1.0f);
  return clip.w > 0.0f && glm::all(glm::lessThanEqual(glm::abs(glm::vec3(clip)), glm::vec3(clip.w)));
}

TEST(BoxOutsideView, IsNeverABoxWithAPointInViewAndIsEveryBoxBeyondOneSide) {
  const glm::mat4 view_projection = glm::perspective(glm::radians(50.0f), 16.0f / 9.0f, 0.5f, 200.0f) *
                                    glm::lookAt(glm::vec3(3, 2, 1), glm::vec3(20, -1, -40), glm::vec3(0, 1, 0));
  pointgen::Random random(5);
  int seen = 0, beyond_a_side = 0, left_out = 0;
  for (int b = 0; b < 4000; ++b) {
    const glm::vec3 corner(random.uniform(-250.0f, 250.0f), random.uniform(-250.0f, 250.0f), random.uniform(-250.0f, 250.0f));
    const glm::vec3 size(random.uniform(0.1f, 60.0f), random.uniform(0.1f, 60.0f), random.uniform(0.1f, 60.0f));
    Box box;
    box.add(corner);
    box.add(corner + size);
    // Points of the box on a 9³ grid: one in view shows the box; all of them beyond one of the
    // six sides of the clip volume hide it.
    bool any_inside = false;
    glm::bvec3 below(true), above(true);
    for (int i = 0; i < 9 * 9 * 9; ++i) {
      const glm::vec3 f(static_cast<float>(i % 9) / 8.0f, static_cast<float>(i / 9 % 9) / 8.0f, static_cast<float>(i / 81) / 8.0f);
      const glm::vec3 p = corner + f * size;
      any_inside = any_inside || inside_clip_volume(view_projection, p);
      const glm::vec4 clip = view_projection * glm::vec4(p, 1.0f);
      below = below && glm::lessThan(glm::vec3(clip), glm::vec3(-clip.w));
      above = above && glm::greaterThan(glm::vec3(clip), glm::vec3(clip.w));
    }
    const bool beyond = glm::any(below) || glm::any(above);
    const bool out = outside_view(box, view_projection);
    seen += any_inside;
    beyond_a_side += beyond;
    left_out += out;
    EXPECT_FALSE(any_inside && out) << "box " << b << " has a point in view";
    EXPECT_FALSE(beyond && !out) << "box " << b << " lies beyond a side of the view";
  }
  EXPECT_GT(seen, 100);
  EXPECT_GT(beyond_a_side, 1000);
  EXPECT_TRUE(outside_view(Box{}, view_projection)) << "an empty box";
}

}  // namespace
}  // namespace shadow
