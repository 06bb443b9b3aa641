// Open meshes end to end: a box with its top face missing (and the assimp
// corpus's sphere with a hole) is reported open by `info`, drops without
// error, and the run's summary and run.json name it; `info MESH` prints the
// tetrahedra a mesh would get.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "sim/geometry/mesh_import.h"
#include "sim/geometry/mesh_stats.h"
#include "tests/cli/box_mesh_file.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;
using nlohmann::json;

TEST(OpenMesh, InfoReportsItOpenWithTheTetsOfTheClosedBox) {
  const fs::path dir = scratch_dir("open_info");
  const Eigen::Vector3d lo(-0.1, -0.1, -0.1), hi(0.1, 0.1, 0.1);
  const fs::path open = write_box_off(dir / "openbox.off", lo, hi, /*skip_top=*/true);
  const fs::path closed = write_box_off(dir / "box.off", lo, hi);
  const CommandResult r = run_recoil("info --json " + shell_quote(open));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json info = json::parse(r.out);
  EXPECT_FALSE(info["watertight"].get<bool>());
  EXPECT_EQ(info["boundary_edges"], 4);
  // Its solid is where the winding number says inside: the box, less at
  // most the layer of weighing cells under the missing lid.
  EXPECT_LE(info["volume"].get<double>(), 0.008 + 1e-9);
  EXPECT_GE(info["volume"].get<double>(), 0.008 * 63.0 / 64.0 - 1e-9);
  // The missing face changes nothing inside: the cells below the hole still
  // see the rest of the box over more than half the sphere.
  const CommandResult c = run_recoil("info --json " + shell_quote(closed));
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_EQ(info["tetrahedra"], json::parse(c.out)["tetrahedra"]);
  EXPECT_EQ(info["tetrahedra"]["tets"], 8 * 8 * 8 * 6);

  const CommandResult text = run_recoil("info " + shell_quote(open));
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("watertight   no: open mesh (4 boundary"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("inside by winding number"), std::string::npos) << text.out;
}

TEST(OpenMesh, AClosedMeshWoundInwardKeepsItsVolumeAndMass) {
  const fs::path dir = scratch_dir("inward_mesh");
  const fs::path box = write_box_off(dir / "box.off", Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1));
  // The same box with every face's winding reversed.
  std::ifstream in(box);
  std::ofstream out(dir / "inward.off");
  std::string line;
  for (int n = 0; std::getline(in, line); ++n) {
    std::istringstream words(line);
    int count = 0, a = 0, b = 0, c = 0;
    if (n > 1 && (words >> count >> a >> b >> c) && count == 3 && words.eof()) line = "3 " + std::to_string(a) + " " +
        std::to_string(c) + " " + std::to_string(b);
    out << line << "\n";
  }
  out.close();
  const CommandResult r = run_recoil("info --json " + shell_quote(dir / "inward.off"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json info = json::parse(r.out);
  EXPECT_TRUE(info["wound_inward"].get<bool>());
  EXPECT_NEAR(info["volume"].get<double>(), 0.008, 1e-8);  // the import keeps floats
  // A soft body of it weighs what the outward box does: density times 0.008 m^3.
  const std::string drop = "drop --seconds 0.004 --no-render -q -o " + shell_quote(dir / "out") + " --save-scene ";
  for (const char* name : {"box", "inward"}) {
    const fs::path scene = dir / (std::string(name) + ".json");
    ASSERT_EQ(run_recoil(drop + shell_quote(scene) + " " + shell_quote(dir / (std::string(name) + ".off"))).exit_code, 0);
    const CommandResult s = run_recoil("info --json " + shell_quote(scene));
    ASSERT_EQ(s.exit_code, 0) << s.err;
    EXPECT_NEAR(json::parse(s.out)["bodies"][1]["mass"].get<double>(), 8.0, 1e-5) << name;
  }
}

TEST(OpenMesh, InfoPrintsTheTetsAtTheDefaultAndAGivenResolution) {
  const fs::path dir = scratch_dir("open_info_tets");
  // 0.1 x 0.1 x 0.4: at 8 cells along the longest side the lattice is 2 x 2 x 8
  // cells (3 x 3 x 9 nodes), six tets a cell; at 16 it is 4 x 4 x 16.
  const fs::path tall = write_box_off(dir / "tall.off", Eigen::Vector3d(-0.05, -0.05, 0.0), Eigen::Vector3d(0.05, 0.05, 0.4));
  const CommandResult text = run_recoil("info " + shell_quote(tall));
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("tetrahedra   192 tets, 81 nodes at resolution 8 (cells of 0.05 m)"), std::string::npos)
      << text.out;
  const CommandResult fine = run_recoil("info --json --resolution 16 " + shell_quote(tall));
  ASSERT_EQ(fine.exit_code, 0) << fine.err;
  const json tets = json::parse(fine.out)["tetrahedra"];
  EXPECT_EQ(tets["resolution"], 16);
  EXPECT_EQ(tets["tets"], 4 * 4 * 16 * 6);
  EXPECT_EQ(tets["nodes"], 5 * 5 * 17);
  EXPECT_NEAR(tets["cell_size"].get<double>(), 0.025, 1e-6);

  EXPECT_EQ(run_recoil("info --resolution 0 " + shell_quote(tall)).exit_code, 2);
  const CommandResult scene =
      run_recoil("info --resolution 4 " + shell_quote(source_path("assets/scenes/bunny-drop.json")));
  EXPECT_EQ(scene.exit_code, 2);
  EXPECT_NE(scene.err.find("--resolution applies to a mesh"), std::string::npos) << scene.err;
}

