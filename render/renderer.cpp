#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "render/ambient_occlusion.h"
#include "render/bounds.h"
#include "render/context.h"
#include "render/gl.h"
#include "render/ground.h"
#include "render/mesh_buffers.h"
#include "render/refused_setting.h"
#include "render/render_target.h"
#include "render/screen_rect.h"
#include "render/shader_program.h"
#include "render/shaders.h"
#include "render/shadow_map.h"
#include "render/srgb.h"
#include "render/studio_lights.h"
#include "render/texture_cache.h"

namespace recoil::render {
namespace {

// Shadow-map side: about one texel per output pixel across the subject,
// a power of two between 512 and the largest (2048 for 720p and 1080p).
int shadow_map_size(const RenderSettings& s) {
  int size = 512;
  while (size < std::max(s.width, s.height) && size < ShadowMap::kLargestSize) size *= 2;
  return size;
}

constexpr GLenum kShadowUnit = GL_TEXTURE0;
constexpr GLenum kMaterialUnit = GL_TEXTURE1;
constexpr GLenum kOcclusionUnit = GL_TEXTURE2;
constexpr GLenum kLayerUnit = GL_TEXTURE3;
// Pixels the meshes' rectangle grows by: line width, sample positions, rounding.
constexpr int kMeshRectPad = 2;
// The occlusion's reach as a share of the scene's bounding radius: creases
// and the gap under a resting body, not the whole room.
constexpr double kOcclusionReach = 0.15;
// Receivers look up the map this far off their surface, against acne.
constexpr double kNormalOffsetTexels = 1.5;
// How far a receiver's lookups reach past its own shadow-map texel: the
// normal offset, the taps' 0.75 and the 2x2 comparison's 1, rounded up.
constexpr double kShadowReachTexels = 4.0;
constexpr float kOpaque = 0.999f;  // opacity at or above this draws in the opaque pass

void validate(const Camera& c) {
  if (!c.eye.allFinite() || !c.target.allFinite() || !c.up.allFinite() || (c.eye - c.target).norm() < 1e-9) {
    throw bad_input("camera position and target must be finite and distinct");
  }
  if (!(c.fov_y_degrees > 0.0 && c.fov_y_degrees < 180.0)) {
    throw bad_input("camera fov must be between 0 and 180 degrees, not " + std::to_string(c.fov_y_degrees));
  }
}

void validate(const RenderSettings& s) {
  if (s.width < 1 || s.height < 1 || s.width > 16384 || s.height > 16384) {
    throw RefusedSetting("resolution", "render resolution " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                    " is outside 1x1 .. 16384x16384");
  }
  if (s.msaa != 0 && s.msaa != 2 && s.msaa != 4) {
    throw RefusedSetting("msaa", "render msaa must be 0, 2 or 4, not " + std::to_string(s.msaa));
  }
}

void set(ShaderProgram& p, const char* name, const Eigen::Vector3f& v) { glUniform3fv(p.location(name), 1, v.data()); }
void set(ShaderProgram& p, const char* name, const Eigen::Vector3d& v) { set(p, name, Eigen::Vector3f(v.cast<float>())); }
void set(ShaderProgram& p, const char* name, const Eigen::Matrix4f& m) {
  glUniformMatrix4fv(p.location(name), 1, GL_FALSE, m.data());
}
void set(ShaderProgram& p, const char* name, float v) { glUniform1f(p.location(name), v); }
void set(ShaderProgram& p, const char* name, int v) { glUniform1i(p.location(name), v); }
void set_shading(ShaderProgram& p, const SurfaceShading& shading) {
  set(p, "u_metallic", shading.metallic);
  set(p, "u_shininess", shading.shininess);
  set(p, "u_highlight", shading.highlight);
}

std::string hex(unsigned value) {
  char text[16];
  std::snprintf(text, sizeof text, "%04x", value);
  return text;
}

// The meshes' ambient occlusion is the renderer's, fixed by its settings.
ShaderProgram mesh_program(bool shadows, bool textured, const RenderSettings& s) {
  const std::string name = std::string("mesh") + (shadows ? "+shadow" : "") + (textured ? "+texture" : "") +
                           (s.ambient_occlusion ? "+occlusion" : "");
  return ShaderProgram(name, shaders::mesh_vertex(), shaders::mesh_fragment(shadows, textured, s.ambient_occlusion));
}

ShaderProgram ground_program(bool shadows, bool grid, bool occlusion) {
  const std::string name =
      std::string("ground") + (grid ? "+grid" : "") + (shadows ? "+shadow" : "") + (occlusion ? "+occlusion" : "");
  return ShaderProgram(name, shaders::ground_vertex(), shaders::ground_fragment(shadows, grid, occlusion));
}

void set_culling(bool cull) {
  if (cull) {
    glEnable(GL_CULL_FACE);
  } else {
    glDisable(GL_CULL_FACE);
  }
}

}  // namespace

// What one frame needs besides the scene: derived once, used by every pass.
struct Frame {
  Eigen::Vector3d center;  // of the visible meshes' bounding box (metres)
  double radius = 1.0;     // half its diagonal
  Bounds meshes;           // that box; empty when no mesh is visible
  // Keeps what the drawn ground does not hide: the side of it the eye is on
  // (n, d: n.p + d >= 0 kept); everything when no ground is drawn.
  Eigen::Vector4f clip_plane = Eigen::Vector4f(0.0f, 0.0f, 0.0f, 1.0f);
  bool shadows = false;
  bool meshes_changed = false;  // some mesh was uploaded anew
  StudioLights lights;
  GroundLayout ground;
  Eigen::Matrix4f view_projection;  // world to clip, 4 by 4
  Eigen::Matrix4f projection;       // view to clip, 4 by 4
  bool occlusion = false;
  std::array<float, 3> background;  // linear
};

// What the shadow map was drawn from: while it stays the same and no mesh
// changed, so does the map, and the pass is skipped.
struct ShadowSource {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;  // 0: no map drawn yet
  Eigen::Vector3d to_light = Eigen::Vector3d::Zero();
  std::vector<bool> casts;  // per mesh slot

