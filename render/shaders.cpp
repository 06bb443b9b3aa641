#include "render/shaders.h"

namespace recoil::render::shaders {
namespace {

// Shared by meshes and the ground: the key light's shadow lookup.
const char* const kShadow = R"(
uniform sampler2DShadow u_shadow_map;
uniform vec2 u_shadow_texel;  // one texel in shadow-map coordinates

// Fraction of the key light reaching a point: four bilinear-PCF taps (each
// compares 2x2 texels in hardware), which smooths the edge over ~3 texels.
float key_visibility(vec4 shadow_coord) {
#ifdef SHADOWS
  vec3 p = shadow_coord.xyz;
  vec2 d = 0.75 * u_shadow_texel;
  return 0.25 * (texture(u_shadow_map, vec3(p.xy + vec2(-d.x, -d.y), p.z)) +
                 texture(u_shadow_map, vec3(p.xy + vec2(d.x, -d.y), p.z)) +
                 texture(u_shadow_map, vec3(p.xy + vec2(-d.x, d.y), p.z)) +
                 texture(u_shadow_map, vec3(p.xy + vec2(d.x, d.y), p.z)));
#else
  return 1.0;
#endif
}
)";

// Shared by meshes and the ground: the ambient occlusion at this pixel
// (render/ambient_occlusion.h), half the frame's size, read bilinear.
const char* const kAmbientOcclusion = R"(
#ifdef AMBIENT_OCCLUSION
uniform sampler2D u_ao;
uniform vec2 u_frame_size;  // pixels
uniform float u_ao_weight;  // 1, or 0 where the surface is not in the occlusion's depth (transparent)
float ambient_visibility() {
  return mix(1.0, texture(u_ao, gl_FragCoord.xy / u_frame_size).r, u_ao_weight);
}
#else
float ambient_visibility() { return 1.0; }
#endif
)";

// Meshes: three-point lighting (key, fill, rim) with a hemisphere ambient
// and a Blinn-Phong highlight of the key.
const char* const kStudio = R"(
uniform vec3 u_eye;
uniform vec3 u_key_dir;     // unit vectors towards each light, world space
uniform vec3 u_fill_dir;
uniform vec3 u_rim_dir;
uniform vec3 u_key_color;   // linear radiance scale of each light
uniform vec3 u_fill_color;
uniform vec3 u_rim_color;
uniform vec3 u_sky_ambient;
uniform vec3 u_ground_ambient;
uniform float u_metallic;   // the material's (render/surface_shading.h)
uniform float u_shininess;
uniform float u_highlight;
const float kSpecular = 0.25;

// Radiance leaving a surface (linear) lit by the rig; n unit, facing the
// viewer; `visibility` of the key light, `open` of the broad fill and ambient.
vec3 studio_light(vec3 albedo, vec3 n, vec3 world, float visibility, float open) {
  float key = max(dot(n, u_key_dir), 0.0) * visibility;
  float fill = max(dot(n, u_fill_dir), 0.0);
  float rim = max(dot(n, u_rim_dir), 0.0);
  vec3 ambient = mix(u_ground_ambient, u_sky_ambient, 0.5 + 0.5 * n.y);
  vec3 color = (albedo * (1.0 - u_metallic)) *
               (u_key_color * key + (u_fill_color * fill + ambient) * open + u_rim_color * rim);
  vec3 v = normalize(u_eye - world);
  vec3 mirrored = reflect(-v, n);
  color += (u_metallic * albedo * open) * mix(u_ground_ambient, u_sky_ambient, 0.5 + 0.5 * mirrored.y);
  vec3 h = normalize(u_key_dir + v);
  float highlight = pow(max(dot(n, h), 0.0), u_shininess) * u_highlight * float(key > 0.0);
  return color + (mix(vec3(kSpecular), albedo, u_metallic) * highlight * visibility) * u_key_color;
}
)";

const char* const kHeader = "#version 330 core\n";

// llvmpipe runs both sides of a branch on a uniform, texture taps included,
// so shadowed and unshadowed programs are compiled separately.
std::string fragment_header(bool shadows, bool occlusion = false) {
  return std::string(kHeader) + (shadows ? "#define SHADOWS 1\n" : "") +
         (occlusion ? "#define AMBIENT_OCCLUSION 1\n" : "");
}

}  // namespace

