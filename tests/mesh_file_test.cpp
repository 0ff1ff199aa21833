// Mesh files through OpenMesh: the three formats load the same tetrahedron; counts that cannot be
// right are refused before OpenMesh reserves memory for them.
#include "pointgen/file_error.hpp"
#include "pointgen/input_file.hpp"
#include "pointgen/json_nesting.hpp"
#include "pointgen/mesh_file.hpp"
#include "pointgen/obj_references.hpp"
#include "test_support.hpp"

#include <sys/resource.h>
#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

namespace {

pointgen::TriangleMesh load(const std::string& name, const std::string& bytes) {
  return pointgen::load_mesh_file(name, [&](const std::string& path) -> std::optional<std::string> {
    if (path == name) return bytes;
    return std::nullopt;
  });
}

const char* off_tetrahedron = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const char* ply_tetrahedron =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const char* obj_tetrahedron = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

TEST(MeshFile, EveryOpenMeshFormatLoadsTheTetrahedron) {
  for (const auto& [name, bytes] : {std::pair{"t.off", off_tetrahedron}, {"t.ply", ply_tetrahedron}, {"t.obj", obj_tetrahedron}}) {
    const pointgen::TriangleMesh mesh = load(name, bytes);
    EXPECT_EQ(mesh.triangle_count(), 4u) << name;
    EXPECT_EQ(mesh.bounds().max, glm::vec3(1.0f)) << name;
    // Normals point out of the tetrahedron: away from its centre.
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      EXPECT_GT(glm::dot(mesh.normals[i], mesh.positions[i] - glm::vec3(0.25f)), 0.0f) << name;
    }
  }
}

// A triangle's three corners, before its face.
const std::string ply_triangle_corners =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
const std::string obj_triangle_corners = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

