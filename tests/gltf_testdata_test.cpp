// Real glTF files from outside the project (../shared/testdata/gltf, see its README): the good ones
// load, the hostile ones fail with FileError, none crashes or reads out of bounds.
//
// One exception to that README: regression/zero-sized-bin-chunk-issue-440.glb is listed there as
// broken, but its bytes are a valid GLB holding one triangle (a 44-byte BIN chunk after padded
// JSON), and tinygltf's own regression test for issue 440 requires it to load. It loads here, and
// the test checks the triangle.
#include "pointgen/file_error.hpp"
#include "pointgen/mesh_file.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace ecoview::test {
namespace {

std::optional<std::string> read_disk(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class SharedGltf : public testing::TestWithParam<std::string> {
 protected:
  std::string path() const { return (shared_testdata_dir() / "gltf" / GetParam()).string(); }
  void SetUp() override {
    if (!std::filesystem::exists(shared_testdata_dir())) {
      GTEST_SKIP() << shared_testdata_dir() << " is absent (it is beside the repository on development machines only)";
    }
  }
};

class LoadableGltf : public SharedGltf {};
class HostileGltf : public SharedGltf {};

TEST_P(LoadableGltf, LoadsWithTriangles) {
  const pointgen::TriangleMesh mesh = pointgen::load_mesh_file(path(), read_disk);
  EXPECT_GT(mesh.triangle_count(), 0u);
  EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
}

TEST_P(HostileGltf, FailsWithFileErrorNamingTheFile) {
  try {
    pointgen::load_mesh_file(path(), read_disk);
    ADD_FAILURE() << "no error";
  } catch (const pointgen::FileError& e) {
    EXPECT_NE(std::string(e.what()).find(GetParam()), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Testdata, LoadableGltf,
                         testing::Values("Cube/Cube.gltf", "Cube-texture-ext/Cube-textransform.gltf",
                                         "CubeImageUriSpaces/CubeImageUriSpaces.gltf",
                                         "CubeImageUriSpaces/CubeImageUriMultipleSpaces.gltf", "box01.glb",
                                         "SparseMorphTargets-issue280/singleBlendshapeCube_sparse.glb",
                                         "Extensions-issue97/test.gltf",
                                         "Extensions-overwrite-issue261/issue-261.gltf",
                                         "regression/unassigned-skeleton.gltf"));

INSTANTIATE_TEST_SUITE_P(Testdata, HostileGltf,
                         testing::Values("BoundsChecking/integer-out-of-bounds.gltf",
                                         "BoundsChecking/invalid-buffer-index.gltf",
                                         "BoundsChecking/invalid-buffer-view-index.gltf",
                                         "BoundsChecking/invalid-primitive-indices.gltf"));

TEST(SharedGltfRegression, Issue440GlbLoadsItsOneTriangle) {
  const auto path = shared_testdata_dir() / "gltf" / "regression" / "zero-sized-bin-chunk-issue-440.glb";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
  const pointgen::TriangleMesh mesh = pointgen::load_mesh_file(path.string(), read_disk);
  ASSERT_EQ(mesh.triangle_count(), 1u);
  EXPECT_EQ(mesh.positions[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(mesh.positions[2], glm::vec3(0, 1, 0));
}

}  // namespace
}  // namespace ecoview::test
