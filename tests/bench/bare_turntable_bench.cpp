// recoil's turntable and drop against the least an offscreen OSMesa program
// must do for the same frames: one static mesh, a lit shader, 4x MSAA
// resolved and read back, each frame PNG-encoded at level 1, 36 frames at
// 1920x1080 round the mesh. The bare program gives the floor recoil's look
// and pipeline add to.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "render/camera.h"
#include "render/context.h"
#include "render/gl.h"
#include "render/gl_objects.h"
#include "render/png.h"
#include "render/shader_program.h"
#include "render/vertex_normals.h"
#include "sim/geometry/mesh_import.h"
#include "sim/geometry/primitives.h"
#include "tests/bench/bench.h"

namespace recoil::bench {
namespace {

namespace fs = std::filesystem;
constexpr int kWidth = 1920, kHeight = 1080, kFrames = 36;

// Wall seconds for the bare program's 36 frames of `mesh`.
double bare_seconds(const sim::TriMesh& mesh) {
  const auto start = std::chrono::steady_clock::now();
  render::GlContext context(render::GlBackend::osmesa);
  std::vector<float> positions, normals;
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    for (int k = 0; k < 3; ++k) positions.push_back(static_cast<float>(mesh.vertices(v, k)));
  std::vector<std::uint32_t> indices(mesh.triangles.data(), mesh.triangles.data() + mesh.triangles.size());
  render::area_weighted_normals(positions, indices, normals);
  render::ShaderProgram program("bare", R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_view_projection;
out vec3 v_normal;
void main() { v_normal = a_normal; gl_Position = u_view_projection * vec4(a_position, 1.0); })",
                                R"(#version 330 core
in vec3 v_normal;
out vec4 o_color;
void main() { o_color = vec4(vec3(0.8, 0.6, 0.4) * (0.2 + 0.8 * max(dot(normalize(v_normal), normalize(vec3(0.4, 0.8, 0.3))), 0.0)), 1.0); })");
  auto vao = render::gl::VertexArray::create();
  auto buffers = std::array{render::gl::Buffer::create(), render::gl::Buffer::create(), render::gl::Buffer::create()};
  glBindVertexArray(vao.get());
  for (int i = 0; i < 2; ++i) {
    const std::vector<float>& data = i == 0 ? positions : normals;
    glBindBuffer(GL_ARRAY_BUFFER, buffers[static_cast<size_t>(i)].get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(static_cast<GLuint>(i));
    glVertexAttribPointer(static_cast<GLuint>(i), 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[2].get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * 4), indices.data(), GL_STATIC_DRAW);
  // A 4x MSAA target and a single-sample one to resolve into.
  auto msaa = render::gl::Framebuffer::create(), resolved = render::gl::Framebuffer::create();
  auto color = render::gl::Renderbuffer::create(), depth = render::gl::Renderbuffer::create(),
       plain = render::gl::Renderbuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, msaa.get());
  glBindRenderbuffer(GL_RENDERBUFFER, color.get());
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, kWidth, kHeight);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color.get());
  glBindRenderbuffer(GL_RENDERBUFFER, depth.get());
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH_COMPONENT24, kWidth, kHeight);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.get());
  glBindFramebuffer(GL_FRAMEBUFFER, resolved.get());
  glBindRenderbuffer(GL_RENDERBUFFER, plain.get());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kWidth, kHeight);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, plain.get());

  const sim::Aabb box = sim::bounding_box(mesh);
  render::Image image(kWidth, kHeight);
  for (int frame = 0; frame < kFrames; ++frame) {
    const render::Camera camera = render::frame_bounding_sphere(box.center(), 0.5 * box.extent().norm(),
                                                                360.0 * frame / kFrames, 20.0, 40.0, double(kWidth) / kHeight);
    const double reach = (camera.eye - camera.target).norm() + box.extent().norm();
    const Eigen::Matrix4f view_projection =
        (camera.projection_matrix(double(kWidth) / kHeight, 0.01 * reach, reach) * camera.view_matrix()).cast<float>();
    glBindFramebuffer(GL_FRAMEBUFFER, msaa.get());
    glViewport(0, 0, kWidth, kHeight);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.11f, 0.13f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    program.use();
    glUniformMatrix4fv(program.location("u_view_projection"), 1, GL_FALSE, view_projection.data());
    glBindVertexArray(vao.get());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indices.size()), GL_UNSIGNED_INT, nullptr);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa.get());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved.get());
    glBlitFramebuffer(0, 0, kWidth, kHeight, 0, 0, kWidth, kHeight, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved.get());
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    render::PngOptions png;
    png.level = 1;
    png.alpha = false;  // opaque, as recoil writes frames over a background colour
    volatile size_t bytes = render::encode_png(image, png).size();
    (void)bytes;
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Wall seconds of `recoil` writing 36 frames at 1920x1080: `command` names
// the subcommand, the mesh and its own options, `flags` the look. Less the
// world's build and the simulation's steps (run.json), which run before the
// frames and beside them; what is left is drawing and writing the frames.
double recoil_seconds(const std::string& command, const std::string& flags, const fs::path& out) {
  const std::string line = std::string(RECOIL_BINARY) + " -q " + command +
                           " --resolution 1920x1080 --msaa 4 --png-level 1 " + flags + " -o '" + out.string() + "'";
  if (std::system(line.c_str()) != 0) return NAN;
  const nlohmann::json t = nlohmann::json::parse(std::ifstream(out / "run.json"))["timings_ms"];
  return (t["total"].get<double>() - t["build"].get<double>() - t["step"].get<double>()) * 1e-3;
}

