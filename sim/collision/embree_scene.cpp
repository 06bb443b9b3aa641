// The only file in recoil that includes Embree (ARCHITECTURE.md).
#include "sim/collision/embree_scene.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <mutex>

#include "core/check.h"
#include "core/error.h"

namespace recoil::sim {

struct EmbreeDevice::Impl {
  RTCDevice device = nullptr;
  std::mutex mutex;
  std::string error;  // recorded by the callback, thrown after the call returns
};

namespace {
void record_embree_error(void* user, RTCError code, const char* message) {
  auto* impl = static_cast<EmbreeDevice::Impl*>(user);
  std::lock_guard<std::mutex> lock(impl->mutex);
  if (impl->error.empty())
    impl->error = "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
}
}  // namespace

EmbreeDevice::EmbreeDevice() : m_impl(std::make_unique<Impl>()) {
  m_impl->device = rtcNewDevice(nullptr);
  if (!m_impl->device)
    throw Error(ErrorKind::internal, "cannot create an Embree device (is libembree3 installed?)");
  rtcSetDeviceErrorFunction(m_impl->device, record_embree_error, m_impl.get());
}

EmbreeDevice::~EmbreeDevice() {
  if (m_impl && m_impl->device) rtcReleaseDevice(m_impl->device);
}

void EmbreeDevice::throw_if_error(const char* what) {
  std::string message;
  {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    message.swap(m_impl->error);
  }
  if (!message.empty()) throw Error(ErrorKind::internal, std::string(what) + ": " + message);
}

struct TriangleScene::Impl {
  EmbreeDevice* device = nullptr;
  RTCScene scene = nullptr;
  RTCGeometry geometry = nullptr;
  float* vertex_buffer = nullptr;  // owned by the geometry; #V by 3 floats (+ padding)
  int num_vertices = 0;
};

namespace {
void copy_vertices(const Points& vertices, float* buffer) {
  for (Eigen::Index i = 0; i < vertices.rows(); ++i)
    for (int k = 0; k < 3; ++k) buffer[3 * i + k] = static_cast<float>(vertices(i, k));
}
}  // namespace

TriangleScene::TriangleScene(EmbreeDevice& device, const Points& vertices, const Triangles& triangles,
                             bool dynamic)
    : m_impl(std::make_unique<Impl>()), m_num_triangles(static_cast<int>(triangles.rows())) {
  RTCDevice rtc_device = device.impl().device;
  m_impl->device = &device;
  m_impl->num_vertices = static_cast<int>(vertices.rows());
  m_impl->scene = rtcNewScene(rtc_device);
  rtcSetSceneFlags(m_impl->scene, dynamic ? RTC_SCENE_FLAG_DYNAMIC | RTC_SCENE_FLAG_ROBUST
                                          : RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(m_impl->scene, dynamic ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_HIGH);
  m_impl->geometry = rtcNewGeometry(rtc_device, RTC_GEOMETRY_TYPE_TRIANGLE);
  if (dynamic) rtcSetGeometryBuildQuality(m_impl->geometry, RTC_BUILD_QUALITY_REFIT);
  // Embree reads vertex buffers with 16-byte loads: one spare float at the end.
  m_impl->vertex_buffer = static_cast<float*>(rtcSetNewGeometryBuffer(
      m_impl->geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
      static_cast<size_t>(vertices.rows()) + 1));
  auto* index_buffer = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      m_impl->geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
      static_cast<size_t>(triangles.rows())));
  device.throw_if_error("creating a triangle scene");
  copy_vertices(vertices, m_impl->vertex_buffer);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) index_buffer[3 * f + k] = static_cast<unsigned>(triangles(f, k));
  rtcCommitGeometry(m_impl->geometry);
  rtcAttachGeometryByID(m_impl->scene, m_impl->geometry, 0);
  rtcCommitScene(m_impl->scene);
  device.throw_if_error("building a triangle scene");
}

TriangleScene::~TriangleScene() {
  if (m_impl->geometry) rtcReleaseGeometry(m_impl->geometry);
  if (m_impl->scene) rtcReleaseScene(m_impl->scene);
}

void TriangleScene::update_vertices(const Points& vertices) {
  RECOIL_CHECK(vertices.rows() == m_impl->num_vertices, "vertex count changed: " << vertices.rows());
  copy_vertices(vertices, m_impl->vertex_buffer);
  rtcUpdateGeometryBuffer(m_impl->geometry, RTC_BUFFER_TYPE_VERTEX, 0);
  rtcCommitGeometry(m_impl->geometry);
  rtcCommitScene(m_impl->scene);
  m_impl->device->throw_if_error("refitting a triangle scene");
}

std::optional<RayHit> TriangleScene::first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                               double t_min, double t_max) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query{};
  query.ray.org_x = static_cast<float>(origin.x());
  query.ray.org_y = static_cast<float>(origin.y());
  query.ray.org_z = static_cast<float>(origin.z());
  query.ray.dir_x = static_cast<float>(direction.x());
  query.ray.dir_y = static_cast<float>(direction.y());
  query.ray.dir_z = static_cast<float>(direction.z());
  query.ray.tnear = static_cast<float>(t_min);
  query.ray.tfar = std::isfinite(t_max) ? static_cast<float>(t_max) : std::numeric_limits<float>::infinity();
  query.ray.mask = 0xFFFFFFFFu;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(m_impl->scene, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return RayHit{query.ray.tfar, static_cast<int>(query.hit.primID), query.hit.u, query.hit.v};
}

std::vector<RayHit> TriangleScene::all_hits(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) const {
  std::vector<RayHit> hits;
  double t = 0.0;
  // Step past each hit by a relative epsilon; a ray through an edge may report
  // the edge's two triangles, which callers treating parity must expect.
  while (hits.size() < static_cast<size_t>(4 * m_num_triangles + 4)) {
    const std::optional<RayHit> hit = first_hit(origin, direction, t);
    if (!hit) break;
    hits.push_back(*hit);
    t = std::nextafter(static_cast<float>(hit->t), std::numeric_limits<float>::infinity());
  }
  return hits;
}

}  // namespace recoil::sim