TEST(OpenMesh, DropRunsAndTheSummaryNamesTheOpenMesh) {
  const fs::path dir = scratch_dir("open_drop");
  const fs::path open = write_box_off(dir / "openbox.off", Eigen::Vector3d(-0.1, -0.1, -0.1),
                                      Eigen::Vector3d(0.1, 0.1, 0.1), /*skip_top=*/true);
  const CommandResult r = run_recoil("drop " + shell_quote(open) + " --seconds 0.2 --no-render -o " + shell_quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: open mesh: 'openbox' (not watertight; inside by winding number)"), std::string::npos)
      << r.err;
  const json run = json::parse(file_bytes(dir / "out" / "run.json"));
  EXPECT_EQ(run["warnings"]["open_meshes"], json::array({"openbox"}));
  EXPECT_NE(run["warnings"]["summary"].get<std::string>().find("open mesh"), std::string::npos);
  // A rigid drop weighs the solid its winding number fills; a static turntable's mesh is only drawn, so nothing to warn of.
  const CommandResult rigid = run_recoil("drop " + shell_quote(open) + " --material rigid -q --seconds 0.1 --no-render -o " +
                                         shell_quote(dir / "rigid"));
  ASSERT_EQ(rigid.exit_code, 0) << rigid.err;
  EXPECT_NE(rigid.err.find("open mesh: 'openbox'"), std::string::npos) << rigid.err;
  const CommandResult drawn = run_recoil("turntable " + shell_quote(open) + " --turn-frames 1 --no-render -o " +
                                         shell_quote(dir / "turntable"));
  ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
  EXPECT_EQ(drawn.err.find("open mesh"), std::string::npos) << drawn.err;
  // -q hides the summary line, except for its warnings.
  const CommandResult quiet = run_recoil("drop " + shell_quote(open) + " -q --seconds 0.1 --no-render -o " + shell_quote(dir / "q"));
  EXPECT_NE(quiet.err.find("open mesh: 'openbox'"), std::string::npos) << quiet.err;
  // The resolved scene says so too.
  const CommandResult info = run_recoil("info --json " + shell_quote(dir / "out" / "scene.json"));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const json bodies = json::parse(info.out)["bodies"];
  ASSERT_EQ(bodies.size(), 2u);
  EXPECT_TRUE(bodies[1]["open_mesh"].get<bool>());
  EXPECT_GT(bodies[1]["tets"].get<int>(), 0);
}

TEST(OpenMesh, AssimpSphereWithAHoleDrops) {
  const fs::path sphere = "/usr/share/assimp/models/STL/sphereWithHole.stl";
  if (!fs::exists(sphere)) GTEST_SKIP() << "assimp-testmodels is not installed";
  const fs::path dir = scratch_dir("open_sphere");
  const CommandResult info = run_recoil("info --json " + shell_quote(sphere));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_FALSE(json::parse(info.out)["watertight"].get<bool>());
  const CommandResult r = run_recoil("drop " + shell_quote(sphere) + " --seconds 0.2 --no-render -o " + shell_quote(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("open mesh: 'sphereWithHole'"), std::string::npos) << r.err;
}


// The corpus's figure: nearly closed (80 boundary edges in 28 796 triangles),
// its limbs and torso thinner than a lattice cell. It weighs what its surface
// nearly encloses (not the layer of cells it crosses, ten times that, under
// which it crushed itself on landing) and lands.
TEST(OpenMesh, AssimpFigureThinnerThanACellWeighsItsSolidAndLands) {
  const fs::path human = "/usr/share/assimp/models/Collada/human.zae";
  if (!fs::exists(human)) GTEST_SKIP() << "assimp-testmodels is not installed";
  const fs::path dir = scratch_dir("open_human");
  const fs::path scene = dir / "human.json";
  const CommandResult r = run_recoil("drop " + shell_quote(human) + " --seconds 1.4 --no-render -o " +
                                     shell_quote(dir / "out") + " --save-scene " + shell_quote(scene));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("encloses nothing"), std::string::npos) << r.err;
  const CommandResult info = run_recoil("info --json " + shell_quote(scene));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  // drop keeps its 1.66 m; soft is 1000 kg/m^3.
  const double signed_mass = 1000.0 * sim::enclosed_volume(sim::import_surface(human));
  EXPECT_NEAR(json::parse(info.out)["bodies"][1]["mass"].get<double>(), signed_mass, 0.02 * signed_mass);
}

// A flat open sheet encloses nothing: whether it is soft or rigid, and
// wherever it lies, it weighs the one-cell layer of lattice cells it crosses,
// and the summary says so.
TEST(OpenMesh, AFlatSheetIsNamedAndWeighsTheCellsItCrosses) {
  const fs::path dir = scratch_dir("flat_sheet");
  // 0.3 m square at y = 0.5 (a signed volume would read 0.5 * 0.09 / 3 m^3 there).
  const fs::path sheet = dir / "sheet.off";
  std::ofstream(sheet) << "OFF\n4 2 0\n0 0.5 0\n0.3 0.5 0\n0.3 0.5 0.3\n0 0.5 0.3\n3 0 1 2\n3 0 2 3\n";
  // 8 x 8 cells of 0.0375 m crossed, density 1000 (soft) and 1000 (rigid).
  const double layer_mass = 64 * std::pow(0.3 / 8, 3) * 1000.0;
  for (const char* material : {"soft", "rigid"}) {
    const fs::path scene = dir / (std::string(material) + ".json");
    const CommandResult r = run_recoil("drop " + shell_quote(sheet) + " --material " + material +
                                       " --seconds 0.01 --no-render -o " + shell_quote(dir / material) +
                                       " --save-scene " + shell_quote(scene));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("'sheet' is open and encloses nothing (a sheet, or parts thinner than 1/64 of its longest "
                         "side): its solid is the lattice cells its surface crosses, 3.38 kg"),
              std::string::npos)
        << material << ": " << r.err;
    const CommandResult info = run_recoil("info --json " + shell_quote(scene));
    ASSERT_EQ(info.exit_code, 0) << info.err;
    EXPECT_NEAR(json::parse(info.out)["bodies"][1]["mass"].get<double>(), layer_mass, 1e-6 * layer_mass) << material;
  }
  // A closed box encloses cells: no such warning.
  const fs::path box = write_box_off(dir / "box.off", Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1));
  const CommandResult closed = run_recoil("drop " + shell_quote(box) + " --seconds 0.01 --no-render -o " + shell_quote(dir / "box"));
  ASSERT_EQ(closed.exit_code, 0) << closed.err;
  EXPECT_EQ(closed.err.find("encloses nothing"), std::string::npos) << closed.err;
}

