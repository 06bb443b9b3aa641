#pragma once
// The materials of an assimp scene as SurfaceLook materials, and their
// base-colour textures. The mesh reader's child (isolated_reader.h) reads the
// materials and finds each texture (a file beside the mesh, or bytes
// embedded in it); the parent then decodes each distinct texture with
// stb_image in a child of its own, so an image that is missing, broken or too
// slow to decode costs that texture (a warning), never the mesh.
#include <filesystem>
#include <string>
#include <vector>

#include "core/rgba_image.h"
#include "sim/geometry/surface_look.h"

struct aiScene;

namespace recoil::sim {

// A material's texture before decoding.
struct TextureSource {
  int material = -1;           // index into the materials
  std::string name;            // as the file names it (printable), for messages
  std::filesystem::path file;  // an image file; empty when embedded
  std::string encoded;         // an embedded image file's bytes (PNG, JPEG, ...)
  RgbaImage pixels;            // an embedded image stored as raw texels (already decoded)
};

// Runs in the mesh reader's child: one material per material of the scene,
// in its order, and the textures they name. External paths are taken
// relative to the mesh file's folder. An embedded image too large to keep is
// a warning here.
std::vector<LookMaterial> read_materials(const aiScene& scene, const std::filesystem::path& mesh_file,
                                         std::vector<TextureSource>& textures, std::vector<std::string>& warnings);

// The sources as bytes and back (the mesh reader's answer carries them).
void encode_texture_sources(const std::vector<TextureSource>& textures, std::string& bytes);
std::vector<TextureSource> decode_texture_sources(const std::string& bytes, size_t& offset);

// Runs in the parent: decodes each distinct source (by file or embedded
// name) in a child process and sets the materials' textures; one that cannot
// be read adds a line to `warnings` naming it, and its materials stay untextured.
void decode_textures(const std::vector<TextureSource>& textures, std::vector<LookMaterial>& materials,
                     std::vector<std::string>& warnings);

}  // namespace recoil::sim
