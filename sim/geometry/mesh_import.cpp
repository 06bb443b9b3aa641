// The only file in recoil that includes assimp (ARCHITECTURE.md).
#include "sim/geometry/mesh_import.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <assimp/Importer.hpp>
#include <cmath>
#include <map>
#include <system_error>

#include "core/error.h"

namespace recoil::sim {
namespace fs = std::filesystem;

namespace {

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return out;
}

// Appends the triangles of every mesh under `node`, transformed to the root.
void collect(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& parent, TriMesh& out, int depth) {
  if (depth > 256) return;  // a cyclic or absurdly deep node graph from a broken file
  const Eigen::Matrix4d world = parent * to_eigen(node.mTransformation);
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    if (node.mMeshes[i] >= scene.mNumMeshes) continue;
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    if (!(mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || !mesh.mVertices) continue;
    TriMesh part;
    part.vertices.resize(mesh.mNumVertices, 3);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const Eigen::Vector4d p(mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z, 1.0);
      part.vertices.row(v) = (world * p).head<3>().transpose();
    }
    int kept = 0;
    part.triangles.resize(mesh.mNumFaces, 3);
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      bool in_range = true;
      for (int k = 0; k < 3; ++k) in_range &= face.mIndices[k] < mesh.mNumVertices;
      if (!in_range) continue;
      for (int k = 0; k < 3; ++k) part.triangles(kept, k) = static_cast<int>(face.mIndices[k]);
      ++kept;
    }
    part.triangles.conservativeResize(kept, 3);
    if (world.topLeftCorner<3, 3>().determinant() < 0) part.triangles.col(1).swap(part.triangles.col(2));
    append(out, part);
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    if (node.mChildren[c]) collect(scene, *node.mChildren[c], world, out, depth + 1);
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
  for (int f = 0; f < mesh.num_triangles(); ++f) {
    const int a = remap[mesh.triangles(f, 0)], b = remap[mesh.triangles(f, 1)], c = remap[mesh.triangles(f, 2)];
    if (a == b || b == c || a == c) continue;
    if ((kept_points[b] - kept_points[a]).cross(kept_points[c] - kept_points[a]).squaredNorm() == 0.0) continue;
    faces.push_back({a, b, c});
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
  return out;
}

TriMesh import_surface(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw bad_input(path.string() + ": no such file");
  if (fs::is_directory(path, ec)) throw bad_input(path.string() + ": is a folder, not a mesh file");
  Assimp::Importer importer;
  // Ask assimp to drop points and lines; we weld positions ourselves, since
  // assimp's own joining keeps vertices apart that differ in normal or UV.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path.string(), aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  if (!scene || !scene->mRootNode) {
    std::string reason = importer.GetErrorString();
    if (reason.empty()) reason = "not a mesh file assimp can read";
    throw bad_input(path.string() + ": cannot read mesh: " + reason);
  }
  TriMesh merged;
  collect(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), merged, 0);
  for (int v = 0; v < merged.num_vertices(); ++v)
    if (!merged.vertices.row(v).allFinite()) throw bad_input(path.string() + ": mesh has non-finite vertex coordinates");
  TriMesh clean = weld_and_clean(merged);
  if (clean.empty()) throw bad_input(path.string() + ": mesh has no triangles");
  return clean;
}

}  // namespace recoil::sim
