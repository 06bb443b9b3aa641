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

// Radiance leaving a surface (linear) lit by the rig; n unit, facing the viewer.
vec3 studio_light(vec3 albedo, vec3 n, vec3 world, float visibility) {
  float key = max(dot(n, u_key_dir), 0.0) * visibility;
  float fill = max(dot(n, u_fill_dir), 0.0);
  float rim = max(dot(n, u_rim_dir), 0.0);
  vec3 ambient = mix(u_ground_ambient, u_sky_ambient, 0.5 + 0.5 * n.y);
  vec3 color = (albedo * (1.0 - u_metallic)) * (u_key_color * key + u_fill_color * fill + u_rim_color * rim + ambient);
  vec3 v = normalize(u_eye - world);
  vec3 mirrored = reflect(-v, n);
  color += (u_metallic * albedo) * mix(u_ground_ambient, u_sky_ambient, 0.5 + 0.5 * mirrored.y);
  vec3 h = normalize(u_key_dir + v);
  float highlight = pow(max(dot(n, h), 0.0), u_shininess) * u_highlight * float(key > 0.0);
  return color + (mix(vec3(kSpecular), albedo, u_metallic) * highlight * visibility) * u_key_color;
}
)";

const char* const kHeader = "#version 330 core\n";

// llvmpipe runs both sides of a branch on a uniform, texture taps included,
// so shadowed and unshadowed programs are compiled separately.
std::string fragment_header(bool shadows) {
  return std::string(kHeader) + (shadows ? "#define SHADOWS 1\n" : "");
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

std::string mesh_fragment(bool shadows, bool textured) {
  return fragment_header(shadows) + (textured ? "#define TEXTURED 1\n" : "") + kShadow + kStudio + R"(
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
  vec3 color = studio_light(albedo, n, v_world, key_visibility(v_shadow));
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

std::string ground_fragment(bool shadows, bool grid) {
  return fragment_header(shadows) + (grid ? "#define GRID 1\n" : "") + kShadow + R"(
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
  vec3 color = albedo * (u_other_light + u_key_light * key_visibility(v_shadow));
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
