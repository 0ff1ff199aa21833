// A landscape's ground as a quadtree of chunks: what covers the area for an eye, how coarse each
// chunk's squares are, that no crack opens where two sizes meet, and that the mesh follows from
// the eye alone.
#include "pointgen/landscape/ground_chunks.hpp"
#include "pointgen/landscape/landscape_terrain.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace pointgen {
namespace {

LandscapeSpec hills(float size) {
  LandscapeSpec spec;
  spec.seed = 7;
  spec.size = glm::vec2(size, 0.75f * size);  // not square: the root reaches past the shorter side
  spec.terrain = {.relief = 200.0f, .feature = 1500.0f, .octaves = 6, .valley_depth = 60.0f, .valley_width = 800.0f,
                  .valley_meander = 500.0f, .valley_wavelength = 4000.0f};
  return spec;
}

constexpr GroundChunks::Settings settings{16, 2.0f, 2.0f};

struct Square {
  glm::vec2 min, max;
};

Square square_of(const LandscapeSpec& spec, const GroundChunks& ground, const GroundChunkKey& key) {
  const float side = ground.side(key.level);
  const glm::vec2 min = -0.5f * spec.size + side * glm::vec2(key.x, key.z);
  return {min, glm::min(min + side, 0.5f * spec.size)};
}

const glm::vec3 eyes[] = {{120.0f, 40.0f, -300.0f}, {-2990.0f, 15.0f, 2240.0f}, {0.0f, 900.0f, 0.0f}};

TEST(GroundChunks, CoverTheAreaOnceForAnyEye) {
  const LandscapeSpec spec = hills(6000.0f);
  const GroundChunks ground(spec, settings);
  for (const glm::vec3& eye : eyes) {
    const std::vector<GroundChunkKey> chunks = ground.chosen(eye);
    double area = 0.0;
    for (std::size_t a = 0; a < chunks.size(); ++a) {
      const Square s = square_of(spec, ground, chunks[a]);
      ASSERT_TRUE(s.min.x < s.max.x && s.min.y < s.max.y) << "a chunk wholly past the area";
      area += static_cast<double>(s.max.x - s.min.x) * (s.max.y - s.min.y);
      for (std::size_t b = a + 1; b < chunks.size(); ++b) {
        const Square t = square_of(spec, ground, chunks[b]);
        const bool overlap = s.min.x < t.max.x && t.min.x < s.max.x && s.min.y < t.max.y && t.min.y < s.max.y;
        ASSERT_FALSE(overlap) << a << " and " << b;
      }
    }
    EXPECT_NEAR(area, 6000.0 * 4500.0, 1e-3 * 6000.0 * 4500.0);
  }
}

// A chunk's squares are at most `step` metres or, seen from the eye, at most 1 / (2 × 16) of its
// distance: about 1.8° each, near or far, low or high.
TEST(GroundChunks, ASquareIsAsLargeToTheEyeNearAsFar) {
  const LandscapeSpec spec = hills(6000.0f);
  const GroundChunks ground(spec, settings);
  for (const glm::vec3& eye : eyes) {
    std::size_t finest = 0;
    for (const GroundChunkKey& key : ground.chosen(eye)) {
      const Square s = square_of(spec, ground, key);
      const glm::vec2 nearest = glm::clamp(glm::vec2(eye.x, eye.z), s.min, s.max);
      const float distance = glm::length(glm::vec3(nearest.x - eye.x, std::max(0.0f, eye.y - 100.0f), nearest.y - eye.z));
      const float square = ground.side(key.level) / 16.0f;
      EXPECT_LE(square, std::max(2.0f, distance / 32.0f) + 1e-3f) << key.level << " at " << distance << " m";
      finest += square <= 2.0f;
    }
    if (eye.y < 100.0f) {
      EXPECT_GT(finest, 0u) << "squares of 2 m around an eye near the ground";
    }
  }
}

// Along every edge where a chunk meets a larger one, each of its vertices lies on the larger
// chunk's edge: the height the larger chunk's two vertices around it give there, to a millimetre.
// The mesh is drawn by its chunks: an index range each, in order, inside its box.
TEST(GroundChunks, NoCrackOpensWhereChunksOfTwoSizesMeet) {
  const LandscapeSpec spec = hills(6000.0f);
  GroundChunks ground(spec, settings);
  const std::size_t per_chunk = 17 * 17;
  std::size_t checked = 0;
  for (const glm::vec3& eye : eyes) {
    const std::vector<GroundChunkKey> chunks = ground.chosen(eye);
    const GroundChunks::Chunked chunked = ground.mesh(chunks);
    const TriangleMesh& mesh = chunked.mesh;
    ASSERT_EQ(mesh.positions.size(), chunks.size() * per_chunk);
    // Each chunk's index range follows the one before and its box holds its triangles.
    ASSERT_EQ(chunked.chunks.size(), chunks.size());
    std::uint32_t next = 0;
    for (const PolygonPart& part : chunked.chunks) {
      ASSERT_EQ(part.first_index, next);
      next += part.index_count;
      for (std::uint32_t i = part.first_index; i < part.first_index + part.index_count; ++i) {
        const glm::vec3 p = mesh.positions[mesh.indices[i]];
        ASSERT_TRUE(glm::all(glm::lessThanEqual(glm::abs(p - part.center), part.half_size + 1e-3f)));
      }
    }
    ASSERT_EQ(next, mesh.indices.size());
    for (std::size_t a = 0; a < chunks.size(); ++a) {
      for (std::size_t b = 0; b < chunks.size(); ++b) {
        if (chunks[b].level >= chunks[a].level) continue;
        const Square coarse = square_of(spec, ground, chunks[b]);
        for (std::size_t v = a * per_chunk; v < (a + 1) * per_chunk; ++v) {
          const glm::vec3 p = mesh.positions[v];
          const bool on_x_edge = (p.x == coarse.min.x || p.x == coarse.max.x) && p.z >= coarse.min.y && p.z <= coarse.max.y;
          const bool on_z_edge = (p.z == coarse.min.y || p.z == coarse.max.y) && p.x >= coarse.min.x && p.x <= coarse.max.x;
          if (!on_x_edge && !on_z_edge) continue;
          // The coarse chunk's vertices on the same edge, nearest below and above p along it.
          const int along = on_x_edge ? 2 : 0;
          const int across = on_x_edge ? 0 : 2;
          const glm::vec3* below = nullptr;
          const glm::vec3* above = nullptr;
          for (std::size_t w = b * per_chunk; w < (b + 1) * per_chunk; ++w) {
            const glm::vec3& q = mesh.positions[w];
            if (q[across] != p[across]) continue;
            if (q[along] <= p[along] && (!below || q[along] > (*below)[along])) below = &q;
            if (q[along] >= p[along] && (!above || q[along] < (*above)[along])) above = &q;
          }
          ASSERT_TRUE(below && above);
          const float t = (*above)[along] == (*below)[along] ? 0.0f : (p[along] - (*below)[along]) / ((*above)[along] - (*below)[along]);
          EXPECT_NEAR(p.y, glm::mix(below->y, above->y, t), 1e-3f) << "at " << p.x << ", " << p.z;
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 100u);
}

TEST(GroundChunks, TheMeshFollowsFromTheEyeAloneWhateverWasMadeBefore) {
  const LandscapeSpec spec = hills(6000.0f);
  GroundChunks fresh(spec, settings), flown(spec, settings);
  for (const glm::vec3& eye : eyes) flown.mesh(flown.chosen(eye));
  flown.mesh(flown.chosen({130.0f, 40.0f, -280.0f}));
  const TriangleMesh a = fresh.mesh(fresh.chosen(eyes[0])).mesh, b = flown.mesh(flown.chosen(eyes[0])).mesh;
  ASSERT_EQ(a.positions.size(), b.positions.size());
  EXPECT_EQ(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::vec3)), 0);
  EXPECT_EQ(std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(glm::vec3)), 0);
  EXPECT_EQ(a.indices, b.indices);
}

// The chunks grow with the levels of the quadtree, the logarithm of the area: at most 64 a level
// (those within two sides of the eye, split, leave about 50 children), so a 100 km landscape
// takes about twice as many as a 2 km one (12 levels against 6), not 2,500 times.
TEST(GroundChunks, TheirNumberGrowsWithTheLogarithmOfTheArea) {
  std::vector<std::size_t> counts;
  for (const float size : {2000.0f, 20000.0f, 100000.0f}) {
    const LandscapeSpec spec = hills(size);
    const GroundChunks ground(spec, settings);
    const std::vector<GroundChunkKey> chunks = ground.chosen({10.0f, 30.0f, 10.0f});
    int levels = 0;
    for (const GroundChunkKey& key : chunks) levels = std::max(levels, key.level + 1);
    EXPECT_LE(chunks.size(), 64u * static_cast<std::size_t>(levels)) << size;
    counts.push_back(chunks.size());
  }
  EXPECT_LT(counts[2], 3 * counts[0]) << counts[0] << ", " << counts[1] << ", " << counts[2];
}

}  // namespace
}  // namespace pointgen
