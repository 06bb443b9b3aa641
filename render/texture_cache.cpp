#include "render/texture_cache.h"

namespace recoil::render {

void TextureCache::bind(const std::shared_ptr<const Image>& image) {
  auto found = m_textures.find(image.get());
  if (found != m_textures.end()) {
    glBindTexture(GL_TEXTURE_2D, found->second.second.get());
    return;
  }
  gl::Texture texture = gl::Texture::create();
  glBindTexture(GL_TEXTURE_2D, texture.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, image->width, image->height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               image->rgba.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  m_textures.emplace(image.get(), std::make_pair(image, std::move(texture)));
}

}  // namespace recoil::render
