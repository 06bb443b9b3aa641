// The only file in recoil that includes Embree.
#include "sim/collision/embree_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
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
  double max_abs_coordinate = 0.0;  // bounds the float rounding of the stored vertices
  const unsigned* indices = nullptr;  // owned by the geometry; #F by 3
  // A small scene is searched triangle by triangle and builds its BVH only
  // for a ray query: Embree's threaded commit costs more than the search.
  bool direct = false;
  std::atomic<bool> stale{false};  // the vertices moved since the last commit
  std::mutex commit_mutex;
};

namespace {
// Returns the largest |coordinate|, which bounds the rounding error.
double copy_vertices(const Points& vertices, float* buffer) {
  double max_abs = 0.0;
  for (Eigen::Index i = 0; i < vertices.rows(); ++i)
    for (int k = 0; k < 3; ++k) {
      buffer[3 * i + k] = static_cast<float>(vertices(i, k));
      max_abs = std::max(max_abs, std::abs(vertices(i, k)));
    }
  return max_abs;
}

// Triangles a scene searches one by one instead of through its BVH: a rigid
// box's 12, or a coarse primitive's few dozen.
constexpr int kDirectTriangles = 64;

// Commits the geometry and scene if the vertices moved since the last commit;
// safe to call from several threads at once.
void commit_if_moved(TriangleScene::Impl& impl) {
  if (!impl.stale.load(std::memory_order_acquire)) return;
  std::lock_guard<std::mutex> lock(impl.commit_mutex);
  if (!impl.stale.load(std::memory_order_relaxed)) return;
  rtcCommitGeometry(impl.geometry);
  rtcCommitScene(impl.scene);
  impl.device->throw_if_error("refitting a triangle scene");
  impl.stale.store(false, std::memory_order_release);
}

// Squared distance, in float as Embree's culling is, from `p` to the bounding box of triangle `f`.
float squared_distance_to_triangle_box(const TriangleScene::Impl& impl, int f, const float p[3]) {
  float d2 = 0.0f;
  for (int k = 0; k < 3; ++k) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (int c = 0; c < 3; ++c) {
      const float x = impl.vertex_buffer[3 * impl.indices[3 * f + c] + static_cast<unsigned>(k)];
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    const float out = std::max({lo - p[k], p[k] - hi, 0.0f});
    d2 += out * out;
  }
  return d2;
}

struct NearOutput {
  std::vector<int>* ids;
  bool failed = false;  // an allocation failed inside the callback
};

// Collects the primitive ids Embree offers; the exact test happens later in double.
bool collect_primitive(RTCPointQueryFunctionArguments* args) {
  auto* output = static_cast<NearOutput*>(args->userPtr);
  try {
    output->ids->push_back(static_cast<int>(args->primID));
  } catch (...) {  // nothing may cross the C callback
    output->failed = true;
  }
  return false;  // the query radius is left unchanged
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
  m_impl->max_abs_coordinate = copy_vertices(vertices, m_impl->vertex_buffer);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) index_buffer[3 * f + k] = static_cast<unsigned>(triangles(f, k));
  m_impl->indices = index_buffer;
  m_impl->direct = m_num_triangles <= kDirectTriangles;
  rtcAttachGeometryByID(m_impl->scene, m_impl->geometry, 0);
  device.throw_if_error("building a triangle scene");
  m_impl->stale = true;
  if (!m_impl->direct) commit_if_moved(*m_impl);
}

TriangleScene::~TriangleScene() {
  if (m_impl->geometry) rtcReleaseGeometry(m_impl->geometry);
  if (m_impl->scene) rtcReleaseScene(m_impl->scene);
}

void TriangleScene::update_vertices(const Points& vertices) {
  RECOIL_CHECK(vertices.rows() == m_impl->num_vertices, "vertex count changed: " << vertices.rows());
  m_impl->max_abs_coordinate = copy_vertices(vertices, m_impl->vertex_buffer);
  rtcUpdateGeometryBuffer(m_impl->geometry, RTC_BUFFER_TYPE_VERTEX, 0);
  m_impl->stale = true;
  if (!m_impl->direct) commit_if_moved(*m_impl);
}

