#include "sim/geometry/look_import.h"

#include <assimp/material.h>
#include <assimp/scene.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "core/byte_stream.h"
#include "core/error.h"
#include "core/lower_case.h"
#include "sim/geometry/isolated_reader.h"

namespace recoil::sim {
namespace fs = std::filesystem;

namespace {

// Larger maps are refused before decoding (one of 8192 x 8192 is 256 MiB of
// pixels): a preview needs no bigger texture.
constexpr int kLargestTextureSide = 8192;

// A factor read from the file clamped to [0, 1]; `fallback` when it is not a number.
float unit_interval(float x, float fallback) { return std::isfinite(x) ? std::clamp(x, 0.0f, 1.0f) : fallback; }

bool fits(long long width, long long height) {
  return width > 0 && height > 0 && width <= kLargestTextureSide && height <= kLargestTextureSide;
}

std::string size_text(long long width, long long height) {
  return std::to_string(width) + " x " + std::to_string(height) + " pixels is more than " +
         std::to_string(kLargestTextureSide) + " a side";
}

// `path` if it is a file, else a file in its folder whose name differs only in case.
std::optional<fs::path> existing_file(const fs::path& path) {
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) return path;
  const std::string wanted = lower_case(path.filename().string());
  if (wanted.empty()) return std::nullopt;
  for (fs::directory_iterator it(path.parent_path(), ec), end; !ec && it != end; it.increment(ec))
    if (lower_case(it->path().filename().string()) == wanted && it->is_regular_file(ec)) return it->path();
  return std::nullopt;
}

// The image file a material names, as an artist's file names it: relative
// to the mesh's folder, with Windows separators, Blender's "//" prefix or a
// path on the machine it was made on, and in any case. Failing the path as
// written, the file name alone is looked for beside the mesh.
fs::path locate_image(const fs::path& folder, std::string name) {
  std::replace(name.begin(), name.end(), '\\', '/');
  if (name.rfind("//", 0) == 0) name.erase(0, 2);  // Blender: relative to the .blend file
  const fs::path written(name);
  const fs::path as_written = written.is_absolute() ? written : folder / written.relative_path();
  if (const auto found = existing_file(as_written)) return *found;
  if (const auto found = existing_file(folder / written.filename())) return *found;
  return as_written;
}

// Where the texture assimp calls `name` comes from: embedded ("*0", or a name
// glTF gives its embedded images) or an image file beside the mesh.
TextureSource find_texture(const aiScene& scene, const std::string& name, const fs::path& mesh_file,
                           std::vector<std::string>& warnings) {
  TextureSource source;
  source.name = printable(name);
  const aiTexture* embedded = scene.GetEmbeddedTexture(name.c_str());
  if (!embedded) {
    source.file = locate_image(mesh_file.parent_path(), name);
    return source;
  }
  if (!embedded->pcData) {
    warnings.push_back("texture '" + source.name + "' not drawn: the embedded image holds no data");
  } else if (embedded->mHeight == 0) {  // a compressed image file of mWidth bytes
    source.encoded.assign(reinterpret_cast<const char*>(embedded->pcData), embedded->mWidth);
  } else if (!fits(embedded->mWidth, embedded->mHeight)) {
    warnings.push_back("texture '" + source.name + "' not drawn: " + size_text(embedded->mWidth, embedded->mHeight));
  } else {  // raw BGRA texels
    source.pixels = RgbaImage(static_cast<int>(embedded->mWidth), static_cast<int>(embedded->mHeight));
    for (size_t i = 0; i < static_cast<size_t>(embedded->mWidth) * embedded->mHeight; ++i) {
      const aiTexel& t = embedded->pcData[i];
      std::uint8_t* p = source.pixels.rgba.data() + 4 * i;
      p[0] = t.r, p[1] = t.g, p[2] = t.b, p[3] = t.a;
    }
  }
  return source;
}

// In the decoder's child: the image's pixels, its size checked before decoding.
RgbaImage decode_image(const TextureSource& source) {
  const bool in_memory = source.file.empty();
  std::string bytes = source.encoded;
  if (!in_memory) {
    std::error_code ec;
    if (!fs::is_regular_file(source.file, ec)) throw bad_input("no such image file " + source.file.string());
  }
  int width = 0, height = 0, channels = 0;
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(std::min<size_t>(bytes.size(), INT32_MAX));
  const bool known = in_memory ? stbi_info_from_memory(data, size, &width, &height, &channels)
                               : stbi_info(source.file.c_str(), &width, &height, &channels);
  auto reason = [] { return std::string(stbi_failure_reason() ? stbi_failure_reason() : "unknown"); };
  if (!known) throw bad_input("not an image stb_image reads (" + reason() + ")");
  if (!fits(width, height)) throw bad_input(size_text(width, height));
  stbi_uc* pixels = in_memory ? stbi_load_from_memory(data, size, &width, &height, &channels, 4)
                              : stbi_load(source.file.c_str(), &width, &height, &channels, 4);
  if (!pixels) throw bad_input("a broken image (stb_image: " + reason() + ")");
  RgbaImage image;
  image.width = width;
  image.height = height;
  image.rgba.assign(pixels, pixels + static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
  stbi_image_free(pixels);
  return image;
}

void put_image(std::string& bytes, const RgbaImage& image) {
  put_value(bytes, std::array<int, 2>{image.width, image.height});
  put_array(bytes, image.rgba);
}

RgbaImage get_image(ByteReader& in) {
  RgbaImage image;
  const auto size = in.value<std::array<int, 2>>();
  image.width = size[0];
  image.height = size[1];
  image.rgba = in.array<std::uint8_t>();
  RECOIL_CHECK(image.width >= 0 && image.height >= 0 &&
                   image.rgba.size() == static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 4,
               "image " << image.width << " x " << image.height << " in " << image.rgba.size() << " bytes");
  return image;
}

// Whether the file's format can carry materials at all: OFF, PLY and STL
// carry geometry and, at most, vertex colours (read apart from materials).
bool format_has_materials(const fs::path& file) {
  const std::string extension = lower_case(file.extension().string());
  return extension != ".off" && extension != ".ply" && extension != ".stl";
}

}  // namespace

std::vector<LookMaterial> read_materials(const aiScene& scene, const fs::path& mesh_file,
                                         std::vector<TextureSource>& textures, std::vector<std::string>& warnings) {
  std::vector<LookMaterial> out;
  for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
    LookMaterial m;
    const aiMaterial* material = scene.mMaterials ? scene.mMaterials[i] : nullptr;
    if (!material) {
      out.push_back(m);
      continue;
    }
    aiString name;
    if (material->Get(AI_MATKEY_NAME, name) == AI_SUCCESS) m.name = printable(name.C_Str());
    // assimp invents a material for files that have none (a grey
    // "DefaultMaterial", or an unnamed grey or white one for OFF and PLY):
    // that is no colour of the file's.
    if (m.name != AI_DEFAULT_MATERIAL_NAME && format_has_materials(mesh_file)) {
      aiColor4D color;
      if (material->Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS ||
          material->Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS) {
        m.has_color = true;
        m.color = {unit_interval(color.r, 1.0f), unit_interval(color.g, 1.0f), unit_interval(color.b, 1.0f)};
      }
      // A metallic-roughness map (not drawn) scales the factors, which glTF
      // then often leaves at their default of 1: without it they would
      // draw a full metal, so such a material keeps the studio's surface.
      const bool mapped = material->GetTextureCount(aiTextureType_METALNESS) > 0 ||
                          material->GetTextureCount(aiTextureType_DIFFUSE_ROUGHNESS) > 0;
      float metallic = 0.0f, roughness = 1.0f;
      const bool has_metallic = material->Get(AI_MATKEY_METALLIC_FACTOR, metallic) == AI_SUCCESS;
      if (!mapped && material->Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness) == AI_SUCCESS) {
        m.has_surface = true;
        m.metallic = has_metallic ? unit_interval(metallic, 0.0f) : 0.0f;
        m.roughness = unit_interval(roughness, 1.0f);
      }
    }
    for (aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
      aiString path;
      if (material->GetTexture(type, 0, &path) != AI_SUCCESS || path.length == 0) continue;
      TextureSource source = find_texture(scene, path.C_Str(), mesh_file, warnings);
      source.material = static_cast<int>(i);
      textures.push_back(std::move(source));
      break;
    }
    out.push_back(std::move(m));
  }
  return out;
}