void expect_refused(const std::string& name, const std::string& bytes, const char* part) {
  try {
    load(name, bytes);
    ADD_FAILURE() << name << " loaded";
  } catch (const pointgen::FileError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(MeshFile, ImpossibleCountsAreRefusedBeforeReading) {
  expect_refused("a.off", "OFF\n99999999999 1 0\n0 0 0\n", "declares");
  expect_refused("b.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n41113238394 0 1 2\n", "face 0 declares");
  expect_refused("c.off", "OFF BINARY\n", "binary OFF");
  expect_refused("d.ply", "ply\nformat ascii 1.0\nelement vertex 9999999999\nproperty float x\nend_header\n", "vertex");
  expect_refused("e.ply", ply_triangle_corners + "4000000000 0 1 2\n", "declares 4000000000");
  expect_refused("f.ply",
                 "ply\nformat binary_little_endian 1.0\nelement face 1\nproperty list int int vertex_indices\nend_header\n",
                 "list counts of type 'int'");
}

// OpenMesh's readers drop a face that refers to a vertex the file lacks, and a vertex they cannot
// parse: both are corrupt files, not smaller meshes.
TEST(MeshFile, ReferencesToMissingOrUnreadableVerticesAreRefused) {
  expect_refused("a.obj", obj_triangle_corners + "f 1 2 3\nf 1 2 99\n", "line 5: a face refers to vertex '99'");
  expect_refused("b.obj", obj_triangle_corners + "f 0 1 2\n", "vertex '0'");
  expect_refused("c.obj", obj_triangle_corners + "f -4 -2 -1\n", "vertex '-4'");
  expect_refused("d.obj", obj_triangle_corners + "vn 0 0 1\nf 1//1 2//1 3//2\n", "normal '2'");
  expect_refused("e.obj", obj_triangle_corners + "vt 0 0\nf 1/1 2/3 3/1\n", "texture coordinate '3'");
  expect_refused("f.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: a vertex that is not three finite numbers");
  expect_refused("g.obj", "v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1");
  expect_refused("h.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "refers to a vertex the file does not have");
  expect_refused("i.off", "OFF\n3 1 0\n0 inf 0\n1 0 0\n0 1 0\n3 0 1 2\n", "vertex 0 is not three finite numbers");
  expect_refused("j.ply", ply_triangle_corners + "3 0 1 2000000000\n", "refers to a vertex the file does not have");
  expect_refused("k.obj", "f -1 -2 -3\n" + obj_triangle_corners, "vertex '-1'");  // relative to none before it
  // Relative references, v//vn and v/vt forms, a comment after a face, and a face before the
  // vertices it numbers (OpenMesh reads them all first) load.
  EXPECT_EQ(load("l.obj", obj_triangle_corners + "vn 0 0 1\nvt 0 0\nf -3/1/1 -2/1/1 -1//1 # a comment\n").triangle_count(), 1u);
  EXPECT_EQ(load("m.obj", "f 1 2 3\n" + obj_triangle_corners).triangle_count(), 1u);
}

// OpenMesh spins forever on a property without a name and prints its own line for an unknown type:
// the header is checked first.
TEST(MeshFile, MalformedPlyPropertiesAreRefusedAtOnce) {
  const std::string start = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n";
  const std::string faces = "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_refused("a.ply", start + "property float z\nelement face 1\nproperty list uchar int\nend_header\n", "'property list uchar int'");
  expect_refused("b.ply", start + "property float z\nelement face 1\nproperty list uchar\nend_header\n", "'property list uchar'");
  expect_refused("c.ply", start + "property fdoat z\n" + faces, "'property fdoat z'");
  expect_refused("d.ply", start + "property float\n" + faces, "'property float'");
  expect_refused("e.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n", "before any element");
  EXPECT_EQ(load("f.ply", start + "property float32 z\n" + faces).triangle_count(), 1u);
}

// OpenMesh reserves for the counts an empty file never gave (tens of GB).
TEST(MeshFile, EmptyFilesAreRefusedAsEmpty) {
  for (const char* name : {"a.off", "b.ply", "c.obj", "d.gltf"}) {
    expect_refused(name, "", "is empty");
    expect_refused(name, " \n\r\n\t", "is empty");
  }
  expect_refused("e.off", "# only a comment\n", "is empty");
}

TEST(MeshFile, UnknownFormatAndMissingFileAreNamed) {
  expect_refused("model.fbx", "x", "unknown mesh format");
  try {
    pointgen::load_mesh_file("gone.obj", [](const std::string&) { return std::nullopt; });
    ADD_FAILURE();
  } catch (const pointgen::FileError& e) {
    EXPECT_EQ(std::string(e.what()), "gone.obj: no such file");
  }
}

// A one-triangle glTF with its buffer in tri.bin; `accessor_offset` and `nodes` vary per test.
std::string triangle_gltf(const std::string& accessor_offset, const std::string& nodes, const std::string& scene_nodes) {
  return R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "tri.bin", "byteLength": 36}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "byteOffset": )" + accessor_offset + R"(, "componentType": 5126, "count": 3, "type": "VEC3"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "nodes": )" + nodes + R"(, "scenes": [{"nodes": )" + scene_nodes + R"(}], "scene": 0})";
}

pointgen::TriangleMesh load_gltf_text(const std::string& gltf) {
  const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::string bin(reinterpret_cast<const char*>(corners), sizeof corners);
  return pointgen::load_mesh_file("t.gltf", [&](const std::string& path) -> std::optional<std::string> {
    if (path == "t.gltf") return gltf;
    if (path == "tri.bin") return bin;
    return std::nullopt;
  });
}

TEST(GltfFile, ATriangleLoadsAndHostileOffsetsAndNodeGraphsAreRefused) {
  EXPECT_EQ(load_gltf_text(triangle_gltf("0", R"([{"mesh": 0}])", "[0]")).triangle_count(), 1u);
  // An offset that wraps around when added to the others.
  EXPECT_THROW(load_gltf_text(triangle_gltf("18446744073709551612", R"([{"mesh": 0}])", "[0]")), pointgen::FileError);
  EXPECT_THROW(load_gltf_text(triangle_gltf("4", R"([{"mesh": 0}])", "[0]")), pointgen::FileError);
  // A child listed twice (exponential growth when nested) and a cycle.
  EXPECT_THROW(load_gltf_text(triangle_gltf("0", R"([{"children": [1, 1]}, {"mesh": 0}])", "[0]")), pointgen::FileError);
  EXPECT_THROW(load_gltf_text(triangle_gltf("0", R"([{"mesh": 0, "children": [1]}, {"children": [0]}])", "[0]")),
               pointgen::FileError);
}

