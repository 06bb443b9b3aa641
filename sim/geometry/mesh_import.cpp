// With look_import.cpp, the only files in recoil that include assimp.
#include "sim/geometry/mesh_import.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <assimp/Importer.hpp>
#include <cmath>
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <vector>

#include "core/byte_stream.h"
#include "core/check.h"
#include "core/error.h"
#include "core/lower_case.h"
#include "core/regular_file.h"
#include "sim/geometry/isolated_reader.h"
#include "sim/geometry/look_import.h"
#include "sim/geometry/mesh_header.h"
#include "sim/geometry/mesh_stats.h"

namespace recoil::sim {
namespace fs = std::filesystem;

namespace {

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return out;
}

// What collect() gathers: the merged surface and, per triangle, its look.
struct Gathered {
  TriMesh mesh;
  SurfaceLook look;
  bool linear_colors = false;  // the file's vertex colours are linear (glTF), not sRGB
  bool any_uv = false, any_color = false;  // look's corner arrays are filled only once a mesh has them
  std::vector<std::int32_t> materials_with_uvs, materials_with_colors;  // by the meshes that use them
};

float linear_channel(float c, bool linear) {
  if (!std::isfinite(c)) return 1.0f;
  c = std::clamp(c, 0.0f, 1.0f);
  return linear ? c : c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// Appends the triangles of every mesh under `node`, transformed to the root.
void collect(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& parent, Gathered& out, int depth) {
  if (depth > 256) return;  // a cyclic or absurdly deep node graph from a broken file
  const Eigen::Matrix4d world = parent * to_eigen(node.mTransformation);
  const bool mirrored = world.topLeftCorner<3, 3>().determinant() < 0;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    if (node.mMeshes[i] >= scene.mNumMeshes) continue;
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    if (!mesh.mVertices || !mesh.mFaces) continue;
    TriMesh part;
    part.vertices.resize(mesh.mNumVertices, 3);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const Eigen::Vector4d p(mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z, 1.0);
      part.vertices.row(v) = (world * p).head<3>().transpose();
    }
    // Polygons are split into fans here rather than by assimp's Triangulate
    // step, which asserts (aborting the process) on some malformed files.
    std::vector<std::array<int, 3>> fans;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices < 3 || !face.mIndices) continue;
      bool in_range = true;
      for (unsigned k = 0; k < face.mNumIndices; ++k) in_range &= face.mIndices[k] < mesh.mNumVertices;
      if (!in_range) continue;
      for (unsigned k = 1; k + 1 < face.mNumIndices; ++k) {
        std::array<int, 3> fan = {static_cast<int>(face.mIndices[0]), static_cast<int>(face.mIndices[k]),
                                  static_cast<int>(face.mIndices[k + 1])};
        if (mirrored) std::swap(fan[1], fan[2]);
        fans.push_back(fan);
      }
    }
    const int kept = static_cast<int>(fans.size());
    part.triangles.resize(kept, 3);
    for (int f = 0; f < kept; ++f) part.triangles.row(f) << fans[f][0], fans[f][1], fans[f][2];

    // The look of each corner: UV channel 0, colour set 0, the mesh's material.
    SurfaceLook& look = out.look;
    const size_t before = look.triangle_material.size();
    const int material = mesh.mMaterialIndex < scene.mNumMaterials ? static_cast<int>(mesh.mMaterialIndex) : -1;
    look.triangle_material.insert(look.triangle_material.end(), fans.size(), material);
    const aiVector3D* uv = mesh.mTextureCoords[0];
    const aiColor4D* color = mesh.mColors[0];
    if (uv && !out.any_uv) look.corner_uv.assign(6 * before, 0.0f), out.any_uv = true;
    if (color && !out.any_color) look.corner_color.assign(9 * before, 1.0f), out.any_color = true;
    if (uv) out.materials_with_uvs.push_back(material);
    if (color) out.materials_with_colors.push_back(material);
    for (const std::array<int, 3>& fan : fans)
      for (int v : fan) {
        if (out.any_uv) {
          const bool finite = uv && std::isfinite(uv[v].x) && std::isfinite(uv[v].y);
          look.corner_uv.insert(look.corner_uv.end(), {finite ? uv[v].x : 0.0f, finite ? uv[v].y : 0.0f});
        }
        if (out.any_color)
          look.corner_color.insert(look.corner_color.end(),
                                   {color ? linear_channel(color[v].r, out.linear_colors) : 1.0f,
                                    color ? linear_channel(color[v].g, out.linear_colors) : 1.0f,
                                    color ? linear_channel(color[v].b, out.linear_colors) : 1.0f});
      }
    append(out.mesh, part);
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    if (node.mChildren[c]) collect(scene, *node.mChildren[c], world, out, depth + 1);
}

