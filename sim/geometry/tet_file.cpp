// Gmsh and TetGen readers. Formats:
//  Gmsh 2.x: $Nodes: n, then "tag x y z"; $Elements: m, then "tag type ntags tags... nodes...".
//  Gmsh 4.1: $Nodes: "blocks n min max", per block "dim entity parametric k", k tags, k coordinate lines.
//  Gmsh 4.0: $Nodes: "blocks n", per block "entity dim parametric k", k lines "tag x y z".
//  Gmsh 4.x $Elements: per block "a b type k" then k lines "tag nodes...".
//  TetGen: .node "n 3 attrs markers" then "i x y z ..."; .ele "m 4|10 attrs" then "i n0 n1 n2 n3 ...".
#include "sim/geometry/tet_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "core/regular_file.h"
#include "sim/geometry/tet_file_lines.h"

namespace recoil::sim {

namespace {

using detail::LineReader;
using Tokens = std::vector<std::string_view>;

constexpr int kGmshTet4 = 4;
constexpr int kGmshTet10 = 11;  // quadratic tet: its first four nodes are the corners
bool is_gmsh_tet(long long type) { return type == kGmshTet4 || type == kGmshTet10; }

// The fewest bytes (newline included) of what a header counts, so that a
// count the file cannot hold fails before anything is reserved for it.
constexpr long long kNodeLineBytes = 8;      // "1 0 0 0\n"; Gmsh 4.1: "1\n" + "0 0 0\n"
constexpr long long kElementLineBytes = 6;   // Gmsh 2: "1 1 0\n" (tag type ntags)
constexpr long long kBlockHeaderBytes = 8;   // Gmsh 4: "0 1 0 1\n"
constexpr long long kTagLineBytes = 2;       // Gmsh 4 element: "1\n"
constexpr long long kTetLineBytes = 10;      // TetGen: "1 1 2 3 4\n"

// Collects nodes by tag and tets by node tags, then resolves and validates.
struct Builder {
  std::vector<Eigen::Vector3d> nodes;
  std::unordered_map<long long, int> index_of_tag;
  std::vector<std::array<long long, 4>> tet_tags;
  std::vector<int> tet_lines;

  void add_node(const LineReader& r, long long tag, const Eigen::Vector3d& p) {
    if (!index_of_tag.emplace(tag, static_cast<int>(nodes.size())).second)
      r.fail("duplicate node " + std::to_string(tag));
    nodes.push_back(p);
  }
  void add_tet(const LineReader& r, const Tokens& t, size_t first) {
    if (t.size() < first + 4) r.fail("a tetrahedron needs 4 node indices");
    std::array<long long, 4> tags;
    for (int k = 0; k < 4; ++k) tags[k] = r.to_int(t[first + k], "tet node");
    tet_tags.push_back(tags);
    tet_lines.push_back(r.line());
  }