// An accessor declaring 2^28 positions (3 GiB of floats) over a 36-byte buffer: the load must fail
// on the ranges with no more memory than the file needs. In a child process whose address space is
// capped 512 MiB above what it holds at the start: 0 when it fails with `part`.
int load_within_memory(const std::string& gltf, const char* part) {
  std::ifstream status("/proc/self/status");
  std::string key;
  long vm_kib = 0;
  while (status >> key && key != "VmSize:") {}
  status >> vm_kib;
  const rlim_t cap = static_cast<rlim_t>(vm_kib + 512 * 1024) * 1024;
  const rlimit limit{cap, cap};
  setrlimit(RLIMIT_AS, &limit);
  try {
    load_gltf_text(gltf);
  } catch (const pointgen::FileError& e) {
    return std::string(e.what()).find(part) != std::string::npos ? 0 : 3;
  } catch (const std::bad_alloc&) {
    return 4;
  }
  return 5;
}

void expect_refused_within_memory(const std::string& gltf, const char* part) {
  EXPECT_EXIT(std::_Exit(load_within_memory(gltf, part)), testing::ExitedWithCode(0), "") << gltf;
}

// `text` with its one `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(GltfFile, DeclaredCountsAreCheckedAgainstTheBufferBeforeAnythingIsAllocated) {
  const std::string triangle = triangle_gltf("0", R"([{"mesh": 0}])", "[0]");
  const std::string huge = "268435456";
  expect_refused_within_memory(replaced(triangle, R"("count": 3)", R"("count": )" + huge), "reads past the end of its buffer");

  const std::string indices = replaced(
      replaced(triangle, R"("type": "VEC3"}])",
               R"("type": "VEC3"}, {"bufferView": 0, "componentType": 5125, "count": )" + huge + R"(, "type": "SCALAR"}])"),
      R"({"POSITION": 0})", R"({"POSITION": 0}, "indices": 1)");
  expect_refused_within_memory(indices, "reads past the end of its buffer");

  // Without a buffer view: zeros but for a few sparse values, more of them than the file has bytes.
  const std::string sparse = replaced(triangle, R"("bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 3)",
                                      R"("componentType": 5126, "count": )" + huge +
                                          R"(, "sparse": {"count": 1, "indices": {"bufferView": 0, "componentType": 5125}, "values": {"bufferView": 0}})");
  expect_refused_within_memory(sparse, "declares more elements than the file has bytes");
}

// What load_mesh_file says of a mesh on disk, read as a scene reads it; "" when it loads.
std::string disk_failure(const std::filesystem::path& mesh) {
  try {
    pointgen::load_mesh_file(mesh.string(), [](const std::string& path) { return pointgen::read_input_file(path); });
  } catch (const pointgen::FileError& e) {
    return e.what();
  }
  return "";
}

// What read_input_file says of a path; "" when it reads it.
std::string failure_of(const std::filesystem::path& path) {
  try {
    pointgen::read_input_file(path);
  } catch (const pointgen::FileError& e) {
    return e.what();
  }
  return "";
}

TEST(InputFile, OnlyARegularFileWithinTheBoundIsReadAndAnythingElseIsRefusedByName) {
  const ecoview::test::TempDir dir;
  ecoview::test::write_text(dir / "a.obj", obj_tetrahedron);
  EXPECT_EQ(pointgen::read_input_file(dir / "a.obj"), std::optional<std::string>(obj_tetrahedron));
  EXPECT_EQ(pointgen::read_input_file(dir / "gone.obj"), std::nullopt);
  EXPECT_EQ(failure_of(dir.path()), dir.path().string() + ": not a regular file (a folder)");
  EXPECT_EQ(failure_of("/dev/zero"), "/dev/zero: not a regular file (a character device)");
  // A pipe nobody writes to: opening it to read would wait for a writer.
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  EXPECT_EQ(failure_of(dir / "pipe"), (dir / "pipe").string() + ": not a regular file (a pipe)");
  // A sparse file one byte past the bound: refused by its size, before anything is allocated.
  ecoview::test::write_text(dir / "huge.bin", "");
  std::filesystem::resize_file(dir / "huge.bin", pointgen::max_input_file_bytes + 1);
  EXPECT_NE(failure_of(dir / "huge.bin").find("huge.bin: is 2147483648 bytes, more than the 2 GiB"), std::string::npos);
}

