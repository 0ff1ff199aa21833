// glTF 2.0 through tinygltf. tinygltf parses; every index and byte range it hands over is checked
// here before it is read, so hostile files fail with FileError instead of reading out of bounds.
#include "pointgen/file_error.hpp"
#include "pointgen/json_nesting.hpp"
#include "pointgen/mesh_file.hpp"

#include <stb/stb_image.h>
#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cstring>
#include <filesystem>
#include <map>
#include <set>

namespace pointgen {
namespace {

constexpr std::size_t max_elements = std::size_t{1} << 28;

// Routes tinygltf's file access through ReadFile; never expands paths (tinygltf's default runs
// wordexp on URIs from the file). tinygltf takes a file it cannot read for a missing one, and goes
// on without a missing image: a file that is there but cannot be used is kept here, to be refused
// by name once tinygltf is done.
struct FileAccess {
  const ReadFile* read;
  std::string refused;  // the first such file, as FileError words it

  std::optional<std::string> bytes_of(const std::string& path) {
    try {
      return (*read)(path);
    } catch (const FileError& e) {
      if (refused.empty()) refused = e.what();
      return std::nullopt;
    }
  }
  static bool exists(const std::string& path, void* self) {
    return static_cast<FileAccess*>(self)->bytes_of(path).has_value();
  }
  static std::string expand(const std::string& path, void*) { return path; }
  static bool read_whole(std::vector<unsigned char>* out, std::string* err,
                         const std::string& path, void* self) {
    auto& access = *static_cast<FileAccess*>(self);
    const std::optional<std::string> bytes = access.bytes_of(path);
    if (bytes && bytes->empty() && access.refused.empty()) access.refused = path + ": is empty";
    if (!bytes || bytes->empty()) {
      if (err) *err += "cannot read '" + path + "'\n";
      return false;
    }
    out->assign(bytes->begin(), bytes->end());
    return true;
  }
  static bool no_write(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
    return false;
  }
};

// Images are decoded by stb_image (PNG, JPEG) into 8-bit RGBA. Their size is read from the
// header and checked before anything is allocated for the pixels.
constexpr int max_texture_side = 16384;
constexpr std::size_t max_texture_bytes_per_file = std::size_t{1} << 30;

struct ImageDecoding {
  std::size_t bytes = 0;  // decoded so far, in this file
  std::string problem;  // of the image that failed, naming it (image_field)
};

// An image as the user finds it in the file: "images[0].uri: bark.png", or "images[0]" when it is
// embedded (tinygltf keeps the URI only of an image in a file of its own).
std::string image_field(int index, const tinygltf::Image& image) {
  const std::string field = "images[" + std::to_string(index) + "]";
  return image.uri.empty() ? field : field + ".uri: " + image.uri;
}

bool decode_image(tinygltf::Image* image, const int image_index, std::string* error, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
  auto& decoding = *static_cast<ImageDecoding*>(user);
  const auto refuse = [&](const std::string& problem) {
    decoding.problem = image_field(image_index, *image) + ": " + problem;
    if (error) *error += decoding.problem + "\n";
    return false;
  };
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(bytes, size, &width, &height, &channels)) {
    return refuse(std::string("cannot be decoded (") + stbi_failure_reason() + ")");
  }
  if (width <= 0 || height <= 0 || width > max_texture_side || height > max_texture_side) {
    return refuse(std::to_string(width) + " x " + std::to_string(height) + " texels, more than " +
                  std::to_string(max_texture_side) + " a side");
  }
  const std::size_t image_bytes = 4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (image_bytes > max_texture_bytes_per_file - decoding.bytes) return refuse("the file's images exceed 1 GiB decoded");
  stbi_uc* pixels = stbi_load_from_memory(bytes, size, &width, &height, &channels, 4);
  if (!pixels) return refuse(std::string("cannot be decoded (") + stbi_failure_reason() + ")");
  image->width = width;
  image->height = height;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image.assign(pixels, pixels + image_bytes);
  stbi_image_free(pixels);
  decoding.bytes += image_bytes;
  return true;
}

class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, const std::string& path)
      : model_(model), path_(path) {}

  [[noreturn]] void fail(const std::string& problem) const { throw FileError(path_, problem); }

  // count x components floats; integer components are normalized when the accessor says so.
  std::vector<float> floats(int index, int components, const char* what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    if (tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)) != components) {
      fail(std::string(what) + " accessor " + std::to_string(index) + " has the wrong type");
    }
    const Elements elements = checked_elements(a, index, what);  // before anything is sized by a.count
    std::vector<float> out(a.count * static_cast<std::size_t>(components), 0.0f);
    visit(elements, a, what, [&](std::size_t element, const unsigned char* src) {
      for (int c = 0; c < components; ++c) {
        out[element * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] =
            component(src, a.componentType, c, a.normalized, what);
      }
    });
    return out;
  }

  std::vector<std::uint32_t> indices(int index, std::size_t vertex_count) const {
    const tinygltf::Accessor& a = accessor(index, "index");
    if (a.type != TINYGLTF_TYPE_SCALAR) fail("index accessor is not scalar");
    const Elements elements = checked_elements(a, index, "index");
    std::vector<std::uint32_t> out(a.count, 0);
    visit(elements, a, "index", [&](std::size_t element, const unsigned char* src) {
      out[element] = integer(src, a.componentType, 0, "index");
    });
    for (std::uint32_t v : out) {
      if (v >= vertex_count) fail("index " + std::to_string(v) + " is out of range");
    }
    return out;
  }

 private:
  // Where an accessor's elements lie, every byte range checked against its buffer.
  struct Elements {
    const unsigned char* dense = nullptr;  // null: all zeros but the sparse ones
    std::size_t step = 0;
    std::size_t element_size = 0;
    std::size_t sparse_count = 0;
    int sparse_index_type = 0;
    std::size_t sparse_index_size = 0;
    const unsigned char* sparse_indices = nullptr;
    const unsigned char* sparse_values = nullptr;
  };

  const tinygltf::Accessor& accessor(int index, const char* what) const {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) {
      fail(std::string(what) + " accessor " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    if (a.count > max_elements) fail(std::string(what) + " accessor is too large");
    return a;
  }

  static std::size_t component_size(int type) {
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_BYTE:
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
      case TINYGLTF_COMPONENT_TYPE_SHORT:
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
      default: return 0;
    }
  }

  std::size_t buffer_bytes() const {
    std::size_t total = 0;
    for (const tinygltf::Buffer& buffer : model_.buffers) total += buffer.data.size();
    return total;
  }

  // The bytes of a view, checked against its buffer, with the element size and stride it implies.
  const unsigned char* view_range(int view_index, std::size_t offset, std::size_t count,
                                  std::size_t element_size, std::size_t stride_override,
                                  const char* what) const {
    if (view_index < 0 || static_cast<std::size_t>(view_index) >= model_.bufferViews.size()) {
      fail(std::string(what) + " data: buffer view " + std::to_string(view_index) +
           " does not exist");
    }
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(view_index)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size()) {
      fail(std::string(what) + " data: buffer " + std::to_string(view.buffer) + " does not exist");
    }
    const auto& data = model_.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t stride = stride_override ? stride_override : element_size;
    if (stride < element_size) fail(std::string(what) + " data: stride smaller than an element");
    // Every term is checked against what is left, so no sum of numbers from the file can wrap.
    const bool view_fits = view.byteOffset <= data.size() && view.byteLength <= data.size() - view.byteOffset;
    const bool elements_fit = count == 0 || (offset <= view.byteLength && element_size <= view.byteLength - offset &&
                                             (count - 1) <= (view.byteLength - offset - element_size) / stride);
    if (!view_fits || !elements_fit) fail(std::string(what) + " data: accessor reads past the end of its buffer");
    return data.data() + view.byteOffset + offset;
  }

  // A declared count is never trusted: the elements must lie in the file's buffers before
  // anything is allocated for them.
  Elements checked_elements(const tinygltf::Accessor& a, int index, const char* what) const {
    Elements e;
    const std::size_t components = static_cast<std::size_t>(
        tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)));
    e.element_size = component_size(a.componentType) * components;
    if (e.element_size == 0) fail(std::string(what) + " accessor has an unknown component type");
    if (a.bufferView >= 0) {
      const std::size_t stride = static_cast<std::size_t>(a.bufferView) < model_.bufferViews.size()
                                     ? model_.bufferViews[static_cast<std::size_t>(a.bufferView)].byteStride
                                     : 0;
      e.dense = view_range(a.bufferView, a.byteOffset, a.count, e.element_size, stride, what);
      e.step = stride ? stride : e.element_size;
    } else if (!a.sparse.isSparse) {
      fail(std::string(what) + " accessor " + std::to_string(index) + " has no data");
    } else if (a.count > buffer_bytes()) {
      // Zeros with a few sparse values: more of them than the file has bytes is no real model.
      fail(std::string(what) + " accessor " + std::to_string(index) + " declares more elements than the file has bytes");
    }
    if (!a.sparse.isSparse) return e;
    if (a.sparse.count < 0 || static_cast<std::size_t>(a.sparse.count) > a.count) {
      fail(std::string(what) + " accessor: bad sparse count");
    }
    e.sparse_count = static_cast<std::size_t>(a.sparse.count);
    e.sparse_index_type = a.sparse.indices.componentType;
    e.sparse_index_size = component_size(e.sparse_index_type);
    if (e.sparse_index_size == 0 || e.sparse_index_type == TINYGLTF_COMPONENT_TYPE_FLOAT || a.sparse.indices.byteOffset < 0 ||
        a.sparse.values.byteOffset < 0) {
      fail(std::string(what) + " accessor: bad sparse indices");
    }
    e.sparse_indices = view_range(a.sparse.indices.bufferView, static_cast<std::size_t>(a.sparse.indices.byteOffset),
                                  e.sparse_count, e.sparse_index_size, 0, what);
    e.sparse_values = view_range(a.sparse.values.bufferView, static_cast<std::size_t>(a.sparse.values.byteOffset),
                                 e.sparse_count, e.element_size, 0, what);
    return e;
  }

  template <class Store>
  void visit(const Elements& e, const tinygltf::Accessor& a, const char* what, const Store& store) const {
    if (e.dense) {
      for (std::size_t i = 0; i < a.count; ++i) store(i, e.dense + i * e.step);
    }
    for (std::size_t i = 0; i < e.sparse_count; ++i) {
      const std::uint32_t target = integer(e.sparse_indices + i * e.sparse_index_size, e.sparse_index_type, 0, what);
      if (target >= a.count) fail(std::string(what) + " accessor: sparse index out of range");
      store(target, e.sparse_values + i * e.element_size);
    }
  }

  std::uint32_t integer(const unsigned char* src, int type, int c, const char* what) const {
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return src[c];
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, src + 2 * c, 2);
        return v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, src + 4 * c, 4);
        return v;
      }
      default: fail(std::string(what) + " data must be unsigned integers");
    }
  }

  float component(const unsigned char* src, int type, int c, bool normalized,
                  const char* what) const {
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, src + 4 * c, 4);
        return v;
      }
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto v = static_cast<float>(static_cast<std::int8_t>(src[c]));
        return normalized ? std::max(v / 127.0f, -1.0f) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t raw;
        std::memcpy(&raw, src + 2 * c, 2);
        const auto v = static_cast<float>(raw);
        return normalized ? std::max(v / 32767.0f, -1.0f) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? static_cast<float>(src[c]) / 255.0f : static_cast<float>(src[c]);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        const auto v = static_cast<float>(integer(src, type, c, what));
        return normalized ? v / 65535.0f : v;
      }
      default: fail(std::string(what) + " data has an unsupported component type");
    }
  }

  const tinygltf::Model& model_;
  const std::string& path_;
};