void encode_texture_sources(const std::vector<TextureSource>& textures, std::string& bytes) {
  put_value(bytes, static_cast<std::int64_t>(textures.size()));
  for (const TextureSource& t : textures) {
    put_value(bytes, t.material);
    put_string(bytes, t.name);
    put_string(bytes, t.file.string());
    put_string(bytes, t.encoded);
    put_image(bytes, t.pixels);
  }
}

std::vector<TextureSource> decode_texture_sources(const std::string& bytes, size_t& offset) {
  ByteReader in(bytes, offset);
  std::vector<TextureSource> textures(in.count(1));
  for (TextureSource& t : textures) {
    t.material = in.value<int>();
    t.name = in.string();
    t.file = in.string();
    t.encoded = in.string();
    t.pixels = get_image(in);
  }
  offset = in.offset();
  return textures;
}

void decode_textures(const std::vector<TextureSource>& textures, std::vector<LookMaterial>& materials,
                     std::vector<std::string>& warnings) {
  // One decode per image: by its file (normalised) or, embedded, by its name.
  std::map<std::string, std::shared_ptr<const RgbaImage>> decoded;
  for (const TextureSource& source : textures) {
    if (source.material < 0 || static_cast<size_t>(source.material) >= materials.size()) continue;
    const bool raw = source.file.empty() && source.encoded.empty();
    if (raw && source.pixels.empty()) continue;  // already warned about in the reader
    std::error_code ec;
    const std::string key = source.file.empty() ? "embedded:" + source.name : fs::weakly_canonical(source.file, ec).string();
    auto found = decoded.find(key);
    if (found == decoded.end()) {
      std::shared_ptr<const RgbaImage> image;
      if (raw) {
        image = std::make_shared<const RgbaImage>(source.pixels);
      } else {
        // stb_image decodes tens of MiB a second; 5 s plus 1 s per MiB of file is ample.
        const uintmax_t size = source.file.empty() ? source.encoded.size() : fs::file_size(source.file, ec);
        const int cpu_seconds = 5 + static_cast<int>(std::min<uintmax_t>((ec ? 0 : size) >> 20, 1 << 20));
        try {
          const std::string answer = read_in_child(
              [&] {
                std::string bytes;
                put_image(bytes, decode_image(source));
                return bytes;
              },
              "texture '" + source.name + "'", "the image decoder (stb_image)", cpu_seconds);
          ByteReader in(answer);
          image = std::make_shared<const RgbaImage>(get_image(in));
        } catch (const Error& e) {
          if (e.kind() != ErrorKind::bad_input) throw;
          warnings.push_back("texture '" + source.name + "' of material '" + materials[static_cast<size_t>(source.material)].name +
                             "' not drawn: " + printable(e.what(), 300));
        }
      }
      found = decoded.emplace(key, std::move(image)).first;
    }
    materials[static_cast<size_t>(source.material)].texture = found->second;
  }
}

}  // namespace recoil::sim