  bool operator==(const ShadowSource& other) const = default;
};

// The mesh programs of one frame (with or without shadows), lit alike.
struct MeshPrograms {
  ShaderProgram* plain;
  ShaderProgram* textured;
};

struct Renderer::Impl {
  // Declared first so it is destroyed last, after every GL object.
  GlContext context;
  RenderTarget target;
  ShadowMap shadow_map;
  std::unique_ptr<AmbientOcclusion> occlusion;  // null when the settings have none
  // Index: shadows + 2 * textured (the key light's shadow lookups, a base-colour map).
  std::array<ShaderProgram, 4> mesh_programs;
  std::array<ShaderProgram, 4> ground_programs;  // the floor's cell; index: shadows + 2 * grid
  std::array<ShaderProgram, 2> bare_ground_programs;  // around the cell, no lookups; index: grid
  ShaderProgram catcher_program;  // the ground over a transparent background
  ShaderProgram depth_program;
  ShaderProgram wire_program;
  Ground ground;
  std::vector<MeshBuffers> meshes;  // slot i draws scene.meshes[i]
  TextureCache textures;
  std::vector<Bounds> mesh_bounds;
  std::vector<size_t> transparent_order;
  ShadowSource shadow_source;
  std::size_t shadow_passes = 0;

  explicit Impl(const RenderSettings& s)
      : context(s.gl),
        target(s.width, s.height, s.msaa),
        shadow_map(shadow_map_size(s)),
        occlusion(s.ambient_occlusion ? std::make_unique<AmbientOcclusion>(s.width, s.height) : nullptr),
        mesh_programs{mesh_program(false, false, s), mesh_program(true, false, s), mesh_program(false, true, s),
                      mesh_program(true, true, s)},
        ground_programs{ground_program(false, false, s.ambient_occlusion), ground_program(true, false, s.ambient_occlusion),
                        ground_program(false, true, s.ambient_occlusion), ground_program(true, true, s.ambient_occlusion)},
        bare_ground_programs{ground_program(false, false, false), ground_program(false, true, false)},
        catcher_program("shadow catcher", shaders::ground_vertex(), shaders::shadow_catcher_fragment()),
        depth_program("depth", shaders::depth_vertex(), shaders::depth_fragment()),
        wire_program("wireframe", shaders::mesh_vertex(), shaders::flat_fragment()) {}

