// Gmsh (v2, v4.1) and TetGen readers: good files, bad files naming file and
// line, and a little fuzzing (truncations, corrupted bytes) that must only
// ever produce bad_input errors.
#include "sim/geometry/tet_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "core/error.h"
#include "tests/test_support.h"

namespace recoil::sim {
namespace {

// A unit cube as 5 tets (a corner-cut split), 8 nodes with 1-based tags.
const char* kGmsh2 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
1
3 1 "body"
$EndPhysicalNames
$Nodes
8
1 0 0 0
2 1 0 0
3 0 1 0
4 1 1 0
5 0 0 1
6 1 0 1
7 0 1 1
8 1 1 1
$EndNodes
$Elements
7
1 15 2 0 1 1
2 2 2 0 1 1 2 3
3 4 2 1 1 1 2 3 5
4 4 2 1 1 2 4 3 8
5 4 2 1 1 2 5 6 8
6 4 2 1 1 3 8 7 5
7 4 2 1 1 2 3 5 8
$EndElements
)";

const char* kGmsh41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Entities
0 0 0 1
1 0 0 0 1 1 1 0 0
$EndEntities
$Nodes
2 8 1 8
3 1 0 5
1
2
3
4
5
0 0 0
1 0 0
0 1 0
1 1 0
0 0 1
3 1 0 3
6
7
8
1 0 1
0 1 1
1 1 1
$EndNodes
$Elements
2 6 1 6
0 1 15 1
1 1
3 1 4 5
2 1 2 3 5
3 2 4 3 8
4 2 5 6 8
5 3 8 7 5
6 2 3 5 8
$EndElements
)";

const char* kNode = R"(# cube
8 3 0 0
0 0 0 0
1 1 0 0
2 0 1 0
3 1 1 0
4 0 0 1
5 1 0 1
6 0 1 1
7 1 1 1
)";

const char* kEle = R"(5 4 0
0 0 1 2 4
1 1 3 2 7
2 1 4 5 7
3 2 7 6 4   # trailing comment
4 1 2 4 7
)";

void expect_unit_cube(const TetMesh& m) {
  EXPECT_EQ(m.num_nodes(), 8);
  EXPECT_EQ(m.num_tets(), 5);
  EXPECT_NEAR(total_volume(m), 1.0, 1e-12);
  for (int t = 0; t < m.num_tets(); ++t) EXPECT_GT(tet_volume(m, t), 0.0);
}

std::string error_of(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::bad_input);
    return e.what();
  }
  ADD_FAILURE() << "no error thrown";
  return "";
}

TEST(TetFile, ReadsGmshV2AndV41AndTetgen) {
  expect_unit_cube(parse_gmsh(kGmsh2, "cube.msh"));
  expect_unit_cube(parse_gmsh(kGmsh41, "cube41.msh"));
  expect_unit_cube(parse_tetgen(kNode, "cube.node", kEle, "cube.ele"));
}

TEST(TetFile, QuadraticTetsKeepTheirCorners) {
  const char* text = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
10
1 0 0 0
2 1 0 0
3 0 1 0
4 0 0 1
5 0.5 0 0
6 0.5 0.5 0
7 0 0.5 0
8 0 0 0.5
9 0 0.5 0.5
10 0.5 0 0.5
$EndNodes
$Elements
1
1 11 0 1 2 3 4 5 6 7 8 9 10
$EndElements
)";
  const TetMesh m = parse_gmsh(text, "quadratic.msh");
  EXPECT_EQ(m.num_nodes(), 4);  // mid-edge nodes dropped
  EXPECT_EQ(m.num_tets(), 1);
  EXPECT_NEAR(total_volume(m), 1.0 / 6.0, 1e-15);
}