std::string mesh_vertex() {
  return std::string(kHeader) + R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;  // linear; white where the mesh has one colour (u_albedo)
layout(location = 3) in vec2 a_uv;
uniform mat4 u_view_projection;
uniform mat4 u_light_matrix;     // world to shadow-map [0,1]^3
uniform float u_normal_offset;   // metres; pushes lookups off the surface against acne
out vec3 v_world;
out vec3 v_normal;
out vec4 v_shadow;
out vec3 v_color;
out vec2 v_uv;
void main() {
  v_world = a_position;
  v_normal = a_normal;
  v_color = a_color;
  v_uv = a_uv;
  v_shadow = u_light_matrix * vec4(a_position + u_normal_offset * a_normal, 1.0);
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";
}

std::string mesh_fragment(bool shadows, bool textured, bool occlusion) {
  return fragment_header(shadows, occlusion) + (textured ? "#define TEXTURED 1\n" : "") + kShadow +
         kAmbientOcclusion + kStudio + R"(
in vec3 v_world;
in vec3 v_normal;
in vec4 v_shadow;
in vec3 v_color;
in vec2 v_uv;
uniform vec3 u_albedo;     // linear
uniform float u_opacity;
#ifdef TEXTURED
uniform sampler2D u_texture;  // sRGB texels read as linear; rows stored top first, so v runs down
#endif
out vec4 o_color;
void main() {
  vec3 n = normalize(v_normal);
  // Open or inward-facing surfaces are lit from the side we see.
  if (!gl_FrontFacing) n = -n;
  vec3 albedo = u_albedo * v_color;
#ifdef TEXTURED
  albedo *= texture(u_texture, vec2(v_uv.x, 1.0 - v_uv.y)).rgb;
#endif
  vec3 color = studio_light(albedo, n, v_world, key_visibility(v_shadow), ambient_visibility());
  o_color = vec4(color * u_opacity, u_opacity);
}
)";
}

std::string ground_vertex() {
  return std::string(kHeader) + R"(
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
uniform mat4 u_light_matrix;
uniform float u_normal_offset;
out vec3 v_world;
out vec4 v_shadow;
void main() {
  v_world = a_position;
  v_shadow = u_light_matrix * vec4(a_position + vec3(0.0, u_normal_offset, 0.0), 1.0);
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";
}

std::string ground_fragment(bool shadows, bool grid, bool occlusion) {
  return fragment_header(shadows, occlusion) + (grid ? "#define GRID 1\n" : "") + kShadow + kAmbientOcclusion + R"(
in vec3 v_world;
in vec4 v_shadow;
uniform vec3 u_albedo;       // linear ground colour
uniform vec3 u_line_albedo;  // linear colour of the major grid lines
uniform vec3 u_key_light;    // irradiance on the flat floor from the key (shadowed)...
uniform vec3 u_other_light;  // ... and from fill and sky (the rim light aims at the subject only)
uniform vec2 u_center;       // scene centre on the ground (x, z)
uniform vec2 u_fade;         // the floor fades out between these radii (metres)
uniform float u_spacing;     // major grid spacing (metres); minor lines every tenth
uniform vec4 u_background;   // linear, premultiplied: the clear colour under the floor
out vec4 o_color;

// Coverage of the lines through integer `cell` coordinates, `half_width`
// cells wide each side, antialiased over `pixel` (cells per pixel) and faded
// out before they crowd into moire.
float grid_lines(vec2 cell, vec2 pixel, float half_width) {
  vec2 distance_to_line = abs(fract(cell + 0.5) - 0.5);
  vec2 coverage = 1.0 - smoothstep(vec2(half_width) - pixel, vec2(half_width) + pixel, distance_to_line);
  return max(coverage.x, coverage.y) * (1.0 - smoothstep(0.08, 0.25, max(pixel.x, pixel.y)));
}

void main() {
  vec3 albedo = u_albedo;
  float r = length(v_world.xz - u_center);
#ifdef GRID
  vec2 cell = v_world.xz / u_spacing;
  vec2 pixel = fwidth(cell);
  float minor = grid_lines(10.0 * cell, 10.0 * pixel, 0.03);
  float major = grid_lines(cell, pixel, 0.006);
  // Lines fade with distance before the floor itself does.
  float line = max(0.4 * minor, major) * (1.0 - smoothstep(0.2 * u_fade.y, 0.8 * u_fade.y, r));
  albedo = mix(albedo, u_line_albedo, line);
#endif
  vec3 color = albedo * (u_other_light * ambient_visibility() + u_key_light * key_visibility(v_shadow));
  // Composited over the clear colour here rather than by GL blending, which
  // on llvmpipe costs as much again as this whole shader.
  float alpha = 1.0 - smoothstep(u_fade.x, u_fade.y, r);
  o_color = vec4(color * alpha, alpha) + (1.0 - alpha) * u_background;
}
)";
}

std::string shadow_catcher_fragment() {
  return fragment_header(true) + kShadow + R"(
in vec3 v_world;
in vec4 v_shadow;
uniform vec2 u_center;           // scene centre on the ground (x, z)
uniform vec2 u_fade;             // shadows fade out between these radii (metres), as the floor would
uniform float u_shadow_strength; // the share of the floor's light the key gives
out vec4 o_color;

// Only the darkening a floor would show under the key's shadow, as black of
// that coverage (premultiplied) over the transparent clear colour.
void main() {
  float r = length(v_world.xz - u_center);
  float fade = 1.0 - smoothstep(u_fade.x, u_fade.y, r);
  float shadow = u_shadow_strength * (1.0 - key_visibility(v_shadow)) * fade;
  o_color = vec4(0.0, 0.0, 0.0, shadow);
}
)";
}