  void draw(const RenderSettings& settings, const RenderScene& scene, const Camera& camera, Image& image);
  Frame upload(const RenderSettings& settings, const RenderScene& scene, const Camera& camera);
  void shadow_pass(const RenderScene& scene, const Frame& frame);
  void occlusion_pass(const RenderSettings& settings, const RenderScene& scene, const Frame& frame);
  // The meshes whose opacity `accept` takes, with the bound depth-only program.
  template <typename Accept>
  void draw_depth(const RenderScene& scene, Accept accept);
  void set_common(ShaderProgram& p, const Frame& frame);
  void set_lighting(ShaderProgram& p, const Frame& frame, const Camera& camera);
  void draw_mesh(const RenderSettings& settings, const RenderMesh& mesh, const MeshBuffers& buffers,
                 const MeshPrograms& programs);
  void draw_ground(const RenderSettings& settings, const RenderScene& scene, const Frame& frame);
  void draw_shadow_catcher(const Frame& frame, const GroundLayout& g);
  void draw_transparent(const RenderSettings& settings, const RenderScene& scene, const Camera& camera,
                        const MeshPrograms& programs);
};

Renderer::Renderer(const RenderSettings& settings) : m_settings(settings) {
  validate(settings);
  m_impl = std::make_unique<Impl>(settings);
}

std::size_t Renderer::shadow_passes() const { return m_impl->shadow_passes; }

GlBackend Renderer::backend() const { return m_impl->context.backend(); }

std::string Renderer::gl_renderer() { return m_impl->context.renderer_name(); }

Renderer::~Renderer() {
  if (m_impl) m_impl->context.make_current();
}

Image Renderer::render(const RenderScene& scene, const Camera& camera) {
  Image image;
  render(scene, camera, image);
  return image;
}

void Renderer::render(const RenderScene& scene, const Camera& camera, Image& image) {
  validate(camera);
  m_impl->context.make_current();
  m_impl->draw(m_settings, scene, camera, image);
}

Frame Renderer::Impl::upload(const RenderSettings& settings, const RenderScene& scene, const Camera& camera) {
  // Every mesh is re-sent (new positions and normals each frame); the
  // bounds of the visible ones frame the shadow map, floor and depth range.
  meshes.resize(scene.meshes.size());
  mesh_bounds.resize(scene.meshes.size());
  Frame frame;
  Bounds scene_bounds;
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    if (meshes[i].upload(scene.meshes[i])) frame.meshes_changed = true;
    mesh_bounds[i] = bounds_of(scene.meshes[i].positions);
    if (scene.meshes[i].opacity > 0.0f && !scene.meshes[i].indices.empty()) scene_bounds.add(mesh_bounds[i]);
  }
  frame.center = camera.target;
  const double size = (scene_bounds.hi - scene_bounds.lo).norm();
  const bool has_meshes = !scene_bounds.empty() && std::isfinite(size);
  if (has_meshes) {
    frame.center = 0.5 * (scene_bounds.lo + scene_bounds.hi);
    frame.radius = std::max(0.5 * size, 1e-3);
    frame.meshes = scene_bounds;
  }
  if (scene.ground && settings.ground) {
    // What lies in the floor's plane rests on it, so it belongs to the upper
    // side: seen from below, the floor hides it (a hair's breadth of slack).
    const double h = scene.ground_height;
    const bool above = camera.eye.y() >= h;
    const double slack = above ? 0.0 : 1e-5 * std::max(frame.radius, std::abs(h));
    frame.clip_plane = above ? Eigen::Vector4f(0.0f, 1.0f, 0.0f, static_cast<float>(-h))
                             : Eigen::Vector4f(0.0f, -1.0f, 0.0f, static_cast<float>(h - slack));
  }
  frame.shadows = settings.shadows && has_meshes;
  frame.lights = studio_lights(camera);
  frame.ground = ground_layout(frame.center.x(), frame.center.z(), frame.radius, scene.ground_height);
  frame.background = srgb_to_linear(settings.background);

