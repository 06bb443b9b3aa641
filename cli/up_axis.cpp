#include "cli/up_axis.h"

#include <cctype>

namespace recoil::cli {

std::optional<UpAxis> parse_up_axis(std::string_view text) {
  if (text.empty() || text.size() > 2) return std::nullopt;
  bool negative = false;
  if (text.size() == 2) {
    if (text[0] != '+' && text[0] != '-') return std::nullopt;
    negative = text[0] == '-';
    text.remove_prefix(1);
  }
  switch (std::toupper(static_cast<unsigned char>(text[0]))) {
    case 'X': return negative ? UpAxis::neg_x : UpAxis::pos_x;
    case 'Y': return negative ? UpAxis::neg_y : UpAxis::pos_y;
    case 'Z': return negative ? UpAxis::neg_z : UpAxis::pos_z;
    default: return std::nullopt;
  }
}

const char* to_string(UpAxis axis) {
  switch (axis) {
    case UpAxis::pos_x: return "+X";
    case UpAxis::neg_x: return "-X";
    case UpAxis::pos_y: return "+Y";
    case UpAxis::neg_y: return "-Y";
    case UpAxis::pos_z: return "+Z";
    case UpAxis::neg_z: return "-Z";
  }
  return "+Y";
}

Eigen::Matrix3d up_rotation(UpAxis axis) {
  Eigen::Matrix3d r;
  switch (axis) {
    case UpAxis::pos_y: r.setIdentity(); break;
    // Half a turn about X: (x, y, z) -> (x, -y, -z).
    case UpAxis::neg_y: r << 1, 0, 0, 0, -1, 0, 0, 0, -1; break;
    // A quarter turn about X, -90 degrees: (x, y, z) -> (x, z, -y).
    case UpAxis::pos_z: r << 1, 0, 0, 0, 0, 1, 0, -1, 0; break;
    // +90 degrees about X: (x, y, z) -> (x, -z, y).
    case UpAxis::neg_z: r << 1, 0, 0, 0, 0, -1, 0, 1, 0; break;
    // +90 degrees about Z: (x, y, z) -> (-y, x, z).
    case UpAxis::pos_x: r << 0, -1, 0, 1, 0, 0, 0, 0, 1; break;
    // -90 degrees about Z: (x, y, z) -> (y, -x, z).
    case UpAxis::neg_x: r << 0, 1, 0, -1, 0, 0, 0, 0, 1; break;
  }
  return r;
}

void apply_up(UpAxis axis, sim::TriMesh& mesh) {
  if (axis == UpAxis::pos_y) return;
  sim::transform_in_place(mesh, up_rotation(axis), Eigen::Vector3d::Ones(), Eigen::Vector3d::Zero());
}

void apply_up(UpAxis axis, sim::TetMesh& mesh) {
  if (axis == UpAxis::pos_y) return;
  sim::transform_in_place(mesh, up_rotation(axis), Eigen::Vector3d::Ones(), Eigen::Vector3d::Zero());
}

void add_up_option(CLI::App& command, UpAxis& up) {
  const CLI::Validator axis_check(
      [](std::string& text) {
        if (parse_up_axis(text)) return std::string();
        return "unknown up axis \"" + text + "\" (" + kUpAxisChoices + ")";
      },
      "+X|-X|+Y|-Y|+Z|-Z");
  command
      .add_option_function<std::string>(
          "--up", [&up](const std::string& text) { up = *parse_up_axis(text); },
          "The mesh file's up axis, turned onto world +Y (recoil is Y-up) before anything else; "
          "CAD and 3D-print files (STL, OBJ, OFF, PLY) are often +Z, and Blender's own .blend files are +Z. glTF is +Y by "
          "its specification. "
          "Default +Y")
      ->check(axis_check);
}

}  // namespace recoil::cli