  TetMesh finish(const std::string& name) const {
    if (tet_tags.empty()) throw bad_input(name + ": no tetrahedra in the file");
    TetMesh mesh;
    mesh.nodes.resize(static_cast<Eigen::Index>(nodes.size()), 3);
    for (size_t i = 0; i < nodes.size(); ++i) mesh.nodes.row(static_cast<Eigen::Index>(i)) = nodes[i].transpose();
    mesh.tets.resize(static_cast<Eigen::Index>(tet_tags.size()), 4);
    for (size_t t = 0; t < tet_tags.size(); ++t) {
      for (int k = 0; k < 4; ++k) {
        const auto it = index_of_tag.find(tet_tags[t][k]);
        if (it == index_of_tag.end())
          throw bad_input(name + ":" + std::to_string(tet_lines[t]) + ": tetrahedron uses unknown node " +
                          std::to_string(tet_tags[t][k]));
        mesh.tets(static_cast<Eigen::Index>(t), k) = it->second;
      }
    }
    // Positive orientation; a (near) zero-volume tet is an error of the file.
    const Aabb box = bounding_box(mesh.nodes);
    const double diag = box.extent().norm();
    const double eps = 1e-14 * diag * diag * diag;
    for (int t = 0; t < mesh.num_tets(); ++t) {
      const double v = tet_volume(mesh, t);
      if (!(std::abs(v) > eps))
        throw bad_input(name + ":" + std::to_string(tet_lines[static_cast<size_t>(t)]) +
                        ": degenerate (zero-volume) tetrahedron");
      if (v < 0.0) std::swap(mesh.tets(t, 2), mesh.tets(t, 3));
    }
    remove_unused_nodes(mesh);
    return mesh;
  }
};

Eigen::Vector3d read_point(const LineReader& r, const Tokens& t, size_t first) {
  if (t.size() < first + 3) r.fail("a node needs x y z");
  return {r.to_double(t[first], "x"), r.to_double(t[first + 1], "y"), r.to_double(t[first + 2], "z")};
}

void expect_end(LineReader& r, const char* end_tag) {
  const Tokens t = r.expect(end_tag);
  if (t[0] != end_tag) r.fail(std::string("expected ") + end_tag);
}

void gmsh_nodes_v2(LineReader& r, Builder& b) {
  const long long n = r.declared_count(r.expect("node count")[0], "nodes", kNodeLineBytes);
  for (long long i = 0; i < n; ++i) {
    const Tokens t = r.expect("a node line");
    if (t.size() < 4) r.fail("a node line needs: tag x y z");
    b.add_node(r, r.to_int(t[0], "node tag"), read_point(r, t, 1));
  }
}

void gmsh_elements_v2(LineReader& r, Builder& b) {
  const long long m = r.declared_count(r.expect("element count")[0], "elements", kElementLineBytes);
  for (long long i = 0; i < m; ++i) {
    const Tokens t = r.expect("an element line");
    if (t.size() < 3) r.fail("an element line needs: tag type ntags ...");
    const long long type = r.to_int(t[1], "element type");
    const long long ntags = r.to_count(t[2], "tag count", 64);
    if (is_gmsh_tet(type)) b.add_tet(r, t, 3 + static_cast<size_t>(ntags));
  }
}

void gmsh_nodes_v4(LineReader& r, Builder& b, bool v41) {
  const Tokens head = r.expect("node section header");
  const long long blocks = r.declared_count(head[0], "node blocks", kBlockHeaderBytes);
  if (head.size() > 1) r.declared_count(head[1], "nodes", kNodeLineBytes);  // the total, over all blocks
  for (long long bi = 0; bi < blocks; ++bi) {
    const Tokens bh = r.expect("a node block header");
    if (bh.size() < 4) r.fail("a node block header needs 4 numbers");
    const bool parametric = r.to_int(bh[2], "parametric flag") != 0;
    const long long k = r.declared_count(bh[3], "nodes in a block", kNodeLineBytes);
    if (v41) {
      std::vector<long long> tags;
      for (long long i = 0; i < k; ++i) tags.push_back(r.to_int(r.expect("a node tag")[0], "node tag"));
      for (long long i = 0; i < k; ++i) {
        const Tokens t = r.expect("node coordinates");
        b.add_node(r, tags[static_cast<size_t>(i)], read_point(r, t, 0));
      }
    } else {
      for (long long i = 0; i < k; ++i) {
        const Tokens t = r.expect("a node line");
        b.add_node(r, r.to_int(t[0], "node tag"), read_point(r, t, 1));
      }
    }
    (void)parametric;  // extra parametric coordinates follow xyz on the same line
  }
}

void gmsh_elements_v4(LineReader& r, Builder& b) {
  const Tokens head = r.expect("element section header");
  const long long blocks = r.declared_count(head[0], "element blocks", kBlockHeaderBytes);
  if (head.size() > 1) r.declared_count(head[1], "elements", kTagLineBytes);
  for (long long bi = 0; bi < blocks; ++bi) {
    const Tokens bh = r.expect("an element block header");
    if (bh.size() < 4) r.fail("an element block header needs 4 numbers");
    const long long type = r.to_int(bh[2], "element type");
    const long long k = r.declared_count(bh[3], "elements in a block", kTagLineBytes);
    for (long long i = 0; i < k; ++i) {
      const Tokens t = r.expect("an element line");
      if (is_gmsh_tet(type)) b.add_tet(r, t, 1);
    }
  }
}

}  // namespace

TetMesh parse_gmsh(const std::string& text, const std::string& name) {
  LineReader r(text, name, 0);
  Builder b;
  int major = 0;
  bool v41 = false;
  Tokens t;
  while (r.next(t)) {
    const std::string_view tag = t[0];
    if (tag == "$MeshFormat") {
      const Tokens f = r.expect("the format line");
      if (f.size() < 2) r.fail("format line needs: version file-type data-size");
      const double version = r.to_double(f[0], "version");
      if (r.to_int(f[1], "file type") != 0) r.fail("binary .msh files are not supported; save as ASCII");
      // Checked before the cast: a double beyond int's range has no int value.
      major = version >= 2.0 && version < 5.0 ? static_cast<int>(version) : -1;
      v41 = version >= 4.05;
      if (major != 2 && major != 4) r.fail("unsupported Gmsh version " + std::string(f[0]) + " (use 2.2 or 4.1)");
      expect_end(r, "$EndMeshFormat");
    } else if (tag == "$Nodes" || tag == "$Elements") {
      if (major == 0) r.fail(std::string(tag) + " before $MeshFormat");
      if (tag == "$Nodes") {
        if (major == 2) gmsh_nodes_v2(r, b);
        else gmsh_nodes_v4(r, b, v41);
        expect_end(r, "$EndNodes");
      } else {
        if (major == 2) gmsh_elements_v2(r, b);
        else gmsh_elements_v4(r, b);
        expect_end(r, "$EndElements");
      }
    } else if (tag.size() > 1 && tag[0] == '$') {
      // Any other section ($Entities, $PhysicalNames, ...): skip to its end.
      const std::string end = "$End" + std::string(tag.substr(1));
      Tokens s;
      bool closed = false;
      while (r.next(s))
        if (s[0] == end) { closed = true; break; }
      if (!closed) r.fail("section " + std::string(tag) + " is not closed by " + end);
    } else {
      r.fail("unexpected '" + std::string(tag.substr(0, 32)) + "' outside a section");
    }
  }
  if (major == 0) throw bad_input(name + ": not a Gmsh file (no $MeshFormat)");
  return b.finish(name);
}

TetMesh parse_tetgen(const std::string& node_text, const std::string& node_name,
                     const std::string& ele_text, const std::string& ele_name) {
  Builder b;
  {
    LineReader r(node_text, node_name, '#');
    const Tokens h = r.expect("the header: count dimension attributes markers");
    const long long n = r.declared_count(h[0], "nodes", kNodeLineBytes);
    if (h.size() > 1 && r.to_int(h[1], "dimension") != 3) r.fail("dimension must be 3");
    for (long long i = 0; i < n; ++i) {
      const Tokens t = r.expect("a node line");
      if (t.size() < 4) r.fail("a node line needs: index x y z");
      b.add_node(r, r.to_int(t[0], "node index"), read_point(r, t, 1));
    }
  }
  LineReader r(ele_text, ele_name, '#');
  const Tokens h = r.expect("the header: count nodes-per-tet attributes");
  const long long m = r.declared_count(h[0], "tetrahedra", kTetLineBytes);
  if (h.size() > 1) {
    const long long per = r.to_int(h[1], "nodes per tet");
    if (per != 4 && per != 10) r.fail("nodes per tetrahedron must be 4 or 10");
  }
  for (long long i = 0; i < m; ++i) b.add_tet(r, r.expect("a tetrahedron line"), 1);
  return b.finish(ele_name);
}

TetMesh read_tet_file(const std::filesystem::path& path) {
  static const std::string kWhat = "tet mesh file";
  const std::string ext = path.extension().string();
  if (ext == ".msh") return parse_gmsh(read_regular_file(path, kWhat), path.string());
  if (ext == ".node" || ext == ".ele") {
    std::filesystem::path node = path, ele = path;
    node.replace_extension(".node");
    ele.replace_extension(".ele");
    return parse_tetgen(read_regular_file(node, kWhat), node.string(), read_regular_file(ele, kWhat), ele.string());
  }
  throw bad_input(path.string() + ": unknown tet mesh extension '" + ext + "' (expected .msh, .node or .ele)");
}

}  // namespace recoil::sim