  const Eigen::Vector3d reach = Eigen::Vector3d::Constant(frame.radius);
  Bounds visible{frame.center - reach, frame.center + reach};
  if (scene.ground && settings.ground) {
    const GroundLayout& g = frame.ground;
    visible.add({Eigen::Vector3d(g.center_x - g.fade_end, g.height, g.center_z - g.fade_end),
                 Eigen::Vector3d(g.center_x + g.fade_end, g.height, g.center_z + g.fade_end)});
  }
  const DepthRange range = depth_range(camera, visible.lo, visible.hi);
  const double aspect = static_cast<double>(settings.width) / settings.height;
  const Eigen::Matrix4d projection = camera.projection_matrix(aspect, range.near_plane, range.far_plane);
  frame.projection = projection.cast<float>();
  frame.view_projection = (projection * camera.view_matrix()).cast<float>();
  frame.occlusion = occlusion != nullptr && has_meshes;
  return frame;
}

void Renderer::Impl::shadow_pass(const RenderScene& scene, const Frame& frame) {
  // Every visible mesh casts; the floor only receives.
  ShadowSource source{frame.center, frame.radius, frame.lights.key.to_light, {}};
  for (const RenderMesh& mesh : scene.meshes) source.casts.push_back(mesh.opacity > 0.0f);
  if (!frame.meshes_changed && source == shadow_source) return;
  shadow_source = std::move(source);
  ++shadow_passes;
  const Eigen::Matrix4f light_clip = shadow_map.begin(frame.center, frame.radius, frame.lights.key.to_light);
  glClear(GL_DEPTH_BUFFER_BIT);
  // Slope-scaled offset keeps lit surfaces from shadowing themselves (acne).
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 2.0f);
  depth_program.use();
  set(depth_program, "u_view_projection", light_clip);
  draw_depth(scene, [](float opacity) { return opacity > 0.0f; });
  glDisable(GL_POLYGON_OFFSET_FILL);
}

double occlusion_reach(const Frame& frame) { return kOcclusionReach * frame.radius; }

template <typename Accept>
void Renderer::Impl::draw_depth(const RenderScene& scene, Accept accept) {
  // A closed mesh's back faces are hidden by its front faces.
  glCullFace(GL_BACK);
  for (size_t i = 0; i < meshes.size(); ++i) {
    if (!accept(scene.meshes[i].opacity)) continue;
    // The coarser copy may fold a few triangles over: drawn from both sides, it leaves no hole.
    set_culling(meshes[i].closed() && !meshes[i].has_depth_copy());
    meshes[i].draw_depth();
  }
  set_culling(false);
}

void Renderer::Impl::occlusion_pass(const RenderSettings& settings, const RenderScene& scene, const Frame& frame) {
  // What the lighting passes see opaque: the opaque meshes and the floor.
  // A point's taps reach twice the reach from the meshes' box at most.
  const Eigen::Vector3d taps_reach = Eigen::Vector3d::Constant(2.0 * occlusion_reach(frame));
  occlusion->begin_depth(occlusion->region_around(frame.meshes.lo - taps_reach, frame.meshes.hi + taps_reach,
                                                  frame.view_projection));
  depth_program.use();
  set(depth_program, "u_view_projection", frame.view_projection);
  draw_depth(scene, [](float opacity) { return opacity >= kOpaque; });
  if (scene.ground && settings.ground) ground.draw(frame.ground);
  occlusion->resolve(frame.projection, static_cast<float>(occlusion_reach(frame)));
}

