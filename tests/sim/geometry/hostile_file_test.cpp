// The tet and mesh readers refuse what is not a regular file (a FIFO at once,
// /dev/zero behind a symlink) and header counts their file cannot hold, with
// bad_input errors that name the file.
#include <gtest/gtest.h>

#include <fstream>

#include "sim/geometry/mesh_import.h"
#include "sim/geometry/tet_file.h"
#include "tests/hostile_files.h"
#include "tests/test_support.h"

namespace recoil::sim {
namespace {

namespace fs = std::filesystem;

void expect_names(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << message;
}

TEST(TetFile, FifoIsRefusedWithoutBlocking) {
  const fs::path dir = test::scratch_dir("tet_file_fifo");
  test::make_fifo(dir / "pipe.msh");
  const std::string e = test::bad_input_within_a_second([&] { read_tet_file(dir / "pipe.msh"); }, dir / "pipe.msh");
  expect_names(e, (dir / "pipe.msh").string());
  expect_names(e, "FIFO");
  // TetGen reads the sibling .ele too: a FIFO there is refused the same way.
  std::ofstream(dir / "cube.node") << "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  test::make_fifo(dir / "cube.ele");
  expect_names(test::bad_input_within_a_second([&] { read_tet_file(dir / "cube.node"); }, dir / "cube.ele"),
               (dir / "cube.ele").string());
}

TEST(TetFile, DeviceBehindSymlinkIsRefused) {
  const fs::path dir = test::scratch_dir("tet_file_dev_zero");
  test::link_to_dev_zero(dir / "zero.msh");
  const std::string e = test::bad_input_within_a_second([&] { read_tet_file(dir / "zero.msh"); });
  expect_names(e, (dir / "zero.msh").string());
  expect_names(e, "device");
}

TEST(TetFile, HeaderCountBeyondFileSizeIsRefused) {
  const fs::path dir = test::scratch_dir("tet_file_huge_count");
  std::ofstream(dir / "huge.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1000000000\n1 0 0 0\n";
  std::string e = test::bad_input_within_a_second([&] { read_tet_file(dir / "huge.msh"); });
  expect_names(e, (dir / "huge.msh").string() + ":5:");
  expect_names(e, "1000000000 nodes");

  std::ofstream(dir / "blocks.msh") << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1000000000 1 1000000000\n";
  e = test::bad_input_within_a_second([&] { read_tet_file(dir / "blocks.msh"); });
  expect_names(e, (dir / "blocks.msh").string() + ":5:");
  expect_names(e, "1000000000 nodes");

  std::ofstream(dir / "huge.node") << "1000000000 3 0 0\n1 0 0 0\n";
  std::ofstream(dir / "huge.ele") << "1 4 0\n1 1 1 1 1\n";
  e = test::bad_input_within_a_second([&] { read_tet_file(dir / "huge.node"); });
  expect_names(e, (dir / "huge.node").string() + ":1:");
  expect_names(e, "1000000000 nodes");
}

TEST(MeshImport, FifoAndDeviceAreRefused) {
  const fs::path dir = test::scratch_dir("mesh_import_hostile");
  test::make_fifo(dir / "pipe.obj");
  const std::string e1 = test::bad_input_within_a_second([&] { import_surface(dir / "pipe.obj"); }, dir / "pipe.obj");
  expect_names(e1, (dir / "pipe.obj").string());
  expect_names(e1, "FIFO");
  test::link_to_dev_zero(dir / "zero.stl");
  const std::string e2 = test::bad_input_within_a_second([&] { import_surface(dir / "zero.stl"); });
  expect_names(e2, (dir / "zero.stl").string());
  expect_names(e2, "device");
}

// A point cloud is read by assimp, whose validation refuses it in its own
// words ("Mesh  contains no faces"): the message says what the file lacks.
TEST(MeshImport, APointCloudOrLinesAreRefusedForTheirMissingFaces) {
  const fs::path dir = test::scratch_dir("mesh_import_points");
  std::ofstream(dir / "points.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::string e = test::bad_input_within_a_second([&] { import_surface(dir / "points.obj"); });
  expect_names(e, (dir / "points.obj").string());
  expect_names(e, "no faces (a point cloud?)");
  // Lines only pass assimp's validation (they are faces to it) and are
  // dropped by recoil: the same words, not an empty mesh.
  std::ofstream(dir / "lines.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n";
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "lines.obj"); }),
               "no faces (a point cloud?)");
  // A face whose corners lie in one line has no area.
  std::ofstream(dir / "flat.obj") << "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n";
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "flat.obj"); }),
               "its one triangle is degenerate");
}

