#include "app/reference/exact_visibility.hpp"

#include "app/errors.hpp"
#include "app/render/pixel_rays.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>

namespace ecoview {
namespace {

// Shares of the distance from the eye: the window around the frame's depth in which the eye ray
// looks for the drawn surface, and how far off the surface the ray to the light starts.
constexpr float surface_window = 1e-2f;
constexpr float origin_offset = 2e-4f;

glm::mat3 normal_matrix(const glm::mat4x3& transform) { return glm::transpose(glm::inverse(glm::mat3(transform))); }

// Refuses the hits where the mesh's alpha mask cuts its surface away: the rays pass there, as the
// maps' depth passes discard there.
void pass_masked_away(const RTCFilterFunctionNArguments* args) {
  const auto& mesh = *static_cast<const pointgen::TriangleMesh*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const std::size_t t = 3 * static_cast<std::size_t>(RTCHitN_primID(args->hit, args->N, i));
    if (!mesh.kept_texel(t, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i))) args->valid[i] = 0;
  }
}

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
  if (mesh.masked()) {
    rtcSetGeometryUserData(geometry, const_cast<pointgen::TriangleMesh*>(&mesh));
    rtcSetGeometryIntersectFilterFunction(geometry, pass_masked_away);
    rtcSetGeometryOccludedFilterFunction(geometry, pass_masked_away);
  }
  rtcCommitGeometry(geometry);
  RTCScene scene = rtcNewScene(device);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  return scene;
}

// A table's transform as it keeps it: four columns of three floats.
void set_transform(RTCScene scene, unsigned id, const glm::mat4x3& transform) {
  RTCGeometry instance = rtcGetGeometry(scene, id);
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, &transform[0][0]);
  rtcCommitGeometry(instance);
}

}  // namespace

ExactVisibility::ExactVisibility(const std::vector<pointgen::TriangleMesh>& meshes,
                                 const pointgen::TableList& tables)
    : device_(rtcNewDevice(nullptr)), meshes_(meshes) {
  if (device_ == nullptr) throw RuntimeFailure("Embree could not start a device for the exact reference");
  for (const pointgen::TriangleMesh& mesh : meshes) mesh_scenes_.push_back(mesh_scene(device_, mesh));
  scene_ = rtcNewScene(device_);
  for (const pointgen::InstanceTable& table : tables) {
    std::vector<unsigned>& ids = geometry_ids_.emplace_back();
    transforms_.push_back(table.transforms);
    for (const glm::mat4x3& transform : table.transforms) {
      if (mesh_scenes_[table.mesh] == nullptr) {
        ids.push_back(RTC_INVALID_GEOMETRY_ID);
        continue;
      }
      RTCGeometry instance = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(instance, mesh_scenes_[table.mesh]);
      rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, &transform[0][0]);
      rtcCommitGeometry(instance);
      ids.push_back(rtcAttachGeometry(scene_, instance));
      rtcReleaseGeometry(instance);
      if (instances_.size() <= ids.back()) instances_.resize(ids.back() + 1);
      instances_[ids.back()] = {static_cast<std::uint32_t>(table.mesh), normal_matrix(transform)};
    }
  }
  rtcCommitScene(scene_);
  check_device();
}

// Embree reports failures (out of memory in a build) through the device only.
void ExactVisibility::check_device() const {
  if (const RTCError error = rtcGetDeviceError(device_); error != RTC_ERROR_NONE) {
    throw RuntimeFailure("Embree failed building the exact reference (error " + std::to_string(static_cast<int>(error)) +
                         "); try a smaller scene or --memory-budget");
  }
}

ExactVisibility::~ExactVisibility() {
  rtcReleaseScene(scene_);
  for (RTCScene s : mesh_scenes_) {
    if (s != nullptr) rtcReleaseScene(s);
  }
  rtcReleaseDevice(device_);
}

