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
// viewer; `visibility`: the key light's share that is not shadowed; `open`:
// the ambient occlusion's open share, which dims all diffuse light and a
// metal's reflected ambient, as a crease would in a soft-lit studio; the
// key's highlight is left alone.
vec3 studio_light(vec3 albedo, vec3 n, vec3 world, float visibility, float open) {
  float key = max(dot(n, u_key_dir), 0.0) * visibility;
  float fill = max(dot(n, u_fill_dir), 0.0);
  float rim = max(dot(n, u_rim_dir), 0.0);
  vec3 ambient = mix(u_ground_ambient, u_sky_ambient, 0.5 + 0.5 * n.y);
  vec3 color = (albedo * (1.0 - u_metallic) * open) *
               (u_key_color * key + u_fill_color * fill + u_rim_color * rim + ambient);
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
uniform vec3 u_key_dir;          // unit, world space, towards the key light
uniform vec4 u_clip_plane;       // (n, d): what has n.p + d < 0 is hidden by the ground, and cut away
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
  // Off the side the key lights, whichever way the mesh is wound: a surface
  // wound inward pushed its lookups into itself and shadowed itself in stripes.
  vec3 lit_side = dot(a_normal, u_key_dir) < 0.0 ? -a_normal : a_normal;
  v_shadow = u_light_matrix * vec4(a_position + u_normal_offset * lit_side, 1.0);
  gl_ClipDistance[0] = dot(u_clip_plane, vec4(a_position, 1.0));
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
  vec3 color = albedo * ambient_visibility() * (u_other_light + u_key_light * key_visibility(v_shadow));
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
uniform sampler2D u_depth;  // window depth, this pass's size
uniform mat4 u_projection;  // view to clip (a symmetric perspective)
uniform float u_radius;     // metres the occlusion reaches
uniform vec2 u_size;        // pixels of this pass
out vec4 o_color;           // R: the share of the hemisphere that is open

const int kTaps = 12;
// Tap i at (i + 0.5) / 12 of the reach, on a spiral of two and a half turns.
const vec2 kSpiral[kTaps] = vec2[](
  vec2(0.0331, 0.0254), vec2(-0.0478, 0.1155), vec2(-0.2066, -0.0272), vec2(-0.0381, -0.2892),
  vec2(0.3465, -0.1435), vec2(0.2790, 0.3636), vec2(-0.3297, 0.4297), vec2(-0.5774, -0.2392),
  vec2(0.0925, -0.7023), vec2(0.7849, -0.1033), vec2(0.3348, 0.8084), vec2(-0.7603, 0.5834));
// A 4x4 ordered-dither permutation: neighbouring pixels turn the taps far apart.
const float kTurn[16] = float[](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);

// The view-space point seen at `texel` (its centre).
vec3 seen_at(ivec2 texel) {
  float window_depth = texelFetch(u_depth, texel, 0).r;
  // z_ndc = (A z + B) / -z, solved for the view-space z (negative ahead).
  float z = -u_projection[3][2] / ((2.0 * window_depth - 1.0) + u_projection[2][2]);
  vec2 ndc = 2.0 * (vec2(texel) + 0.5) / u_size - 1.0;
  return vec3(-z * ndc.x / u_projection[0][0], -z * ndc.y / u_projection[1][1], z);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(u_depth, pixel, 0).r;
  vec3 p = seen_at(pixel);
  vec3 n = normalize(cross(dFdx(p), dFdy(p)));
  // The reach in this pass's pixels at p's distance, at least one ring of texels.
  float reach = max(u_radius * u_projection[1][1] * 0.5 * u_size.y / -p.z, 2.0);
  ivec2 cell = pixel & 3;
  float turn = (kTurn[cell.x + 4 * cell.y] + 0.5) * (6.2831853 / 16.0);
  mat2 rotation = reach * mat2(cos(turn), sin(turn), -sin(turn), cos(turn));
  // Taps on the spiral, turned; each surface point found there closes
  // the hemisphere by how far it rises above p's tangent plane (the cosine of
  // its direction to the normal), fading out beyond the reach. A plane closes
  // nothing, at any resolution and any angle.
  float closed = 0.0;
  for (int i = 0; i < kTaps; ++i) {
    ivec2 texel = clamp(pixel + ivec2(rotation * kSpiral[i]), ivec2(0), ivec2(u_size) - 1);
    vec3 v = seen_at(texel) - p;
    float distance2 = dot(v, v);
    float rise = dot(v, n) * inversesqrt(distance2 + 1e-12);
    closed += max(rise - 0.1, 0.0) * max(1.0 - distance2 / (u_radius * u_radius), 0.0);
  }
  o_color = vec4(depth < 1.0 ? clamp(1.0 - 3.0 * closed / float(kTaps), 0.0, 1.0) : 1.0);
}
)";
}

std::string box_blur_fragment() {
  return std::string(kHeader) + R"(
uniform sampler2D u_source;  // bilinear
uniform vec2 u_texel;        // one texel in texture coordinates
out vec4 o_color;
// The mean of the 4x4 texels from one below to two above this one in x and
// y (a 4-wide box has no centre texel): four bilinear taps, each on the
// corner between four texels.
void main() {
  vec2 uv = gl_FragCoord.xy * u_texel;
  o_color = vec4(0.25 * (texture(u_source, uv + vec2(-0.5, -0.5) * u_texel).r +
                         texture(u_source, uv + vec2(1.5, -0.5) * u_texel).r +
                         texture(u_source, uv + vec2(-0.5, 1.5) * u_texel).r +
                         texture(u_source, uv + vec2(1.5, 1.5) * u_texel).r));
}
)";
}

std::string lay_over_fragment(int samples) {
  const std::string layer = samples > 0 ? "uniform sampler2DMS u_layer;\nconst int kSamples = " +
                                              std::to_string(samples) + ";\n"
                                        : "uniform sampler2D u_layer;\nconst int kSamples = 1;\n";
  return std::string(kHeader) + layer + R"(
out vec4 o_color;
// The mean of this pixel's samples, each decoded from sRGB to linear on fetch.
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 sum = vec4(0.0);
  for (int i = 0; i < kSamples; ++i) sum += texelFetch(u_layer, pixel, i);
  o_color = sum / float(kSamples);
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