glm::mat4 node_matrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(node.matrix[static_cast<std::size_t>(i)]);
    return m;
  }
  glm::mat4 m(1.0f);
  if (node.translation.size() == 3) {
    m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
  }
  if (node.rotation.size() == 4) {
    const glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                      static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
    m *= glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3) {
    m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
  }
  return m;
}

const tinygltf::Material* material_of(const tinygltf::Model& model, int material) {
  if (material < 0 || static_cast<std::size_t>(material) >= model.materials.size()) return nullptr;
  return &model.materials[static_cast<std::size_t>(material)];
}

glm::vec4 base_color(const tinygltf::Material* material) {
  if (!material || material->pbrMetallicRoughness.baseColorFactor.size() < 4) return glm::vec4(1.0f);
  const auto& f = material->pbrMetallicRoughness.baseColorFactor;
  return glm::clamp(glm::vec4(f[0], f[1], f[2], f[3]), 0.0f, 1.0f);
}

SurfaceTexture::Wrap wrap_mode(int gl_wrap) {
  if (gl_wrap == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return SurfaceTexture::Wrap::clamp;
  if (gl_wrap == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return SurfaceTexture::Wrap::mirror;
  return SurfaceTexture::Wrap::repeat;
}

// What the file has that ecoview does not use, for its one line at load.
std::string ignored_features(const tinygltf::Model& model) {
  std::vector<std::string> ignored;
  if (!model.skins.empty()) ignored.push_back("skins");
  if (!model.animations.empty()) ignored.push_back("animations");
  for (const tinygltf::Mesh& mesh : model.meshes) {
    if (std::any_of(mesh.primitives.begin(), mesh.primitives.end(), [](const tinygltf::Primitive& p) { return !p.targets.empty(); })) {
      ignored.push_back("morph targets");
      break;
    }
  }
  const auto any_material = [&](auto has) { return std::any_of(model.materials.begin(), model.materials.end(), has); };
  if (any_material([](const tinygltf::Material& m) { return m.alphaMode == "BLEND"; })) ignored.push_back("alpha blending (drawn as MASK at 0.5)");
  if (any_material([](const tinygltf::Material& m) { return m.normalTexture.index >= 0; })) ignored.push_back("normal maps");
  if (any_material([](const tinygltf::Material& m) { return m.emissiveTexture.index >= 0; })) ignored.push_back("emission");
  if (any_material([](const tinygltf::Material& m) { return m.pbrMetallicRoughness.baseColorTexture.index >= 0 &&
                                                            m.pbrMetallicRoughness.baseColorTexture.texCoord != 0; })) {
    ignored.push_back("texture coordinate sets other than TEXCOORD_0 (TEXCOORD_0 used)");
  }
  if (std::any_of(model.samplers.begin(), model.samplers.end(), [](const tinygltf::Sampler& s) {
        return s.minFilter != -1 && s.minFilter != TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
      })) {
    ignored.push_back("minification filters (drawn trilinear)");
  }
  for (const std::string& extension : model.extensionsUsed) ignored.push_back(extension);
  std::string line;
  for (const std::string& what : ignored) line += (line.empty() ? "" : ", ") + what;
  return line;
}

// Triangle list indices for a primitive of any triangle mode.
std::vector<std::uint32_t> triangle_list(const std::vector<std::uint32_t>& in, int mode) {
  if (mode == TINYGLTF_MODE_TRIANGLES) return {in.begin(), in.begin() + static_cast<std::ptrdiff_t>(in.size() / 3 * 3)};
  std::vector<std::uint32_t> out;
  for (std::size_t i = 2; i < in.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      if (i % 2 == 0) out.insert(out.end(), {in[i - 2], in[i - 1], in[i]});
      else out.insert(out.end(), {in[i - 1], in[i - 2], in[i]});
    } else {  // fan
      out.insert(out.end(), {in[0], in[i - 1], in[i]});
    }
  }
  return out;
}

class MeshBuilder {
 public:
  MeshBuilder(const tinygltf::Model& model, const std::string& path)
      : model_(model), reader_(model, path) {}

  // glTF nodes form trees: a node reached twice (a cycle, or a child listed by two parents, which
  // could multiply the geometry exponentially) is refused, and so is a hierarchy deep enough to
  // exhaust the stack.
  void add_node(int index, const glm::mat4& parent, int depth = 0) {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size()) {
      reader_.fail("node " + std::to_string(index) + " does not exist");
    }
    if (depth > 256) reader_.fail("node hierarchy is deeper than 256 levels");
    if (!visited_.insert(index).second) reader_.fail("node " + std::to_string(index) + " is reached twice (nodes must form trees)");
    const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
    const glm::mat4 world = parent * node_matrix(node);
    if (node.mesh >= 0) add_mesh(node.mesh, world);
    for (int child : node.children) add_node(child, world, depth + 1);
  }

  TriangleMesh take() { return std::move(mesh_); }

 private:
  void add_mesh(int index, const glm::mat4& world) {
    if (static_cast<std::size_t>(index) >= model_.meshes.size()) {
      reader_.fail("mesh " + std::to_string(index) + " does not exist");
    }
    for (const tinygltf::Primitive& primitive : model_.meshes[static_cast<std::size_t>(index)].primitives) {
      const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
      if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
          mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        continue;  // points and lines have no surface to shade or sample
      }
      mesh_.append(primitive_mesh(primitive, mode), world);
    }
  }

  TriangleMesh primitive_mesh(const tinygltf::Primitive& primitive, int mode) const {
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) reader_.fail("a primitive has no POSITION");
    TriangleMesh part;
    const std::vector<float> p = reader_.floats(position->second, 3, "POSITION");
    for (std::size_t i = 0; i + 2 < p.size(); i += 3) part.positions.emplace_back(p[i], p[i + 1], p[i + 2]);
    const std::size_t n = part.positions.size();

    std::vector<std::uint32_t> indices;
    if (primitive.indices >= 0) {
      indices = reader_.indices(primitive.indices, n);
    } else {
      for (std::size_t i = 0; i < n; ++i) indices.push_back(static_cast<std::uint32_t>(i));
    }
    part.indices = triangle_list(indices, mode);

    const auto normal = primitive.attributes.find("NORMAL");
    if (normal != primitive.attributes.end()) {
      const std::vector<float> v = reader_.floats(normal->second, 3, "NORMAL");
      if (v.size() != 3 * n) reader_.fail("NORMAL and POSITION counts differ");
      for (std::size_t i = 0; i < v.size(); i += 3) {
        const glm::vec3 nrm(v[i], v[i + 1], v[i + 2]);
        const float length = glm::length(nrm);
        part.normals.push_back(length > 0.0f && std::isfinite(length) ? nrm / length : glm::vec3(0, 1, 0));
      }
    } else {
      part.normals = vertex_normals(part.positions, part.indices);
    }

    const tinygltf::Material* material = material_of(model_, primitive.material);
    const glm::vec3 tint(base_color(material));
    part.colors.assign(n, tint);
    std::vector<float> color_alphas(n, 1.0f);
    const auto color = primitive.attributes.find("COLOR_0");
    if (color != primitive.attributes.end()) {
      const int index = color->second;
      const bool rgba = index >= 0 && static_cast<std::size_t>(index) < model_.accessors.size() &&
                        model_.accessors[static_cast<std::size_t>(index)].type == TINYGLTF_TYPE_VEC4;
      const int components = rgba ? 4 : 3;
      const std::vector<float> v = reader_.floats(index, components, "COLOR_0");
      if (v.size() != static_cast<std::size_t>(components) * n) reader_.fail("COLOR_0 and POSITION counts differ");
      for (std::size_t i = 0; i < n; ++i) {
        const float* c = &v[i * static_cast<std::size_t>(components)];
        part.colors[i] = tint * glm::clamp(glm::vec3(c[0], c[1], c[2]), 0.0f, 1.0f);
        if (rgba) color_alphas[i] = std::clamp(c[3], 0.0f, 1.0f);
      }
    }
    add_material(part, primitive, material, color_alphas);
    return part;
  }

  // The base-colour texture and alpha mask of a primitive's material, when it has either, with the
  // alpha of its vertex colours.
  void add_material(TriangleMesh& part, const tinygltf::Primitive& primitive, const tinygltf::Material* material,
                    std::vector<float>& color_alphas) const {
    if (!material) return;
    SurfaceMaterial surface;
    surface.alpha = base_color(material).a;
    if (material->alphaMode == "MASK") surface.alpha_cutoff = static_cast<float>(std::clamp(material->alphaCutoff, 0.0, 1.0));
    if (material->alphaMode == "BLEND") surface.alpha_cutoff = 0.5f;
    const auto texcoord = primitive.attributes.find("TEXCOORD_0");
    const int texture = material->pbrMetallicRoughness.baseColorTexture.index;
    if (texture >= 0 && texcoord != primitive.attributes.end()) surface.texture = texture_of(texture);
    if (!surface.texture && !surface.masked()) return;
    const std::size_t n = part.positions.size();
    part.texcoords.assign(n, glm::vec2(0.0f));
    if (texcoord != primitive.attributes.end()) {
      const std::vector<float> uv = reader_.floats(texcoord->second, 2, "TEXCOORD_0");
      if (uv.size() != 2 * n) reader_.fail("TEXCOORD_0 and POSITION counts differ");
      for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(uv[2 * i]) || !std::isfinite(uv[2 * i + 1])) reader_.fail("a TEXCOORD_0 value is NaN or infinite");
        part.texcoords[i] = {uv[2 * i], uv[2 * i + 1]};
      }
    }
    part.alphas = std::move(color_alphas);
    part.materials = {SurfaceMaterial{}, surface};
    part.vertex_materials.assign(n, 1u);
  }

  // The texture's image with its sampler's wrap modes, decoded once however many materials use it.
  std::shared_ptr<const SurfaceTexture> texture_of(int index) const {
    if (static_cast<std::size_t>(index) >= model_.textures.size()) reader_.fail("texture " + std::to_string(index) + " does not exist");
    const tinygltf::Texture& texture = model_.textures[static_cast<std::size_t>(index)];
    if (texture.source < 0 || static_cast<std::size_t>(texture.source) >= model_.images.size()) {
      reader_.fail("texture " + std::to_string(index) + " has no image");
    }
    auto& cached = textures_[index];
    if (cached) return cached;
    const tinygltf::Image& image = model_.images[static_cast<std::size_t>(texture.source)];
    auto surface = std::make_shared<SurfaceTexture>();
    surface->width = image.width;
    surface->height = image.height;
    surface->rgba = image.image;
    if (texture.sampler >= 0 && static_cast<std::size_t>(texture.sampler) < model_.samplers.size()) {
      const tinygltf::Sampler& sampler = model_.samplers[static_cast<std::size_t>(texture.sampler)];
      surface->wrap_s = wrap_mode(sampler.wrapS);
      surface->wrap_t = wrap_mode(sampler.wrapT);
      if (sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) surface->magnify = SurfaceTexture::Filter::nearest;
    }
    if (surface->rgba.size() != 4 * static_cast<std::size_t>(surface->width) * static_cast<std::size_t>(surface->height)) {
      // Every other way an image can fail stops tinygltf with an error; only a missing file of
      // its own gets here.
      reader_.fail(image_field(texture.source, image) + (image.uri.empty() ? ": was not decoded" : ": no such file"));
    }
    return cached = std::move(surface);
  }

  const tinygltf::Model& model_;
  AccessorReader reader_;
  TriangleMesh mesh_;
  std::set<int> visited_;
  mutable std::map<int, std::shared_ptr<const SurfaceTexture>> textures_;
};