std::optional<RayHit> TriangleScene::first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                               double t_min, double t_max) const {
  commit_if_moved(*m_impl);
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

void TriangleScene::triangles_near(const Eigen::Vector3d& center, double radius, std::vector<int>& out) const {
  if (m_num_triangles == 0) return;
  // Rounding to float moves vertices and the centre by at most half an ulp of
  // their magnitude (~6e-8 relative); pad by a generous multiple of that.
  const double magnitude = std::max(m_impl->max_abs_coordinate, center.cwiseAbs().maxCoeff()) + radius;
  const double padded = radius + 1e-6 * magnitude + 1e-30;
  RTCPointQuery query{};
  query.x = static_cast<float>(center.x());
  query.y = static_cast<float>(center.y());
  query.z = static_cast<float>(center.z());
  query.time = 0.0f;
  query.radius = static_cast<float>(padded);
  const size_t first = out.size();
  if (m_impl->direct) {
    // In ascending order, each once: already as the BVH path leaves them.
    const float p[3] = {query.x, query.y, query.z};
    for (int f = 0; f < m_num_triangles; ++f)
      if (squared_distance_to_triangle_box(*m_impl, f, p) <= query.radius * query.radius) out.push_back(f);
    return;
  }
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  NearOutput output{&out};
  rtcPointQuery(m_impl->scene, &query, &context, collect_primitive, &output);
  if (output.failed) throw Error(ErrorKind::internal, "out of memory in a point query");
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
  out.erase(std::unique(out.begin() + static_cast<std::ptrdiff_t>(first), out.end()), out.end());
}

struct BoxScene::Impl {
  EmbreeDevice* device = nullptr;
  RTCScene scene = nullptr;
  RTCGeometry geometry = nullptr;
  std::vector<RTCBounds> bounds;  // read by the bounds callback during commits
  std::vector<std::array<int, 2>> keys;  // empty or one per box
  size_t committed_count = 0;      // boxes in the BVH as last committed
  bool stale = false;              // bounds changed since the last commit
};

namespace {
void box_bounds(const RTCBoundsFunctionArguments* args) {
  const auto* impl = static_cast<const BoxScene::Impl*>(args->geometryUserPtr);
  *args->bounds_o = impl->bounds[args->primID];
}

float round_down(double x) {
  float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float round_up(double x) {
  float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

bool overlap(const RTCBounds& a, const RTCBounds& b) {
  return a.lower_x <= b.upper_x && b.lower_x <= a.upper_x && a.lower_y <= b.upper_y && b.lower_y <= a.upper_y &&
         a.lower_z <= b.upper_z && b.lower_z <= a.upper_z;
}

// The pairs of one rtcCollide call. Embree calls back from several threads
// in small batches, so each thread appends to a buffer of its own, taken
// under the lock once per call (a lock per batch had been a third of a
// self query); the buffers are joined and sorted after the call.
struct CollideOutput {
  const BoxScene::Impl* scene0;
  const BoxScene::Impl* scene1;
  std::mutex mutex;
  std::vector<std::unique_ptr<std::vector<std::pair<int, int>>>> buffers;
  bool failed = false;  // an allocation failed inside the callback
  unsigned long long call = 0;  // tells this call's buffers from earlier calls'
};

std::atomic<unsigned long long> g_collide_calls{0};

// This thread's buffer for `output`, created on its first batch.
std::vector<std::pair<int, int>>& thread_buffer(CollideOutput& output) {
  thread_local unsigned long long cached_call = 0;
  thread_local std::vector<std::pair<int, int>>* cached = nullptr;
  if (cached_call != output.call) {
    std::lock_guard<std::mutex> lock(output.mutex);
    output.buffers.push_back(std::make_unique<std::vector<std::pair<int, int>>>());
    cached = output.buffers.back().get();
    cached_call = output.call;
  }
  return *cached;
}

// Whether boxes i (of scene0) and j (of scene1) form a pair as
// overlapping_pairs defines it; a self pair is taken as (lo, hi).
bool is_pair(const BoxScene::Impl& scene0, const BoxScene::Impl& scene1, unsigned i, unsigned j) {
  if (&scene0 == &scene1) {
    if (i == j) return false;
    if (i > j) std::swap(i, j);
    const std::vector<std::array<int, 2>>& keys = scene0.keys;
    if (!keys.empty() && (keys[i][0] == keys[j][0] || keys[i][0] == keys[j][1] || keys[i][1] == keys[j][0] ||
                          keys[i][1] == keys[j][1]))
      return false;
  }
  return overlap(scene0.bounds[i], scene1.bounds[j]);
}

void append_overlaps(CollideOutput& output, const RTCCollision* collisions, unsigned int count) {
  const bool self = output.scene0 == output.scene1;
  std::vector<std::pair<int, int>>& kept = thread_buffer(output);
  for (unsigned int k = 0; k < count; ++k) {
    unsigned i = collisions[k].primID0, j = collisions[k].primID1;
    // Embree reports leaf-box pairs: keep the pairs whose own boxes overlap,
    // each unordered self pair once as (lo, hi), whichever order Embree used.
    if (self && i > j) std::swap(i, j);
    if (is_pair(*output.scene0, *output.scene1, i, j)) kept.emplace_back(static_cast<int>(i), static_cast<int>(j));
  }
}

// Sorts (i, j) pairs of non-negative ints and drops repeats: an LSD radix
// sort on 64-bit keys, much faster than std::sort for the millions of pairs
// a fine self-colliding surface produces, and std::sort below kRadixPairs,
// where the radix passes' 65537-entry counters cost more than the sort.
constexpr size_t kRadixPairs = 1 << 16;
void sort_unique_pairs(std::vector<std::pair<int, int>>& pairs) {
  if (pairs.size() < kRadixPairs) {
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return;
  }
  std::vector<std::uint64_t> keys(pairs.size()), scratch(pairs.size());
  for (size_t k = 0; k < pairs.size(); ++k)
    keys[k] = (static_cast<std::uint64_t>(pairs[k].first) << 32) | static_cast<std::uint32_t>(pairs[k].second);
  for (int shift = 0; shift < 64; shift += 16) {
    std::vector<size_t> offset(65537, 0);
    for (std::uint64_t key : keys) ++offset[((key >> shift) & 0xFFFF) + 1];
    if (offset[1] == keys.size()) continue;  // all in bucket 0: this digit is already sorted
    for (size_t b = 1; b < offset.size(); ++b) offset[b] += offset[b - 1];
    for (std::uint64_t key : keys) scratch[offset[(key >> shift) & 0xFFFF]++] = key;
    keys.swap(scratch);
  }
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  pairs.resize(keys.size());
  for (size_t k = 0; k < keys.size(); ++k)
    pairs[k] = {static_cast<int>(keys[k] >> 32), static_cast<int>(keys[k] & 0xFFFFFFFFu)};
}

void collect_collisions(void* user, RTCCollision* collisions, unsigned int count) {
  auto* output = static_cast<CollideOutput*>(user);
  try {
    append_overlaps(*output, collisions, count);
  } catch (...) {  // nothing may cross the C callback
    std::lock_guard<std::mutex> lock(output->mutex);
    output->failed = true;
  }
}

constexpr size_t kDirectPairs = 4096;  // box pairs tested one by one rather than through rtcCollide

// Refits the BVH when the box count is unchanged, rebuilds it otherwise.
void commit_if_stale(BoxScene::Impl& impl) {
  if (!impl.stale) return;
  if (impl.bounds.size() != impl.committed_count)
    rtcSetGeometryUserPrimitiveCount(impl.geometry, static_cast<unsigned>(impl.bounds.size()));
  rtcCommitGeometry(impl.geometry);
  rtcCommitScene(impl.scene);
  impl.device->throw_if_error("building a box scene");
  impl.committed_count = impl.bounds.size();
  impl.stale = false;
}
}  // namespace

BoxScene::BoxScene(EmbreeDevice& device) : m_impl(std::make_unique<Impl>()) {
  m_impl->device = &device;
  m_impl->scene = rtcNewScene(device.impl().device);
  rtcSetSceneFlags(m_impl->scene, RTC_SCENE_FLAG_DYNAMIC);
  rtcSetSceneBuildQuality(m_impl->scene, RTC_BUILD_QUALITY_LOW);
  m_impl->geometry = rtcNewGeometry(device.impl().device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryBuildQuality(m_impl->geometry, RTC_BUILD_QUALITY_REFIT);
  rtcSetGeometryUserPrimitiveCount(m_impl->geometry, 0);
  rtcSetGeometryUserData(m_impl->geometry, m_impl.get());
  rtcSetGeometryBoundsFunction(m_impl->geometry, box_bounds, nullptr);
  rtcCommitGeometry(m_impl->geometry);
  rtcAttachGeometryByID(m_impl->scene, m_impl->geometry, 0);
  rtcCommitScene(m_impl->scene);
  device.throw_if_error("creating a box scene");
}

BoxScene::~BoxScene() {
  if (m_impl->geometry) rtcReleaseGeometry(m_impl->geometry);
  if (m_impl->scene) rtcReleaseScene(m_impl->scene);
}

int BoxScene::num_boxes() const { return static_cast<int>(m_impl->bounds.size()); }

void BoxScene::set_boxes(const std::vector<Aabb>& boxes, std::vector<std::array<int, 2>> keys) {
  RECOIL_CHECK(keys.empty() || keys.size() == boxes.size(), keys.size() << " keys for " << boxes.size() << " boxes");
  m_impl->keys = std::move(keys);
  m_impl->bounds.resize(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) {
    RECOIL_CHECK(boxes[i].valid(), "box " << i << " is empty or NaN");
    RTCBounds& b = m_impl->bounds[i];
    b.lower_x = round_down(boxes[i].min.x());
    b.lower_y = round_down(boxes[i].min.y());
    b.lower_z = round_down(boxes[i].min.z());
    b.upper_x = round_up(boxes[i].max.x());
    b.upper_y = round_up(boxes[i].max.y());
    b.upper_z = round_up(boxes[i].max.z());
    b.align0 = b.align1 = 0.0f;
  }
  // The BVH is committed when a query first needs it (commit_if_stale): a
  // scene small enough to be paired box by box never builds one.
  m_impl->stale = true;
}

std::vector<std::pair<int, int>> BoxScene::overlapping_pairs(const BoxScene& other) const {
  if (m_impl->bounds.empty() || other.m_impl->bounds.empty()) return {};
  // Few boxes (a rigid box's 12 triangles): every pair directly, in order,
  // with the same test; Embree's threaded traversal costs more than that.
  const size_t n0 = m_impl->bounds.size(), n1 = other.m_impl->bounds.size();
  if (n0 * n1 <= kDirectPairs) {
    std::vector<std::pair<int, int>> pairs;
    const bool self = m_impl.get() == other.m_impl.get();
    for (unsigned i = 0; i < n0; ++i)
      for (unsigned j = self ? i + 1 : 0; j < n1; ++j)
        if (is_pair(*m_impl, *other.m_impl, i, j)) pairs.emplace_back(static_cast<int>(i), static_cast<int>(j));
    return pairs;
  }
  CollideOutput output{m_impl.get(), other.m_impl.get(), {}, {}, false, ++g_collide_calls};
  commit_if_stale(*m_impl);
  commit_if_stale(*other.m_impl);
  rtcCollide(m_impl->scene, other.m_impl->scene, collect_collisions, &output);
  m_impl->device->throw_if_error("rtcCollide on box scenes");
  if (output.failed) throw Error(ErrorKind::internal, "out of memory in rtcCollide");
  std::vector<std::pair<int, int>> pairs;
  size_t total = 0;
  for (const auto& buffer : output.buffers) total += buffer->size();
  pairs.reserve(total);
  for (const auto& buffer : output.buffers) pairs.insert(pairs.end(), buffer->begin(), buffer->end());
  sort_unique_pairs(pairs);
  return pairs;
}

}  // namespace recoil::sim