// A box with its lid off, dropped from above the ground (a signed volume
// about the world origin is off by the hole's area times its height over 3):
// soft or rigid, it weighs the solid its winding number fills, the box less at
// most the layer under the hole, and the summary does not call it empty.
TEST(OpenMesh, AnOpenBoxWeighsTheSolidItsWindingNumberFills) {
  const fs::path dir = scratch_dir("open_box_mass");
  const fs::path open =
      write_box_off(dir / "openbox.off", Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1), /*skip_top=*/true);
  for (const char* material : {"soft", "rigid"}) {
    const fs::path scene = dir / (std::string(material) + ".json");
    const CommandResult r = run_recoil("drop " + shell_quote(open) + " --material " + material +
                                       " --seconds 0.01 --no-render -o " + shell_quote(dir / material) +
                                       " --save-scene " + shell_quote(scene));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("encloses nothing"), std::string::npos) << r.err;
    const CommandResult info = run_recoil("info --json " + shell_quote(scene));
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const double mass = json::parse(info.out)["bodies"][1]["mass"].get<double>();  // density 1000, 0.008 m^3
    EXPECT_LE(mass, 8.0 + 1e-6) << material;
    EXPECT_GE(mass, 8.0 * 63.0 / 64.0 - 1e-6) << material;
  }
}

// A rigid body of a closed mesh wound inward is the solid it bounds: the
// import turns its faces outward, and it weighs 1000 kg/m^3 times 0.008 m^3.
TEST(OpenMesh, ARigidBodyWoundInwardWeighsItsSolid) {
  const fs::path dir = scratch_dir("inward_rigid");
  const fs::path inward = write_box_off(dir / "inward.off", Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1),
                                        false, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(p.x(), p.y(), -p.z()); });
  const fs::path scene = dir / "inward.json";
  const CommandResult r = run_recoil("drop " + shell_quote(inward) + " --material rigid --seconds 0.01 --no-render -q -o " +
                                     shell_quote(dir / "out") + " --save-scene " + shell_quote(scene));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CommandResult s = run_recoil("info --json " + shell_quote(scene));
  ASSERT_EQ(s.exit_code, 0) << s.err;
  EXPECT_NEAR(json::parse(s.out)["bodies"][1]["mass"].get<double>(), 8.0, 1e-5);  // the rigid preset's 1000 kg/m^3
}

}  // namespace recoil::test
