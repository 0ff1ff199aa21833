#include "app/reference/exact_visibility.hpp"

#include "app/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>

namespace ecoview {
namespace {

// The ray starts this share of its distance from the eye back towards the eye, off the surface
// the frame drew (whose depth is exact only to float precision), and so on the seen side of it.
constexpr float origin_offset = 2e-4f;

RTCScene mesh_scene(RTCDevice device, const pointgen::TriangleMesh& mesh) {
  if (mesh.triangle_count() == 0) return nullptr;
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree's own buffers: it reads vertices 16 bytes at a time and pads them itself.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), mesh.positions.size()));
  std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), mesh.triangle_count()));
  std::copy(mesh.indices.begin(), mesh.indices.end(), indices);
  rtcCommitGeometry(geometry);
  RTCScene scene = rtcNewScene(device);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  return scene;
}

void set_transform(RTCScene scene, unsigned id, const glm::mat4& transform) {
  RTCGeometry instance = rtcGetGeometry(scene, id);
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &transform[0][0]);
  rtcCommitGeometry(instance);
}

}  // namespace

ExactVisibility::ExactVisibility(const std::vector<pointgen::TriangleMesh>& meshes,
                                 const std::vector<pointgen::InstanceTable>& tables)
    : device_(rtcNewDevice(nullptr)) {
  if (device_ == nullptr) throw RuntimeFailure("Embree could not start a device for the exact reference");
  for (const pointgen::TriangleMesh& mesh : meshes) mesh_scenes_.push_back(mesh_scene(device_, mesh));
  scene_ = rtcNewScene(device_);
  for (const pointgen::InstanceTable& table : tables) {
    std::vector<unsigned>& ids = geometry_ids_.emplace_back();
    transforms_.push_back(table.transforms);
    for (const glm::mat4& transform : table.transforms) {
      if (mesh_scenes_[table.mesh] == nullptr) {
        ids.push_back(RTC_INVALID_GEOMETRY_ID);
        continue;
      }
      RTCGeometry instance = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(instance, mesh_scenes_[table.mesh]);
      rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &transform[0][0]);
      rtcCommitGeometry(instance);
      ids.push_back(rtcAttachGeometry(scene_, instance));
      rtcReleaseGeometry(instance);
    }
  }
  rtcCommitScene(scene_);
}

ExactVisibility::~ExactVisibility() {
  rtcReleaseScene(scene_);
  for (RTCScene s : mesh_scenes_) {
    if (s != nullptr) rtcReleaseScene(s);
  }
  rtcReleaseDevice(device_);
}

void ExactVisibility::pose(const std::vector<pointgen::InstanceTable>& tables) {
  bool moved = false;
  for (std::size_t t = 0; t < tables.size(); ++t) {
    for (std::size_t i = 0; i < tables[t].size(); ++i) {
      if (tables[t].transforms[i] == transforms_[t][i] || geometry_ids_[t][i] == RTC_INVALID_GEOMETRY_ID) continue;
      transforms_[t][i] = tables[t].transforms[i];
      set_transform(scene_, geometry_ids_[t][i], transforms_[t][i]);
      moved = true;
    }
  }
  if (moved) rtcCommitScene(scene_);
}

Image8 ExactVisibility::trace(const shadow::Camera& camera, float aspect, const shadow::Light& light,
                              const Image<float>& depth) const {
  const glm::mat4 to_world = glm::inverse(camera.projection(aspect) * camera.view());
  const glm::vec3 forward = camera.forward();
  const float cos_cone = std::cos(glm::radians(light.cone_deg));
  Image8 out{depth.width, depth.height, 1, std::vector<std::uint8_t>(depth.samples.size(), 255)};

  auto trace_rows = [&](int first_row, int row_step) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (int y = first_row; y < depth.height; y += row_step) {
      for (int x = 0; x < depth.width; ++x) {
        const float d = depth.at(x, y);
        if (!(d > 0.0f)) continue;
        // The pixel centre's ray from the eye, to the surface at view depth d.
        const glm::vec2 ndc((2.0f * static_cast<float>(x) + 1.0f) / static_cast<float>(depth.width) - 1.0f,
                            1.0f - (2.0f * static_cast<float>(y) + 1.0f) / static_cast<float>(depth.height));
        const glm::vec4 far_point = to_world * glm::vec4(ndc, 1.0f, 1.0f);
        const glm::vec3 view_ray = glm::normalize(glm::vec3(far_point) / far_point.w - camera.position);
        const float distance = d / glm::dot(view_ray, forward);
        const glm::vec3 p = camera.position + view_ray * (distance * (1.0f - origin_offset));

        glm::vec3 to_light = -glm::normalize(light.direction);
        float reach = INFINITY;
        if (light.type != shadow::LightType::directional) {
          to_light = light.position - p;
          reach = glm::length(to_light);
          to_light /= reach;
        }
        std::uint8_t& visible = out.samples[static_cast<std::size_t>(y) * static_cast<std::size_t>(depth.width) + static_cast<std::size_t>(x)];
        if (light.type == shadow::LightType::spot && glm::dot(-to_light, glm::normalize(light.direction)) < cos_cone) {
          visible = 0;
          continue;
        }
        RTCRay ray{};
        ray.org_x = p.x;
        ray.org_y = p.y;
        ray.org_z = p.z;
        ray.dir_x = to_light.x;
        ray.dir_y = to_light.y;
        ray.dir_z = to_light.z;
        ray.tnear = 0.0f;
        ray.tfar = reach;
        ray.mask = 0xFFFFFFFFu;
        rtcOccluded1(scene_, &context, &ray);
        visible = ray.tfar < 0.0f ? 0 : 255;
      }
    }
  };
  const int workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(trace_rows, w, workers);
  trace_rows(0, workers);
  for (std::thread& t : threads) t.join();
  return out;
}

}  // namespace ecoview