// What the reader's child hands back: the merged mesh with its look, and
// the textures its materials name, still to be decoded.
struct ReaderAnswer {
  TriMesh mesh;
  std::vector<TextureSource> textures;
};

// Why a file whose meshes hold points or lines only cannot be a body.
constexpr const char* kNoFaces = "it holds points or lines but no faces (a point cloud?); recoil needs a triangle surface";

// Every mesh of the file at `path` under its node transforms, merged.
ReaderAnswer read_with_assimp(const fs::path& path) {
  Assimp::Importer importer;
  // Only assimp's validation runs: its other post-processing steps assert
  // (and abort) on some malformed files, so triangulation, dropping points and
  // lines, and welding happen in collect() and weld_and_clean() instead
  // (assimp's own joining also keeps vertices apart that differ in normal or UV).
  const aiScene* scene = importer.ReadFile(path.string(), aiProcess_ValidateDataStructure);
  if (!scene || !scene->mRootNode) {
    std::string reason = importer.GetErrorString();
    if (reason.empty()) reason = "not a mesh file assimp can read";
    // A point cloud fails assimp's validation as "Mesh  contains no faces".
    if (reason.find("contains no faces") != std::string::npos) reason = kNoFaces;
    throw bad_input(path.string() + ": cannot read mesh: " + reason);
  }
  Gathered gathered;
  // glTF's COLOR_0 is linear by its specification; other formats' vertex
  // colours (PLY's bytes, OBJ's extension) are the sRGB values a viewer shows.
  const std::string extension = lower_case(path.extension().string());
  gathered.linear_colors = extension == ".gltf" || extension == ".glb";
  collect(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), gathered, 0);
  ReaderAnswer answer;
  SurfaceLook& look = gathered.look;
  look.materials = read_materials(*scene, path, answer.textures, look.warnings);
  // Meshes without a material of their own draw in the body's colour: one
  // more material with none.
  const auto plain = static_cast<std::int32_t>(look.materials.size());
  bool any_plain = false;
  for (std::int32_t& m : look.triangle_material)
    if (m < 0) m = plain, any_plain = true;
  if (any_plain) look.materials.emplace_back();
  for (std::int32_t m : gathered.materials_with_uvs) look.materials[static_cast<size_t>(m < 0 ? plain : m)].has_uvs = true;
  for (std::int32_t m : gathered.materials_with_colors)
    look.materials[static_cast<size_t>(m < 0 ? plain : m)].vertex_colored = true;
  answer.mesh = std::move(gathered.mesh);
  if (look.draws_anything() || !look.warnings.empty() || !answer.textures.empty())
    answer.mesh.look = std::make_shared<const SurfaceLook>(std::move(look));
  return answer;
}

// The answer as bytes: #V and #F (int64), the vertex rows (double), the
// triangle rows (int), whether a look follows (one byte), the look and its textures.
std::string encode_answer(const ReaderAnswer& answer) {
  const TriMesh& mesh = answer.mesh;
  std::string bytes;
  put_value(bytes, std::array<std::int64_t, 2>{mesh.vertices.rows(), mesh.triangles.rows()});
  bytes.append(reinterpret_cast<const char*>(mesh.vertices.data()), sizeof(double) * static_cast<size_t>(mesh.vertices.size()));
  bytes.append(reinterpret_cast<const char*>(mesh.triangles.data()), sizeof(int) * static_cast<size_t>(mesh.triangles.size()));
  put_value(bytes, static_cast<std::uint8_t>(mesh.look != nullptr));
  if (mesh.look) {
    encode_look(*mesh.look, bytes);
    encode_texture_sources(answer.textures, bytes);
  }
  return bytes;
}

// The mesh the answer holds, its textures decoded (each in a child of its own).
TriMesh decode_answer(const std::string& bytes) {
  ByteReader in(bytes);
  const auto counts = in.value<std::array<std::int64_t, 2>>();
  RECOIL_CHECK(counts[0] >= 0 && counts[1] >= 0, "counts " << counts[0] << ", " << counts[1]);
  TriMesh mesh;
  const auto vertices = static_cast<size_t>(counts[0]), triangles = static_cast<size_t>(counts[1]);
  RECOIL_CHECK(vertices <= in.left() / (3 * sizeof(double)) && triangles <= in.left() / (3 * sizeof(int)),
               "mesh of " << bytes.size() << " bytes for " << vertices << " vertices and " << triangles << " triangles");
  mesh.vertices.resize(static_cast<Eigen::Index>(vertices), 3);
  mesh.triangles.resize(static_cast<Eigen::Index>(triangles), 3);
  in.items(mesh.vertices.data(), 3 * vertices);
  in.items(mesh.triangles.data(), 3 * triangles);
  if (in.value<std::uint8_t>() != 0) {
    size_t offset = in.offset();
    SurfaceLook look = decode_look(bytes, offset);
    const std::vector<TextureSource> textures = decode_texture_sources(bytes, offset);
    RECOIL_CHECK(offset == bytes.size(), "mesh answer has " << bytes.size() - offset << " bytes after the look");
    RECOIL_CHECK(look.num_triangles() == mesh.num_triangles(), "look of " << look.num_triangles() << " triangles");
    decode_textures(textures, look.materials, look.warnings);
    if (look.draws_anything() || !look.warnings.empty()) mesh.look = std::make_shared<const SurfaceLook>(std::move(look));
  } else {
    RECOIL_CHECK(in.left() == 0, "mesh answer has " << in.left() << " bytes after the mesh");
  }
  return mesh;
}

}  // namespace

