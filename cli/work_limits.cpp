#include "cli/work_limits.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "cli/format_number.h"
#include "cli/peak_memory.h"
#include "cli/render_options.h"
#include "cli/scene_limits.h"
#include "core/error.h"
#include "render/frame_writer.h"

namespace recoil::cli {
namespace {

// Peak memory per tetrahedron of a deformable body, measured on a falling
// cube (resolution 48: 664 000 tets, 394 MB peak, about 500 B each) and
// rounded up for the contact stage's working set.
constexpr double kBytesPerTet = 640.0;
// Peak memory per triangle of a body's mesh, measured as the slope between
// 250 000- and 1 000 000-triangle spheres (`turntable` and `drop`, peak RSS):
// 270-370 B while simulating (the largest: a static mesh, whose collision
// surface and its BVH are the mesh itself) and 35-130 B more to draw it.
// The slopes include the imported mesh, about 20 B a triangle, which the
// resident memory counted as in use also holds: a slight overestimate.
constexpr double kBytesPerMeshTriangle = 370.0, kBytesPerDrawnTriangle = 130.0;
// What drawing holds whatever the scene (the OpenGL context, llvmpipe's
// threads and compiled shaders): the same measurements' intercept, 28-35 MiB.
constexpr double kRendererBytes = 40.0 * 1024.0 * 1024.0;

// Upper bound on the tets a lattice of `resolution` cells along the longest
// side gives a body: six per cell of the box around its surface (the lattice
// is laid on the surface before the transform scales it).
double lattice_tets(const sim::DeformableBodyDesc& body) {
  if (!body.tets.empty()) return body.tets.num_tets();
  if (body.mesh.vertices.rows() == 0) return 0.0;
  const Eigen::Vector3d extent =
      (body.mesh.vertices.colwise().maxCoeff() - body.mesh.vertices.colwise().minCoeff()).transpose();
  const double longest = extent.maxCoeff();
  if (!(longest > 0.0)) return 0.0;
  double cells = 1.0;
  for (int k = 0; k < 3; ++k) cells *= std::ceil(body.resolution * extent[k] / longest) + 1.0;
  return 6.0 * cells;
}

std::string gib(double bytes) { return format_number("%.3g", bytes / (1024.0 * 1024.0 * 1024.0)) + " GiB"; }

}  // namespace

double memory_limit_bytes(double max_memory_gib) {
  if (max_memory_gib > 0.0) return max_memory_gib * 1024.0 * 1024.0 * 1024.0;
  const double pages = static_cast<double>(::sysconf(_SC_PHYS_PAGES));
  const double page = static_cast<double>(::sysconf(_SC_PAGESIZE));
  return pages > 0 && page > 0 ? 0.8 * pages * page : INFINITY;
}

MemoryEstimate estimate_memory(const SceneDesc& scene, bool render) {
  MemoryEstimate estimate;
  estimate.in_use = resident_memory_mib().value_or(0.0) * 1024.0 * 1024.0;
  estimate.bytes = estimate.in_use;
  auto add = [&](double bytes, const std::string& field, const std::string& what) {
    estimate.bytes += bytes;
    if (bytes > estimate.largest_bytes) {
      estimate.largest_bytes = bytes;
      estimate.largest_field = field;
      estimate.largest_what = what;
    }
  };
  const double per_triangle = kBytesPerMeshTriangle + (render ? kBytesPerDrawnTriangle : 0.0);
  for (const SceneBody& body : scene.bodies) {
    if (body.is_plane()) continue;
    const bool deformable = body.kind == sim::BodyKind::deformable;
    const sim::TriMesh& mesh = deformable ? scene.world.bodies[static_cast<size_t>(body.index)].mesh
                                          : scene.world.rigid_bodies[static_cast<size_t>(body.index)].mesh;
    const double triangles = static_cast<double>(mesh.num_triangles());
    add(triangles * per_triangle, body.pointer + "/mesh",
        format_number("%.3g", triangles / 1e6) + " million triangles");
    if (!deformable) continue;
    const sim::DeformableBodyDesc& desc = scene.world.bodies[static_cast<size_t>(body.index)];
    const double tets = lattice_tets(desc);
    const std::string field = body.pointer + (desc.tets.empty() ? "/tets/resolution" : "/mesh");
    add(tets * kBytesPerTet, field, format_number("%.3g", tets / 1e6) + " million tetrahedra");
  }
  if (render) {
    const render::RenderSettings settings = to_render_settings(scene.render);
    const double pixels = static_cast<double>(settings.width) * settings.height;
    // The renderer itself, colour and depth per sample, the single-sample frame, and an RGBA8 image per
    // encoder thread and per frame queued for them.
    const render::FrameWriterSize writer = render::default_frame_writer_size();
    const double bytes = kRendererBytes +
        pixels * (8.0 * std::max(1, scene.render.msaa) + 4.0 + 4.0 * (writer.threads + writer.capacity));
    add(bytes, "/render/resolution",
        scene.render.resolution + " pixels at msaa " + std::to_string(scene.render.msaa));
  }
  return estimate;
}

void check_work_limits(const SceneDesc& scene, int last_frame, bool render, double memory_limit) {
  const std::string file = scene.label();
  // The run simulates up to its last frame, which --frames may put past the duration.
  const double frames = std::max(std::floor(scene.duration * scene.render.fps + 1e-9) + 1.0, double(last_frame));
  const double steps = (frames - 1.0) / (scene.render.fps * scene.world.dt) + scene.settle / scene.world.dt;
  if (steps > static_cast<double>(kMaxSteps))
    throw bad_input(file + ": /simulation/duration: " + format_number("%.3g", frames) + " frames at " +
                    format_number("%g", scene.render.fps) + " fps and dt " + format_number("%g", scene.world.dt) +
                    " s" + (scene.settle > 0 ? " after " + format_number("%g", scene.settle) + " s of settling" : "") +
                    " is " + format_number("%.3g", steps) + " steps; at most " +
                    format_number("%.0f", static_cast<double>(kMaxSteps)));
  if (frames > kMaxFrames)
    throw bad_input(file + ": /simulation/duration: " + format_number("%g", scene.duration) + " s at " +
                    format_number("%g", scene.render.fps) + " fps (or --frames) is " + format_number("%.3g", frames) +
                    " frames; at most " + std::to_string(kMaxFrames));
  const MemoryEstimate memory = estimate_memory(scene, render);
  // A limit below what recoil already holds (itself, the meshes read) is no field's fault.
  if (memory.in_use >= memory_limit)
    throw bad_input(file + ": recoil already holds " + gib(memory.in_use) +
                    " (itself and the meshes read), more than the " + gib(memory_limit) +
                    " allowed (--max-memory): raise the limit");
  if (memory.bytes > memory_limit)
    throw bad_input(file + ": " + memory.largest_field + ": the run needs about " + gib(memory.bytes) + " (" +
                    gib(memory.largest_bytes) + " for " + memory.largest_what + ", " + gib(memory.in_use) +
                    " in use before it starts), more than the " +
                    gib(memory_limit) + " allowed (--max-memory)");
}

}  // namespace recoil::cli