// The JSON of a glTF file: all of a .gltf; the first chunk of a .glb (after its 12-byte header
// and the chunk's length and type), as far as the file holds it. tinygltf checks the rest.
std::string_view json_text(const std::string& bytes, bool binary) {
  if (!binary) return bytes;
  constexpr std::size_t chunk_start = 20;
  if (bytes.size() < chunk_start) return {};
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, sizeof length);
  return std::string_view(bytes).substr(chunk_start, length);
}

}  // namespace

TriangleMesh load_gltf(const std::string& path, const std::string& bytes, const ReadFile& read, const Note& note) {
  const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  const std::string_view json = json_text(bytes, binary);
  if (const std::optional<std::size_t> at = json_nests_too_deep(json)) {
    const auto byte = static_cast<std::size_t>(json.data() - bytes.data()) + *at;
    throw FileError(path, "JSON nested deeper than " + std::to_string(max_json_nesting) + " levels (at byte " +
                              std::to_string(byte) + ")");
  }
  FileAccess access{&read, {}};
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&FileAccess::exists, &FileAccess::expand, &FileAccess::read_whole,
                         &FileAccess::no_write, &access});
  ImageDecoding decoding;
  loader.SetImageLoader(&decode_image, &decoding);
  tinygltf::Model model;
  std::string error, warning;
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                           reinterpret_cast<const unsigned char*>(bytes.data()),
                                           static_cast<unsigned int>(bytes.size()), base_dir)
             : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                          static_cast<unsigned int>(bytes.size()), base_dir);
  if (!access.refused.empty()) throw FileError(path, "refers to " + access.refused);
  if (!ok && !decoding.problem.empty()) throw FileError(path, decoding.problem);
  if (!ok) {
    const std::string first_line = error.substr(0, error.find('\n'));
    throw FileError(path, "not a valid glTF file: " + (first_line.empty() ? "parse failed" : first_line));
  }

  MeshBuilder builder(model, path);
  if (!model.scenes.empty()) {
    const std::size_t scene = model.defaultScene >= 0 ? static_cast<std::size_t>(model.defaultScene) : 0;
    if (scene >= model.scenes.size()) throw FileError(path, "default scene does not exist");
    for (int node : model.scenes[scene].nodes) builder.add_node(node, glm::mat4(1.0f));
  } else {  // no scenes: every node that is nobody's child is a root
    std::vector<bool> is_child(model.nodes.size(), false);
    for (const tinygltf::Node& node : model.nodes) {
      for (int child : node.children) {
        if (child >= 0 && static_cast<std::size_t>(child) < is_child.size()) is_child[static_cast<std::size_t>(child)] = true;
      }
    }
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      if (!is_child[i]) builder.add_node(static_cast<int>(i), glm::mat4(1.0f));
    }
  }
  if (note) {
    if (const std::string ignored = ignored_features(model); !ignored.empty()) note(path + ": ignored: " + ignored);
  }
  return builder.take();
}

}  // namespace pointgen