TEST(TetFile, ReadsFromDiskByExtension) {
  const auto dir = test::scratch_dir("tet_file_disk");
  std::ofstream(dir / "cube.msh") << kGmsh2;
  std::ofstream(dir / "cube.node") << kNode;
  std::ofstream(dir / "cube.ele") << kEle;
  expect_unit_cube(read_tet_file(dir / "cube.msh"));
  expect_unit_cube(read_tet_file(dir / "cube.ele"));
  expect_unit_cube(read_tet_file(dir / "cube.node"));
  EXPECT_NE(error_of([&] { read_tet_file(dir / "missing.msh"); }).find("missing.msh"), std::string::npos);
  EXPECT_NE(error_of([&] { read_tet_file(dir / "cube.stl"); }).find("extension"), std::string::npos);
}

TEST(TetFile, BadFilesNameFileAndLine) {
  std::string bad = kGmsh2;
  bad.replace(bad.find("1 1 0\n5 0 0 1"), 5, "1 x 0");  // node 4's y coordinate
  const std::string e1 = error_of([&] { parse_gmsh(bad, "bad.msh"); });
  EXPECT_NE(e1.find("bad.msh:13:"), std::string::npos) << e1;

  bad = kGmsh2;
  bad.replace(bad.find("3 8 7 5"), 7, "3 8 7 9");
  const std::string e2 = error_of([&] { parse_gmsh(bad, "bad.msh"); });
  EXPECT_NE(e2.find("bad.msh:26:"), std::string::npos) << e2;
  EXPECT_NE(e2.find("unknown node 9"), std::string::npos) << e2;

  bad = kEle;
  bad.replace(bad.find("1 2 4 7"), 7, "1 2 3 0");  // flat: all four on z = 0
  const std::string e3 = error_of([&] { parse_tetgen(kNode, "c.node", bad, "c.ele"); });
  EXPECT_NE(e3.find("c.ele:6: degenerate"), std::string::npos) << e3;

  const std::string e4 = error_of([&] { parse_gmsh("$MeshFormat\n2.2 1 8\n$EndMeshFormat\n", "bin.msh"); });
  EXPECT_NE(e4.find("binary"), std::string::npos) << e4;
  const std::string e5 = error_of([&] { parse_gmsh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", "empty.msh"); });
  EXPECT_NE(e5.find("no tetrahedra"), std::string::npos) << e5;
  const std::string e6 = error_of([&] { parse_gmsh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n99999999999\n", "huge.msh"); });
  EXPECT_NE(e6.find("huge.msh:5: declares 99999999999 nodes"), std::string::npos) << e6;
}

// Every prefix of every file, and files with random bytes overwritten, must
// parse or throw bad_input: never crash, hang or throw anything else.
TEST(TetFile, FuzzedInputsOnlyRaiseBadInput) {
  std::mt19937 rng(1234);
  int ok = 0, rejected = 0;
  auto attempt = [&](const std::function<void()>& fn) {
    try {
      fn();
      ++ok;
    } catch (const Error& e) {
      ASSERT_EQ(e.kind(), ErrorKind::bad_input) << e.what();
      ++rejected;
    }
  };
  for (const std::string& text : {std::string(kGmsh2), std::string(kGmsh41)}) {
    for (size_t n = 0; n < text.size(); n += 3) attempt([&] { parse_gmsh(text.substr(0, n), "t.msh"); });
    const std::string alphabet = "0123456789 -.\n$eE#x";
    for (int trial = 0; trial < 400; ++trial) {
      std::string corrupt = text;
      for (int k = 0; k < 3; ++k)
        corrupt[rng() % corrupt.size()] = alphabet[rng() % alphabet.size()];
      attempt([&] { parse_gmsh(corrupt, "c.msh"); });
    }
  }
  const std::string node = kNode, ele = kEle;
  for (size_t n = 0; n < ele.size(); n += 2) attempt([&] { parse_tetgen(node, "t.node", ele.substr(0, n), "t.ele"); });
  for (size_t n = 0; n < node.size(); n += 2) attempt([&] { parse_tetgen(node.substr(0, n), "t.node", ele, "t.ele"); });
  std::cout << "fuzz: " << ok << " parsed, " << rejected << " rejected with bad_input\n";
  EXPECT_GT(rejected, 100);
}

}  // namespace
}  // namespace recoil::sim