TriMesh weld_and_clean(const TriMesh& mesh) {
  std::map<std::array<double, 3>, int> index_of;
  std::vector<int> remap(static_cast<size_t>(mesh.num_vertices()));
  std::vector<Eigen::Vector3d> kept_points;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const std::array<double, 3> key = {mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2)};
    auto [it, inserted] = index_of.try_emplace(key, static_cast<int>(kept_points.size()));
    if (inserted) kept_points.push_back(mesh.vertices.row(v).transpose());
    remap[v] = it->second;
  }
  std::vector<std::array<int, 3>> faces;
  std::vector<int> kept_faces;
  for (int f = 0; f < mesh.num_triangles(); ++f) {
    const int a = remap[mesh.triangles(f, 0)], b = remap[mesh.triangles(f, 1)], c = remap[mesh.triangles(f, 2)];
    if (a == b || b == c || a == c) continue;
    if ((kept_points[b] - kept_points[a]).cross(kept_points[c] - kept_points[a]).squaredNorm() == 0.0) continue;
    faces.push_back({a, b, c});
    kept_faces.push_back(f);
  }
  // Compact away vertices no triangle uses, keeping first-use order stable.
  std::vector<int> compact(kept_points.size(), -1);
  TriMesh out;
  out.triangles.resize(static_cast<Eigen::Index>(faces.size()), 3);
  int used = 0;
  for (size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      int& slot = compact[faces[f][k]];
      if (slot < 0) slot = used++;
      out.triangles(static_cast<Eigen::Index>(f), k) = slot;
    }
  out.vertices.resize(used, 3);
  for (size_t v = 0; v < compact.size(); ++v)
    if (compact[v] >= 0) out.vertices.row(compact[v]) = kept_points[v].transpose();
  if (mesh.look) out.look = std::make_shared<const SurfaceLook>(select_triangles(*mesh.look, kept_faces));
  return out;
}

bool is_mesh_file_name(const fs::path& path) {
  const std::string extension = path.extension().string();
  return extension.size() > 1 && Assimp::Importer().IsExtensionSupported(extension);
}

TriMesh import_surface(const fs::path& path, bool* turned_outward) {
  require_regular_file(path, "mesh file");
  check_declared_mesh_counts(path);
  // assimp reads tens of MiB a second; a reader still busy after 5 s plus 1 s per MiB is stuck in a loop.
  std::error_code failed;  // only the time limit depends on the size
  const std::uintmax_t mib = fs::file_size(path, failed) >> 20;
  const int cpu_seconds = 5 + (failed ? 0 : static_cast<int>(std::min<std::uintmax_t>(mib, 1 << 20)));
  TriMesh merged = decode_answer(read_in_child([&] { return encode_answer(read_with_assimp(path)); }, path.string(),
                                               "the mesh reader (assimp)", cpu_seconds));
  for (int v = 0; v < merged.num_vertices(); ++v)
    if (!merged.vertices.row(v).allFinite()) throw bad_input(path.string() + ": mesh has non-finite vertex coordinates");
  TriMesh clean = weld_and_clean(merged);
  if (merged.num_triangles() == 0) throw bad_input(path.string() + ": cannot read mesh: " + kNoFaces);
  if (clean.empty())
    throw bad_input(path.string() + ": mesh has no triangle with an area: " +
                    (merged.num_triangles() == 1 ? std::string("its one triangle is")
                                                 : "its " + std::to_string(merged.num_triangles()) + " triangles are") +
                    " degenerate (corners repeated or in one line); recoil needs a triangle surface");
  // A closed surface wound inward bounds the same solid turned inside out:
  // turned over, its normals, back faces and mass read as that solid's.
  const MeshStats stats = compute_mesh_stats(clean);  // its volume is the signed enclosed one
  const bool inward = stats.watertight && stats.volume < 0.0;
  if (inward) flip_winding(clean);
  if (turned_outward != nullptr) *turned_outward = inward;
  return clean;
}

}  // namespace recoil::sim
