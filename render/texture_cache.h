#pragma once
// TextureCache: one GL texture per image, however many meshes and materials
// share it (a pile of a thousand copies of a textured asset uploads its map
// once). Images are held, so an address is never reused while cached.
#include <map>
#include <memory>
#include <utility>

#include "render/gl_objects.h"
#include "render/image.h"

namespace recoil::render {

class TextureCache {
 public:
  // The image's texture (sRGB, mipmapped, repeating), uploaded on first use;
  // binds it to GL_TEXTURE_2D of the active texture unit.
  void bind(const std::shared_ptr<const Image>& image);

 private:
  std::map<const Image*, std::pair<std::shared_ptr<const Image>, gl::Texture>> m_textures;
};

}  // namespace recoil::render