void Renderer::Impl::set_common(ShaderProgram& p, const Frame& frame) {
  p.use();
  set(p, "u_view_projection", frame.view_projection);
  set(p, "u_light_matrix", shadow_map.texture_matrix());
  set(p, "u_normal_offset", static_cast<float>(kNormalOffsetTexels * shadow_map.texel_world()));
  set(p, "u_shadow_map", static_cast<int>(kShadowUnit - GL_TEXTURE0));
  const float texel = 1.0f / static_cast<float>(shadow_map.size());
  glUniform2f(p.location("u_shadow_texel"), texel, texel);
  if (occlusion) {
    set(p, "u_ao", static_cast<int>(kOcclusionUnit - GL_TEXTURE0));
    glUniform2f(p.location("u_frame_size"), static_cast<float>(occlusion->frame_width()),
                static_cast<float>(occlusion->frame_height()));
    set(p, "u_ao_weight", frame.occlusion ? 1.0f : 0.0f);
  }
}

void Renderer::Impl::set_lighting(ShaderProgram& p, const Frame& frame, const Camera& camera) {
  set_common(p, frame);
  const StudioLights& lights = frame.lights;
  set(p, "u_eye", camera.eye);
  set(p, "u_key_dir", lights.key.to_light);
  set(p, "u_fill_dir", lights.fill.to_light);
  set(p, "u_rim_dir", lights.rim.to_light);
  set(p, "u_key_color", lights.key.color);
  set(p, "u_fill_color", lights.fill.color);
  set(p, "u_rim_color", lights.rim.color);
  set(p, "u_sky_ambient", lights.sky_ambient);
  set(p, "u_ground_ambient", lights.ground_ambient);
  glUniform4fv(p.location("u_clip_plane"), 1, frame.clip_plane.data());
}

void Renderer::Impl::draw_mesh(const RenderSettings& settings, const RenderMesh& mesh, const MeshBuffers& buffers,
                               const MeshPrograms& programs) {
  const std::array<float, 3> albedo = srgb_to_linear(mesh.color);
  const float opacity = std::clamp(mesh.opacity, 0.0f, 1.0f);
  if (settings.wireframe) {
    // Push the faces back so the edges drawn next win the depth test.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
  }
  if (buffers.groups().empty()) {
    programs.plain->use();
    set(*programs.plain, "u_albedo", Eigen::Vector3f(albedo[0], albedo[1], albedo[2]));
    set(*programs.plain, "u_opacity", opacity);
    set_shading(*programs.plain, SurfaceShading{});
    buffers.draw();
  } else {
    // The look's vertex colours are the whole albedo.
    for (const MeshBuffers::Group& group : buffers.groups()) {
      ShaderProgram& program = group.texture ? *programs.textured : *programs.plain;
      program.use();
      set(program, "u_albedo", Eigen::Vector3f(1.0f, 1.0f, 1.0f));
      set(program, "u_opacity", opacity);
      set_shading(program, group.shading);
      if (group.texture) {
        glActiveTexture(kMaterialUnit);
        textures.bind(group.texture);
        glActiveTexture(GL_TEXTURE0);
        set(program, "u_texture", static_cast<int>(kMaterialUnit - GL_TEXTURE0));
      }
      buffers.draw(group);
    }
  }
  if (settings.wireframe) {
    glDisable(GL_POLYGON_OFFSET_FILL);
    wire_program.use();
    // Edges in a fifth of the body's colour, premultiplied like the faces.
    glUniform4f(wire_program.location("u_color"), 0.2f * albedo[0] * opacity, 0.2f * albedo[1] * opacity,
                0.2f * albedo[2] * opacity, opacity);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    buffers.draw();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }
}