TEST(MeshFile, AMaterialLibraryThatIsNotARegularFileIsRefusedNamingBothFiles) {
  const ecoview::test::TempDir dir;
  // OpenMesh would read /dev/zero without end, as one endless line.
  ecoview::test::write_text(dir / "lamp.obj", std::string("mtllib /dev/zero\n") + obj_tetrahedron);
  EXPECT_EQ(disk_failure(dir / "lamp.obj"),
            (dir / "lamp.obj").string() + ": line 1: mtllib: /dev/zero: not a regular file (a character device)");
  std::filesystem::create_directory(dir / "shades.mtl");
  ecoview::test::write_text(dir / "shade.obj", std::string(obj_tetrahedron) + "  mtllib  shades.mtl\n");
  EXPECT_EQ(disk_failure(dir / "shade.obj"),
            (dir / "shade.obj").string() + ": line 9: mtllib: " + (dir / "shades.mtl").string() + ": not a regular file (a folder)");
}

TEST(MeshFile, AMissingMaterialLibraryIsNotedAsIgnoredAndTheMeshLoads) {
  std::vector<std::string> notes;
  const pointgen::TriangleMesh mesh = pointgen::load_mesh_file(
      "t.obj", [&](const std::string& path) -> std::optional<std::string> {
        if (path == "t.obj") return std::string("mtllib t.mtl\n") + obj_tetrahedron;
        return std::nullopt;
      },
      [&](const std::string& line) { notes.push_back(line); });
  EXPECT_EQ(mesh.triangle_count(), 4u);
  EXPECT_EQ(notes, std::vector<std::string>{"t.obj: ignored: material libraries (OBJ materials are not used; vertex colours are)"});
}

TEST(MeshFile, AMaterialLibraryNamedManyTimesIsReadOnce) {
  std::map<std::string, int> reads;
  std::string obj;
  for (int i = 0; i < 1000; ++i) obj += "mtllib big.mtl other.mtl\n";
  pointgen::load_mesh_file(
      "t.obj",
      [&](const std::string& path) -> std::optional<std::string> {
        ++reads[path];
        if (path == "t.obj") return obj + obj_tetrahedron;
        return std::string("newmtl a\n");
      },
      {});
  EXPECT_EQ(reads, (std::map<std::string, int>{{"t.obj", 1}, {"big.mtl", 1}, {"other.mtl", 1}}));
}

TEST(MeshFile, OpenMeshIsGivenNoMaterialLibraryToOpen) {
  const std::string hidden = pointgen::without_material_libraries("v 0 0 0\n mtllib /dev/zero\nmtllibs x\n\tmtllib\n# mtllib\nmtllib");
  EXPECT_EQ(hidden, "v 0 0 0\n #tllib /dev/zero\nmtllibs x\n\t#tllib\n# mtllib\n#tllib");
}

// A glTF in `dir` whose one buffer is `buffer_uri` and one image `image_uri`, each on disk.
std::string gltf_referring_to(const std::string& buffer_uri, const std::string& image_uri) {
  return R"({"asset": {"version": "2.0"}, "buffers": [{"uri": ")" + buffer_uri + R"(", "byteLength": 36}],
    "images": [{"uri": ")" + image_uri + R"("}]})";
}

