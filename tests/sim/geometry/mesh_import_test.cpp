// Import through assimp: one closed box written in each supported family of
// formats must come back as the same closed surface; broken files must give a
// bad_input error naming the file, never a crash.
#include "sim/geometry/mesh_import.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "sim/geometry/mesh_stats.h"
#include "sim/geometry/primitives.h"
#include "tests/test_support.h"

namespace recoil::sim {
namespace fs = std::filesystem;

namespace {

const TriMesh& unit_box() {
  static const TriMesh box = make_box({1, 2, 3}, 1);
  return box;
}

std::string obj_text(const TriMesh& m) {
  std::ostringstream s;
  for (int v = 0; v < m.num_vertices(); ++v) s << "v " << m.vertices.row(v) << "\n";
  for (int f = 0; f < m.num_triangles(); ++f)
    s << "f " << m.triangles(f, 0) + 1 << " " << m.triangles(f, 1) + 1 << " " << m.triangles(f, 2) + 1 << "\n";
  return s.str();
}

std::string ply_text(const TriMesh& m) {
  std::ostringstream s;
  s << "ply\nformat ascii 1.0\nelement vertex " << m.num_vertices()
    << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m.num_triangles()
    << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (int v = 0; v < m.num_vertices(); ++v) s << m.vertices.row(v) << "\n";
  for (int f = 0; f < m.num_triangles(); ++f) s << "3 " << m.triangles.row(f) << "\n";
  return s.str();
}

// STL stores every triangle with its own three corners: import must weld them.
std::string stl_text(const TriMesh& m) {
  std::ostringstream s;
  s << "solid box\n";
  for (int f = 0; f < m.num_triangles(); ++f) {
    s << " facet normal 0 0 0\n  outer loop\n";
    for (int k = 0; k < 3; ++k) s << "   vertex " << m.vertices.row(m.triangles(f, k)) << "\n";
    s << "  endloop\n endfacet\n";
  }
  s << "endsolid box\n";
  return s.str();
}

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    unsigned n = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 2]);
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[n & 63] : '=';
  }
  return out;
}

// glTF 2.0 with the buffer inline, and a node that translates the mesh by +5 in x.
std::string gltf_text(const TriMesh& m) {
  std::string buffer;
  for (int v = 0; v < m.num_vertices(); ++v)
    for (int k = 0; k < 3; ++k) {
      const float x = static_cast<float>(m.vertices(v, k));
      buffer.append(reinterpret_cast<const char*>(&x), 4);
    }
  const size_t index_offset = buffer.size();
  for (int f = 0; f < m.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = static_cast<std::uint32_t>(m.triangles(f, k));
      buffer.append(reinterpret_cast<const char*>(&i), 4);
    }
  const Aabb box = bounding_box(m);
  std::ostringstream s;
  s << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
    << R"("nodes":[{"mesh":0,"translation":[5,0,0]}],)"
    << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
    << R"("accessors":[{"bufferView":0,"componentType":5126,"count":)" << m.num_vertices()
    << R"(,"type":"VEC3","min":[)" << box.min.x() << "," << box.min.y() << "," << box.min.z() << R"(],"max":[)"
    << box.max.x() << "," << box.max.y() << "," << box.max.z() << "]},"
    << R"({"bufferView":1,"componentType":5125,"count":)" << m.num_triangles() * 3 << R"(,"type":"SCALAR"}],)"
    << R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" << index_offset << "},"
    << R"({"buffer":0,"byteOffset":)" << index_offset << R"(,"byteLength":)" << buffer.size() - index_offset
    << "}],"
    << R"("buffers":[{"byteLength":)" << buffer.size()
    << R"(,"uri":"data:application/octet-stream;base64,)" << base64(buffer) << R"("}]})";
  return s.str();
}

std::string collada_text(const TriMesh& m) {
  std::ostringstream pos, idx;
  for (int v = 0; v < m.num_vertices(); ++v) pos << m.vertices.row(v) << " ";
  for (int f = 0; f < m.num_triangles(); ++f) idx << m.triangles.row(f) << " ";
  std::ostringstream s;
  s << R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
<library_geometries><geometry id="box" name="box"><mesh>
<source id="box-pos"><float_array id="box-pos-array" count=")"
    << m.num_vertices() * 3 << R"(">)" << pos.str() << R"(</float_array>
<technique_common><accessor source="#box-pos-array" count=")"
    << m.num_vertices() << R"(" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
<vertices id="box-vtx"><input semantic="POSITION" source="#box-pos"/></vertices>
<triangles count=")"
    << m.num_triangles() << R"("><input semantic="VERTEX" source="#box-vtx" offset="0"/><p>)" << idx.str()
    << R"(</p></triangles>
</mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="scene"><node id="n"><instance_geometry url="#box"/></node></visual_scene></library_visual_scenes>
<scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
  return s.str();
}

void expect_same_box(const TriMesh& mesh, const Eigen::Vector3d& offset, const std::string& name) {
  const MeshStats stats = compute_mesh_stats(mesh);
  EXPECT_EQ(stats.vertices, 8) << name;
  EXPECT_EQ(stats.triangles, 12) << name;
  EXPECT_TRUE(stats.watertight) << name;
  EXPECT_NEAR(stats.volume, 6.0, 1e-5) << name;
  EXPECT_NEAR((stats.bounds.center() - offset).norm(), 0.0, 1e-5) << name;
}

}  // namespace

TEST(MeshImport, SameClosedBoxFromEveryFormat) {
  const fs::path dir = test::scratch_dir("mesh_import_formats");
  const TriMesh& box = unit_box();
  test::write_file(dir / "box.obj", obj_text(box));
  test::write_file(dir / "box.ply", ply_text(box));
  test::write_file(dir / "box.stl", stl_text(box));
  test::write_file(dir / "box.gltf", gltf_text(box));
  test::write_file(dir / "box.dae", collada_text(box));
  for (const char* name : {"box.obj", "box.ply", "box.stl", "box.dae"})
    expect_same_box(import_surface(dir / name), Eigen::Vector3d::Zero(), name);
  expect_same_box(import_surface(dir / "box.gltf"), Eigen::Vector3d(5, 0, 0), "box.gltf (node transform)");
}

// A closed box whose faces all point inward reads as the box, faces out:
// its enclosed volume is positive, so a rigid body of it has a mass.
TEST(MeshImport, AClosedSurfaceWoundInwardIsTurnedOutward) {
  const fs::path dir = test::scratch_dir("mesh_import_inward");
  TriMesh inward = unit_box();
  flip_winding(inward);
  ASSERT_LT(enclosed_volume(inward), 0.0);
  test::write_file(dir / "inward.obj", obj_text(inward));
  expect_same_box(import_surface(dir / "inward.obj"), Eigen::Vector3d::Zero(), "inward.obj");
}

TEST(MeshImport, QuadsAreTriangulatedAndBunnyIsClosed) {
  const fs::path dir = test::scratch_dir("mesh_import_quads");
  test::write_file(dir / "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  EXPECT_EQ(import_surface(dir / "quad.obj").num_triangles(), 2);
  const MeshStats bunny = compute_mesh_stats(import_surface(test::source_path("assets/meshes/bunny.obj")));
  EXPECT_TRUE(bunny.watertight);
  EXPECT_EQ(bunny.triangles, 3674);
}

TEST(MeshImport, WeldDropsDegenerateTriangles) {
  TriMesh m;
  m.vertices.resize(5, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 2, 0, 0;  // vertex 3 duplicates 1; 0-1-4 collinear
  m.triangles.resize(3, 3);
  m.triangles << 0, 1, 2, 0, 3, 1, 0, 1, 4;
  const TriMesh clean = weld_and_clean(m);
  EXPECT_EQ(clean.num_triangles(), 1);
  EXPECT_EQ(clean.num_vertices(), 3);
}

TEST(MeshImport, BrokenFilesAreBadInputNamingTheFile) {
  const fs::path dir = test::scratch_dir("mesh_import_broken");
  test::write_file(dir / "garbage.stl", std::string("\x01\x02solid nonsense \xff\xfe", 20));
  test::write_file(dir / "empty.obj", "");
  test::write_file(dir / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  test::write_file(dir / "bad_index.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
  test::write_file(dir / "truncated.ply", ply_text(unit_box()).substr(0, 200));
  test::write_file(dir / "notjson.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [");
  test::write_file(dir / "nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  fs::create_directories(dir / "folder.obj");
  for (const char* name : {"garbage.stl", "empty.obj", "points.obj", "bad_index.obj", "truncated.ply", "notjson.gltf",
                           "nan.obj", "folder.obj", "missing.obj"}) {
    try {
      const TriMesh mesh = import_surface(dir / name);
      ADD_FAILURE() << name << " was accepted with " << mesh.num_triangles() << " triangles";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::bad_input) << name;
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      std::cout << "  " << e.what() << "\n";
    }
  }
}

}  // namespace recoil::sim