std::string fullscreen_vertex() {
  return std::string(kHeader) + R"(
// One triangle whose corners (-1,-1), (3,-1), (-1,3) cover the viewport.
void main() {
  vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
}
)";
}

std::string occlusion_fragment() {
  return std::string(kHeader) + R"(
uniform sampler2D u_depth;          // window depth, this pass's size
uniform mat4 u_projection;          // view to clip
uniform mat4 u_inverse_projection;  // clip to view
uniform float u_radius;             // metres the hemisphere reaches
uniform vec2 u_size;                // pixels of this pass
out vec4 o_color;                   // R: the share of the hemisphere that is open

// Points in the unit hemisphere (z along the normal), more of them near the
// surface, where creases and contacts are.
const vec3 kPoints[12] = vec3[](
  vec3(0.10, 0.02, 0.06), vec3(-0.05, 0.12, 0.10), vec3(-0.17, -0.08, 0.06), vec3(0.06, -0.24, 0.14),
  vec3(0.32, 0.10, 0.12), vec3(-0.12, 0.36, 0.20), vec3(-0.45, -0.05, 0.22), vec3(0.05, -0.52, 0.20),
  vec3(0.50, 0.36, 0.30), vec3(-0.40, 0.56, 0.35), vec3(-0.62, -0.48, 0.30), vec3(0.30, -0.70, 0.45));
// A 4x4 ordered-dither permutation: neighbouring pixels turn the points far apart.
const float kTurn[16] = float[](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);

float view_depth(float window_depth) {
  // z_ndc = (A z + B) / -z, solved for the view-space z (negative ahead).
  return -u_projection[3][2] / ((2.0 * window_depth - 1.0) + u_projection[2][2]);
}

void main() {
  vec2 uv = gl_FragCoord.xy / u_size;
  float depth = texture(u_depth, uv).r;
  vec4 h = u_inverse_projection * vec4(2.0 * vec3(uv, depth) - 1.0, 1.0);
  vec3 p = h.xyz / h.w;
  vec3 n = normalize(cross(dFdx(p), dFdy(p)));
  ivec2 cell = ivec2(gl_FragCoord.xy) & 3;
  float turn = (kTurn[cell.x + 4 * cell.y] + 0.5) * (6.2831853 / 16.0);
  vec3 r = vec3(cos(turn), sin(turn), 0.0);
  vec3 t = normalize(r - n * dot(r, n) + vec3(0.0, 0.0, 1e-4));
  vec3 b = cross(n, t);
  float closed = 0.0;
  for (int i = 0; i < 12; ++i) {
    vec3 q = p + u_radius * (kPoints[i].x * t + kPoints[i].y * b + kPoints[i].z * n);
    vec4 c = u_projection * vec4(q, 1.0);
    float scene_z = view_depth(texture(u_depth, 0.5 * c.xy / c.w + 0.5).r);
    // Blocked if the surface seen there is in front of the point, unless it
    // is far in front (another object across a depth gap).
    float near_enough = smoothstep(0.0, 1.0, u_radius / max(abs(p.z - scene_z), 1e-6));
    closed += (scene_z > q.z + 0.02 * u_radius ? 1.0 : 0.0) * near_enough;
  }
  o_color = vec4(depth < 1.0 ? 1.0 - closed / 12.0 : 1.0);
}
)";
}

std::string box_blur_fragment() {
  return std::string(kHeader) + R"(
uniform sampler2D u_source;  // bilinear
uniform vec2 u_texel;        // one texel in texture coordinates
out vec4 o_color;
// The mean of the 4x4 texels around this one: four bilinear taps, each on
// the corner between four texels.
void main() {
  vec2 uv = gl_FragCoord.xy * u_texel;
  o_color = vec4(0.25 * (texture(u_source, uv + vec2(-0.5, -0.5) * u_texel).r +
                         texture(u_source, uv + vec2(1.5, -0.5) * u_texel).r +
                         texture(u_source, uv + vec2(-0.5, 1.5) * u_texel).r +
                         texture(u_source, uv + vec2(1.5, 1.5) * u_texel).r));
}
)";
}

std::string depth_vertex() {
  return std::string(kHeader) + R"(
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
void main() { gl_Position = u_view_projection * vec4(a_position, 1.0); }
)";
}

std::string depth_fragment() {
  return std::string(kHeader) + R"(
void main() {}
)";
}

std::string flat_fragment() {
  return std::string(kHeader) + R"(
uniform vec4 u_color;  // linear, premultiplied
out vec4 o_color;
void main() { o_color = u_color; }
)";
}

}  // namespace recoil::render::shaders