// assimp allocates what PLY and OFF headers declare, and searches forever for a missing end_header.
TEST(MeshImport, HeaderCountsBeyondFileSizeAreRefused) {
  const fs::path dir = test::scratch_dir("mesh_import_huge_count");
  const std::string ply_start = "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\n";
  std::ofstream(dir / "huge.ply") << ply_start << "end_header\n0\n";
  std::ofstream(dir / "unended.ply") << ply_start << "0\n";
  std::ofstream(dir / "vtab.ply") << ply_start << "end_header\v0\n";
  std::ofstream(dir / "last.ply") << ply_start << "end_header";
  std::ofstream(dir / "format.ply") << std::string("ply\nformat ascii\0\0end_header\n", 30);
  // A format line ending in form feeds sends assimp into an endless loop.
  std::ofstream(dir / "loop.ply") << "ply\nformat ascii 0\f\fend_header\n";
  // assimp skips form feeds before the magic as line ends, and then searches for end_header forever.
  std::ofstream(dir / "feed.ply") << "\f\f\n" << ply_start << "0\n";
  // ... and after a leading carriage return it reads the magic from the second line: a .ply file must start with it.
  std::ofstream(dir / "second.ply") << "\rOOOO\n" << ply_start << "0\n";
  // A face list's count is reserved as read, whatever its declared type; once
  // the lines run out, assimp reads the last one again for every instance left.
  const std::string ply_faces = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  std::ofstream(dir / "list.ply") << ply_faces << "0 0 0\n1 0 0\n0 1 0\n99990000 0 1 2\n";
  std::ofstream(dir / "short.ply") << ply_faces << "0 0 0\n1 0 0\n99990000 1 0\n";
  // An element line without its count crashes assimp 5.2's reader.
  std::ofstream(dir / "uncounted.ply") << "ply\nformat ascii 1.0\nelement v2ply\nend_header\n0\n";
  std::ofstream(dir / "huge.off") << "OFF\n1000000000 1 0\n0 0 0\n";
  // assimp allocates the vertices even when no face count follows.
  std::ofstream(dir / "faceless.off") << "OFF999999#]9\r99999t0\n";
  // assimp reads a .off file without its magic too, and takes a leading '4' for the homogeneous flag.
  std::ofstream(dir / "bare.off") << "4 900000000 1 0\n0 0 0\n";
  const std::string e1 = test::bad_input_within_a_second([&] { import_surface(dir / "huge.ply"); });
  expect_names(e1, (dir / "huge.ply").string());
  expect_names(e1, "4000000000 vertex");
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "unended.ply"); }), "end_header");
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "vtab.ply"); }), "end_header");
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "last.ply"); }), "end_header");
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "format.ply"); }), "control byte 0x00");
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "feed.ply"); }), "end_header");
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "loop.ply"); }), "control byte 0x0C");
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "second.ply"); }), "not a PLY file");
  const std::string e_list = test::bad_input_within_a_second([&] { import_surface(dir / "list.ply"); });
  expect_names(e_list, (dir / "list.ply").string());
  expect_names(e_list, "a list of 99990000 values in face");
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "short.ply"); }), "99990000 values");
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "uncounted.ply"); }), "element NAME COUNT");
  const std::string e3 = test::bad_input_within_a_second([&] { import_surface(dir / "huge.off"); });
  expect_names(e3, (dir / "huge.off").string());
  expect_names(e3, "1000000000 vertices");
  expect_names(test::bad_input_within_a_second([&] { import_surface(dir / "faceless.off"); }), "999999 vertices,");
  const std::string e4 = test::bad_input_within_a_second([&] { import_surface(dir / "bare.off"); });
  expect_names(e4, (dir / "bare.off").string());
  expect_names(e4, "900000000 vertices");
}

}  // namespace
}  // namespace recoil::sim
