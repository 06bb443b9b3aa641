#include "sim/geometry/look_import.h"

#include <assimp/material.h>
#include <assimp/scene.h>
#include <stb_image.h>

#include <algorithm>
#include <map>

namespace recoil::sim {
namespace fs = std::filesystem;

namespace {

// Larger maps are decoded but not kept: a preview needs no 64 MiB texture.
constexpr int kLargestTextureSide = 8192;

std::shared_ptr<const LookImage> from_stb(stbi_uc* pixels, int width, int height) {
  if (!pixels) return nullptr;
  auto image = std::make_shared<LookImage>();
  image->width = width;
  image->height = height;
  image->rgba.assign(pixels, pixels + static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
  stbi_image_free(pixels);
  return image;
}

std::string decoder_reason() {
  const char* reason = stbi_failure_reason();
  return reason ? reason : "unknown reason";
}

// Decodes the texture assimp names `name`: embedded ("*0", or a name glTF
// gives its embedded images) or a file beside the mesh. Sets `error` on failure.
std::shared_ptr<const LookImage> decode_texture(const aiScene& scene, const std::string& name, const fs::path& mesh_file,
                                                std::string& error) {
  std::shared_ptr<const LookImage> image;
  int width = 0, height = 0, channels = 0;
  if (const aiTexture* embedded = scene.GetEmbeddedTexture(name.c_str())) {
    if (!embedded->pcData) {
      error = "embedded image holds no data";
      return nullptr;
    }
    if (embedded->mHeight == 0) {  // compressed (PNG, JPEG, ...): mWidth bytes
      if (embedded->mWidth > static_cast<unsigned>(INT32_MAX)) {
        error = "embedded image too large";
        return nullptr;
      }
      stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(embedded->pcData),
                                              static_cast<int>(embedded->mWidth), &width, &height, &channels, 4);
      image = from_stb(pixels, width, height);
      if (!image) error = decoder_reason();
    } else {  // raw BGRA texels
      auto raw = std::make_shared<LookImage>();
      raw->width = static_cast<int>(embedded->mWidth);
      raw->height = static_cast<int>(embedded->mHeight);
      raw->rgba.reserve(static_cast<size_t>(raw->width) * static_cast<size_t>(raw->height) * 4);
      for (size_t i = 0; i < static_cast<size_t>(raw->width) * static_cast<size_t>(raw->height); ++i) {
        const aiTexel& t = embedded->pcData[i];
        raw->rgba.insert(raw->rgba.end(), {t.r, t.g, t.b, t.a});
      }
      image = raw;
    }
  } else {
    std::string relative = name;
    std::replace(relative.begin(), relative.end(), '\\', '/');  // paths written on Windows
    const fs::path file = fs::path(relative).is_absolute() ? fs::path(relative) : mesh_file.parent_path() / relative;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
      error = "no such file " + file.string();
      return nullptr;
    }
    stbi_uc* pixels = stbi_load(file.c_str(), &width, &height, &channels, 4);
    image = from_stb(pixels, width, height);
    if (!image) error = decoder_reason();
  }
  if (image && (image->width > kLargestTextureSide || image->height > kLargestTextureSide)) {
    error = std::to_string(image->width) + " x " + std::to_string(image->height) + " pixels is more than " +
            std::to_string(kLargestTextureSide) + " a side";
    return nullptr;
  }
  return image;
}

}  // namespace

std::vector<LookMaterial> read_materials(const aiScene& scene, const fs::path& mesh_file,
                                         std::vector<std::string>& warnings) {
  std::vector<LookMaterial> out;
  std::map<std::string, std::shared_ptr<const LookImage>> decoded;  // shared maps decode once
  for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
    LookMaterial m;
    const aiMaterial* material = scene.mMaterials ? scene.mMaterials[i] : nullptr;
    if (!material) {
      out.push_back(m);
      continue;
    }
    aiString name;
    if (material->Get(AI_MATKEY_NAME, name) == AI_SUCCESS) m.name = name.C_Str();
    // assimp invents a grey "DefaultMaterial" for files that have none: that is no colour of the file's.
    if (m.name != AI_DEFAULT_MATERIAL_NAME) {
      aiColor4D color;
      if (material->Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS ||
          material->Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS) {
        m.has_color = true;
        m.color = {std::clamp(color.r, 0.0f, 1.0f), std::clamp(color.g, 0.0f, 1.0f), std::clamp(color.b, 0.0f, 1.0f)};
      }
    }
    for (aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
      aiString path;
      if (material->GetTexture(type, 0, &path) != AI_SUCCESS || path.length == 0) continue;
      const std::string key = path.C_Str();
      auto found = decoded.find(key);
      if (found == decoded.end()) {
        std::string error;
        found = decoded.emplace(key, decode_texture(scene, key, mesh_file, error)).first;
        if (!found->second)
          warnings.push_back("texture '" + key + "' of material '" + m.name + "' not drawn: " + error);
      }
      m.texture = found->second;
      break;
    }
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace recoil::sim