void Renderer::Impl::draw_ground(const RenderSettings& settings, const RenderScene& scene, const Frame& frame) {
  // Shadow and occlusion lookups run on the floor's cell that a shadow or
  // the occlusion can reach; around it they would return "open" anyway.
  GroundLayout g = frame.ground;
  // A shadow catcher (transparent background) draws the shadow alone.
  const bool occluded = frame.occlusion && !settings.transparent_background;
  const bool lookups = frame.shadows || occluded;
  if (lookups) {
    std::optional<FloorRect> cell =
        occluded ? std::optional(near_reach(frame.meshes.lo, frame.meshes.hi, occlusion_reach(frame))) : std::nullopt;
    bool whole = false;
    if (frame.shadows) {
      const std::optional<FloorRect> shadow = shadow_reach(g.height, frame.center, frame.radius,
                                                           frame.lights.key.to_light,
                                                           kShadowReachTexels * shadow_map.texel_world());
      whole = !shadow;
      if (shadow) cell = cell ? cell->united(*shadow) : *shadow;
    }
    if (!whole) set_cell(g, *cell);
  }
  if (settings.transparent_background) {
    draw_shadow_catcher(frame, g);
    return;
  }
  // The floor is flat and the lights directional, so its lighting is two
  // constants: the key's share (shadowed per pixel) and the rest.
  const StudioLights& lights = frame.lights;
  const Eigen::Vector3f key_light = lights.key.color * static_cast<float>(std::max(lights.key.to_light.y(), 0.0));
  const Eigen::Vector3f other_light =
      lights.fill.color * static_cast<float>(std::max(lights.fill.to_light.y(), 0.0)) + lights.sky_ambient;
  auto use = [&](ShaderProgram& p) {
    set_common(p, frame);
    set(p, "u_key_light", key_light);
    set(p, "u_other_light", other_light);
    set(p, "u_albedo", Eigen::Vector3f(0.15f, 0.155f, 0.16f));
    set(p, "u_line_albedo", Eigen::Vector3f(0.26f, 0.27f, 0.28f));
    glUniform2f(p.location("u_center"), static_cast<float>(g.center_x), static_cast<float>(g.center_z));
    glUniform2f(p.location("u_fade"), static_cast<float>(g.fade_start), static_cast<float>(g.fade_end));
    set(p, "u_spacing", static_cast<float>(g.grid_spacing));
    glUniform4f(p.location("u_background"), frame.background[0], frame.background[1], frame.background[2], 1.0f);
  };
  ShaderProgram& bare = bare_ground_programs[scene.grid ? 1 : 0];
  if (lookups) {
    use(ground_programs[(frame.shadows ? 1 : 0) + (scene.grid ? 2 : 0)]);
    ground.draw_cell(g);
    use(bare);
    ground.draw_surround(g);
  } else {
    use(bare);
    ground.draw(g);
  }
}

void Renderer::Impl::draw_shadow_catcher(const Frame& frame, const GroundLayout& g) {
  if (!frame.shadows) return;  // nothing to catch
  ShaderProgram& p = catcher_program;
  set_common(p, frame);
  // The share of the lit floor's light that a shadow takes away (luminance).
  const StudioLights& lights = frame.lights;
  const Eigen::Vector3f luma(0.2126f, 0.7152f, 0.0722f);
  const float key = luma.dot(lights.key.color) * static_cast<float>(std::max(lights.key.to_light.y(), 0.0));
  const float other = luma.dot(lights.fill.color) * static_cast<float>(std::max(lights.fill.to_light.y(), 0.0)) +
                      luma.dot(lights.sky_ambient);
  set(p, "u_shadow_strength", key + other > 0.0f ? key / (key + other) : 0.0f);
  glUniform2f(p.location("u_center"), static_cast<float>(g.center_x), static_cast<float>(g.center_z));
  glUniform2f(p.location("u_fade"), static_cast<float>(g.fade_start), static_cast<float>(g.fade_end));
  // Around the cell it would only draw the transparent clear colour again.
  ground.draw_cell(g);
}