void ExactVisibility::pose(const pointgen::TableList& tables) {
  bool moved = false;
  for (std::size_t t = 0; t < tables.size(); ++t) {
    for (std::size_t i = 0; i < tables[t].size(); ++i) {
      if (tables[t].transforms[i] == transforms_[t][i] || geometry_ids_[t][i] == RTC_INVALID_GEOMETRY_ID) continue;
      transforms_[t][i] = tables[t].transforms[i];
      set_transform(scene_, geometry_ids_[t][i], transforms_[t][i]);
      instances_[geometry_ids_[t][i]].normal_matrix = normal_matrix(transforms_[t][i]);
      moved = true;
    }
  }
  if (moved) {
    rtcCommitScene(scene_);
    check_device();
  }
}

glm::vec3 ExactVisibility::geometric_normal(const RTCHit& hit) const {
  return glm::normalize(instances_[hit.instID[0]].normal_matrix * glm::vec3(hit.Ng_x, hit.Ng_y, hit.Ng_z));
}

// The mesh's vertex normals interpolated as the rasterizer does (Embree's u, v weight the
// second and third corner).
glm::vec3 ExactVisibility::shading_normal(const RTCHit& hit) const {
  const Instance& instance = instances_[hit.instID[0]];
  const pointgen::TriangleMesh& mesh = meshes_[instance.mesh];
  if (mesh.normals.size() != mesh.positions.size()) return geometric_normal(hit);
  const std::uint32_t* corner = &mesh.indices[3 * static_cast<std::size_t>(hit.primID)];
  const glm::vec3 n = (1.0f - hit.u - hit.v) * mesh.normals[corner[0]] + hit.u * mesh.normals[corner[1]] + hit.v * mesh.normals[corner[2]];
  return glm::normalize(instance.normal_matrix * n);
}

Image8 ExactVisibility::trace(const shadow::Camera& camera, const shadow::Light& light,
                              const Image<float>& depth) const {
  const PixelRays rays(camera, depth.width, depth.height);
  const float cos_cone = std::cos(glm::radians(light.cone_deg));
  Image8 out{depth.width, depth.height, 1, std::vector<std::uint8_t>(depth.samples.size(), 255)};

  auto trace_rows = [&](int first_row, int row_step) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (int y = first_row; y < depth.height; y += row_step) {
      for (int x = 0; x < depth.width; ++x) {
        const float d = depth.at(x, y);
        if (!(d > 0.0f)) continue;
        const glm::vec3 view_ray = rays.direction(x, y);
        const float distance = rays.distance(view_ray, d);
        std::uint8_t& visible = out.samples[static_cast<std::size_t>(y) * static_cast<std::size_t>(depth.width) + static_cast<std::size_t>(x)];

        RTCRayHit seen{};
        seen.ray.org_x = camera.position.x;
        seen.ray.org_y = camera.position.y;
        seen.ray.org_z = camera.position.z;
        seen.ray.dir_x = view_ray.x;
        seen.ray.dir_y = view_ray.y;
        seen.ray.dir_z = view_ray.z;
        seen.ray.tnear = distance * (1.0f - surface_window);
        seen.ray.tfar = distance * (1.0f + surface_window);
        seen.ray.mask = 0xFFFFFFFFu;
        seen.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        seen.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &seen);
        glm::vec3 p = camera.position + view_ray * (distance * (1.0f - origin_offset));
        glm::vec3 normal(0.0f);  // shading normal on the seen side; 0 where no triangle was found
        if (seen.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
          const glm::vec3 facing = geometric_normal(seen.hit);
          const float side = glm::dot(facing, view_ray) > 0.0f ? -1.0f : 1.0f;  // the side the eye sees
          normal = side * shading_normal(seen.hit);
          p = camera.position + view_ray * seen.ray.tfar + side * facing * (origin_offset * distance);
        }

        glm::vec3 to_light = -glm::normalize(light.direction);
        float reach = INFINITY;
        if (light.type != shadow::LightType::directional) {
          to_light = light.position - p;
          reach = glm::length(to_light);
          to_light /= reach;
        }
        if ((normal != glm::vec3(0.0f) && !(glm::dot(normal, to_light) > 0.0f)) ||
            (light.type == shadow::LightType::spot && glm::dot(-to_light, glm::normalize(light.direction)) < cos_cone)) {
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