// The same three looks against the bare program's time, as one table row.
std::vector<std::string> ratio_row(const std::string& name, const sim::TriMesh& mesh, double bare,
                                   const std::string& command, const fs::path& out) {
  const double occlusion = recoil_seconds(command, "--ao", out.string() + "_ao");
  const double shadows = recoil_seconds(command, "", out.string() + "_shadows");
  const double off = recoil_seconds(command, "--no-shadows --no-ground", out.string() + "_off");
  return {name,
          std::to_string(mesh.num_triangles()),
          fixed(bare, 2),
          fixed(occlusion, 2),
          fixed(occlusion / bare, 2),
          fixed(shadows, 2),
          fixed(shadows / bare, 2),
          fixed(off, 2),
          fixed(off / bare, 2)};
}

void bench_bare_turntable() {
  const std::vector<std::string> columns = {"mesh", "triangles", "bare s", "recoil, shadows + AO s", "x bare",
                                            "recoil, shadows s", "x bare", "recoil, all off s", "x bare"};
  BenchTable turntable("turntable against a bare OSMesa program, 36 frames at 1920x1080, MSAA 4, PNG level 1", columns);
  turntable.note(
      "The bare program (this bench, one process) uploads the mesh once and per frame draws it with one lit "
      "shader into a 4x MSAA target, resolves, reads back and PNG-encodes at level 1, one frame after another. "
      "recoil is `recoil turntable` as a user runs it (its own run.json, less the world's build and steps): with shadows and "
      "the ground and `--ao`, with shadows and the ground, and with `--no-shadows --no-ground`.");
  BenchTable drop("drop against the same bare program, 36 frames at 1920x1080, MSAA 4, PNG level 1", columns);
  drop.note(
      "recoil is `recoil drop MESH --material rigid --seconds 1.2 --frames 1-36` (37 frames, the first 36 "
      "written), the same looks as above, less the world's build and the simulation's steps (run.json): drawing "
      "and writing frames of a body that falls, bounces and rests, so the shadow map and the occlusion are drawn "
      "again every frame. The bare program's time is the turntable's: it draws the mesh once a frame whatever the "
      "view.");
  const fs::path dir = fs::temp_directory_path() / ("recoil_bench_bare_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  struct Subject {
    const char* name;
    fs::path file;
    sim::TriMesh mesh;
  };
  std::vector<Subject> subjects;
  const fs::path bunny = fs::path(RECOIL_SOURCE_DIR) / "assets/meshes/bunny.obj";
  subjects.push_back({"bunny", bunny, sim::import_surface(bunny)});
  const fs::path torus = dir / "torus.off";  // 1 000 000 triangles
  write_off(sim::make_torus(0.11, 0.04, 1000, 500), torus);
  subjects.push_back({"torus", torus, sim::import_surface(torus)});
  for (const Subject& s : subjects) {
    const double bare = bare_seconds(s.mesh);
    const std::string file = "'" + s.file.string() + "'";
    turntable.add_row(ratio_row(s.name, s.mesh, bare, "turntable " + file + " --turn-frames " + std::to_string(kFrames),
                                dir / (std::string(s.name) + "_turntable")));
    drop.add_row(ratio_row(s.name, s.mesh, bare,
                           "drop " + file + " --material rigid --seconds 1.2 --frames 1-" + std::to_string(kFrames),
                           dir / (std::string(s.name) + "_drop")));
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  turntable.print();
  drop.print();
}

const Register registered_bare_turntable("bare_turntable", bench_bare_turntable);

}  // namespace
}  // namespace recoil::bench