void Renderer::Impl::draw_transparent(const RenderSettings& settings, const RenderScene& scene,
                                      const Camera& camera, const MeshPrograms& programs) {
  // Farthest first (by bounding-box centre depth, ties by index), without
  // depth writes; each mesh draws its back faces, then its front faces,
  // which orders a convex body's own layers correctly.
  const Eigen::Vector3d forward = (camera.target - camera.eye).normalized();
  transparent_order.clear();
  for (size_t i = 0; i < meshes.size(); ++i) {
    if (scene.meshes[i].opacity > 0.0f && scene.meshes[i].opacity < kOpaque) transparent_order.push_back(i);
  }
  if (transparent_order.empty()) return;
  auto depth_of = [&](size_t i) { return (0.5 * (mesh_bounds[i].lo + mesh_bounds[i].hi) - camera.eye).dot(forward); };
  std::stable_sort(transparent_order.begin(), transparent_order.end(),
                   [&](size_t a, size_t b) { return depth_of(a) > depth_of(b); });
  // They are not in the occlusion's depth, which shows what lies behind them.
  for (ShaderProgram* program : {programs.plain, programs.textured}) {
    program->use();
    set(*program, "u_ao_weight", 0.0f);
  }
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied colour
  glDepthMask(GL_FALSE);
  glEnable(GL_CULL_FACE);
  for (size_t i : transparent_order) {
    glCullFace(GL_FRONT);
    draw_mesh(settings, scene.meshes[i], meshes[i], programs);
    glCullFace(GL_BACK);
    draw_mesh(settings, scene.meshes[i], meshes[i], programs);
  }
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

void Renderer::Impl::draw(const RenderSettings& settings, const RenderScene& scene, const Camera& camera,
                          Image& image) {
  const Frame frame = upload(settings, scene, camera);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);  // a back face on a silhouette must not replace the front face it meets
  glDepthMask(GL_TRUE);
  if (frame.shadows) shadow_pass(scene, frame);
  if (frame.occlusion) occlusion_pass(settings, scene, frame);
  glEnable(GL_FRAMEBUFFER_SRGB);  // linear in the shaders, sRGB bytes in memory
  shadow_map.bind_texture(kShadowUnit);
  if (occlusion) occlusion->bind_texture(kOcclusionUnit);

  // The frame layer: the background and the floor, its rim fading into the
  // background colour. The floor hides nothing here: what lies beyond it is
  // cut from the meshes by the clip plane instead.
  target.bind_frame();
  if (settings.transparent_background) {
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  } else {
    glClearColor(frame.background[0], frame.background[1], frame.background[2], 1.0f);
  }
  glClear(GL_COLOR_BUFFER_BIT);
  if (scene.ground && settings.ground) draw_ground(settings, scene, frame);

  // The meshes' layer, only where they can show, then laid over the frame.
  const ScreenRect rect = frame.meshes.empty() ? ScreenRect{}
                                               : screen_rect(frame.meshes.lo, frame.meshes.hi, frame.view_projection,
                                                             settings.width, settings.height, kMeshRectPad);
  if (!rect.empty()) {
    target.begin_meshes(rect);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CLIP_DISTANCE0);
    const MeshPrograms programs{&mesh_programs[frame.shadows ? 1 : 0], &mesh_programs[frame.shadows ? 3 : 2]};
    set_lighting(*programs.plain, frame, camera);
    if (std::any_of(meshes.begin(), meshes.end(), [](const MeshBuffers& m) { return !m.groups().empty(); }))
      set_lighting(*programs.textured, frame, camera);
    if (settings.wireframe) {
      wire_program.use();
      set(wire_program, "u_view_projection", frame.view_projection);
      glUniform4fv(wire_program.location("u_clip_plane"), 1, frame.clip_plane.data());
    }
    // Opaque meshes first, with no blending; closed ones without their back
    // faces, which llvmpipe would otherwise set up and depth-test for nothing.
    glCullFace(GL_BACK);
    for (size_t i = 0; i < meshes.size(); ++i) {
      if (scene.meshes[i].opacity < kOpaque) continue;
      set_culling(meshes[i].closed());
      draw_mesh(settings, scene.meshes[i], meshes[i], programs);
    }
    set_culling(false);
    draw_transparent(settings, scene, camera, programs);
    glDisable(GL_CLIP_DISTANCE0);
    target.lay_meshes_over_frame(rect, kLayerUnit);
  }

  target.read(image);
  if (settings.transparent_background) unpremultiply_srgb(image);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  // Our calls are valid by construction, so an error here is the driver
  // running out of memory (or a bug): either way the frame is not trustworthy.
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    throw Error(ErrorKind::internal, "OpenGL error 0x" + hex(error) + " while rendering a frame of " +
                                         std::to_string(scene.meshes.size()) + " meshes");
  }
}

}  // namespace recoil::render