TEST(GltfFile, ABufferOrImageThatIsNotARegularFileIsRefusedNamingBothFiles) {
  const ecoview::test::TempDir dir;
  ecoview::test::write_text(dir / "tri.bin", std::string(36, '\0'));
  ecoview::test::write_text(dir / "leaf.png", "stands for an image");
  std::filesystem::create_symlink("/dev/zero", dir / "zero.bin");
  ecoview::test::write_text(dir / "lamp.gltf", gltf_referring_to("zero.bin", "leaf.png"));
  EXPECT_EQ(disk_failure(dir / "lamp.gltf"),
            (dir / "lamp.gltf").string() + ": refers to " + (dir / "zero.bin").string() + ": not a regular file (a character device)");
  std::filesystem::create_directory(dir / "bark.png");
  ecoview::test::write_text(dir / "tree.gltf", gltf_referring_to("tri.bin", "bark.png"));
  EXPECT_EQ(disk_failure(dir / "tree.gltf"),
            (dir / "tree.gltf").string() + ": refers to " + (dir / "bark.png").string() + ": not a regular file (a folder)");
  ecoview::test::write_text(dir / "empty.png", "");
  ecoview::test::write_text(dir / "bush.gltf", gltf_referring_to("tri.bin", "empty.png"));
  EXPECT_EQ(disk_failure(dir / "bush.gltf"), (dir / "bush.gltf").string() + ": refers to " + (dir / "empty.png").string() + ": is empty");
}

// `levels` arrays one inside the next, around a 0.
std::string nested_arrays(int levels) { return std::string(static_cast<std::size_t>(levels), '[') + "0" + std::string(static_cast<std::size_t>(levels), ']'); }

TEST(JsonNesting, TheFirstBracketPastTheLimitIsFoundOutsideStringsOnly) {
  EXPECT_EQ(pointgen::json_nests_too_deep(nested_arrays(pointgen::max_json_nesting)), std::nullopt);
  EXPECT_EQ(pointgen::json_nests_too_deep(nested_arrays(pointgen::max_json_nesting + 1)), std::size_t(pointgen::max_json_nesting));
  const std::string in_a_string = "{\"a\": \"" + std::string(1000, '[') + "\\\"{\"}";
  EXPECT_EQ(pointgen::json_nests_too_deep(in_a_string), std::nullopt) << in_a_string;
  EXPECT_EQ(pointgen::json_nests_too_deep("[" + std::string(300, '{') + "}]"), std::size_t(pointgen::max_json_nesting));
}

// `levels` objects one inside the next, each {"a": ...}, around a 1.
std::string nested_objects(int levels) {
  std::string text;
  for (int i = 0; i < levels; ++i) text += "{\"a\":";
  return text + "1" + std::string(static_cast<std::size_t>(levels), '}');
}

// 100,000 levels in an extension, where tinygltf's recursive reader overflows the stack.
TEST(GltfFile, JsonNestedTooDeepIsRefusedBeforeTinygltfReadsItInGltfAndGlb) {
  const std::string gltf = R"({"asset": {"version": "2.0"}, "extensions": {"deep": )" + nested_objects(100000) + "}}";
  // The root and "extensions" are two levels: the deep value's 255th object opens the 257th.
  const std::size_t too_deep = gltf.find("{\"a\":") + 254 * std::string("{\"a\":").size();
  try {
    load("deep.gltf", gltf);
    ADD_FAILURE() << "loaded";
  } catch (const pointgen::FileError& e) {
    EXPECT_EQ(std::string(e.what()), "deep.gltf: JSON nested deeper than 256 levels (at byte " + std::to_string(too_deep) + ")");
  }
  std::string glb = "glTF";
  const auto append_u32 = [&](std::uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  append_u32(2);
  append_u32(static_cast<std::uint32_t>(20 + gltf.size()));
  append_u32(static_cast<std::uint32_t>(gltf.size()));
  glb += "JSON" + gltf;
  try {
    load("deep.glb", glb);
    ADD_FAILURE() << "loaded";
  } catch (const pointgen::FileError& e) {
    EXPECT_EQ(std::string(e.what()), "deep.glb: JSON nested deeper than 256 levels (at byte " + std::to_string(glb.find(gltf) + too_deep) + ")");
  }
}

}  // namespace
