#include "render/png.h"

#include <png.h>

#include <cstdio>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <memory>

#include "core/atomic_write.h"
#include "core/error.h"
#include "core/regular_file.h"

namespace recoil::render {
namespace fs = std::filesystem;

namespace {

// libpng reports errors through a callback that must not throw across C
// frames, so errors are recorded here and the call unwinds with longjmp.
struct PngError {
  char message[256] = "";
};

void on_png_error(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngError*>(png_get_error_ptr(png));
  std::snprintf(error->message, sizeof(error->message), "%s", message);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + length);
}

void flush_nothing(png_structp) {}

// Encodes with setjmp-based error handling; nothing with a destructor lives in
// this frame between setjmp and the libpng calls.
bool encode_raw(const Image& image, bool opaque, const PngOptions& options, std::vector<std::uint8_t>* out,
                PngError* error, std::vector<png_bytep>* rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, error, on_png_error, on_png_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, info ? &info : nullptr);
    return false;
  }
  png_set_write_fn(png, out, append_bytes, flush_nothing);
  png_set_IHDR(png, info, image.width, image.height, 8, opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, options.level);
  if (options.fast_filter) png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_rows(png, info, rows->data());
  png_write_png(png, info, opaque ? PNG_TRANSFORM_STRIP_FILLER_AFTER : PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image, const PngOptions& options) {
  if (image.empty()) throw Error(ErrorKind::internal, "cannot encode an empty image as PNG");
  std::vector<png_bytep> rows(image.height);
  for (int y = 0; y < image.height; ++y) rows[y] = const_cast<png_bytep>(image.pixel(0, y));
  std::vector<std::uint8_t> out;
  out.reserve(image.rgba.size() / 4);
  PngError error;
  if (!encode_raw(image, !options.alpha, options, &out, &error, &rows))
    throw Error(ErrorKind::internal, std::string("PNG encoding failed: ") + error.message);
  return out;
}

void write_png(const fs::path& path, const Image& image, const PngOptions& options) {
  const std::vector<std::uint8_t> bytes = encode_png(image, options);
  replace_file(path, bytes.data(), bytes.size());
}

namespace {

struct ReadSource {
  const std::string* bytes;
  size_t offset = 0;
};

void read_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* source = static_cast<ReadSource*>(png_get_io_ptr(png));
  if (length > source->bytes->size() - source->offset) png_error(png, "file is truncated");
  std::memcpy(data, source->bytes->data() + source->offset, length);
  source->offset += length;
}

// The largest image read: the largest render (16384 x 16384 pixels, 1 GiB as RGBA8).
constexpr double kMaxPixels = 16384.0 * 16384.0;
// zlib's deflate packs at most about 1032 bytes into one, so a PNG's filtered
// rows cannot be more than this many times its file size.
constexpr double kMaxDeflateRatio = 1032.0;

// Refuses (through png_error) a header whose pixels the file cannot hold, before
// the pixels are allocated; the message is formatted without heap memory since png_error longjmps.
void check_declared_size(png_structp png, png_infop info, const ReadSource& source) {
  const double width = png_get_image_width(png, info), height = png_get_image_height(png, info);
  const double filtered_bytes = height * (static_cast<double>(png_get_rowbytes(png, info)) + 1.0);
  char message[160];
  if (width * height > kMaxPixels) {
    std::snprintf(message, sizeof(message), "%.0f x %.0f pixels is more than the 16384 x 16384 read", width, height);
    png_error(png, message);
  }
  if (filtered_bytes > kMaxDeflateRatio * static_cast<double>(source.bytes->size())) {
    std::snprintf(message, sizeof(message), "declares %.0f x %.0f pixels, more than its %zu bytes can hold", width,
                  height, source.bytes->size());
    png_error(png, message);
  }
}

// `rows` belongs to the caller so that a longjmp out of libpng leaks nothing.
bool decode_raw(ReadSource* source, Image* image, PngError* error, std::vector<png_bytep>* rows) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, error, on_png_error, on_png_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    return false;
  }
  png_set_read_fn(png, source, read_bytes);
  png_read_info(png, info);
  check_declared_size(png, info, *source);
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  // Normalise every colour type and depth to 8-bit RGBA.
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (png_get_rowbytes(png, info) != width * 4) png_error(png, "unsupported pixel layout");
  image->width = static_cast<int>(width);
  image->height = static_cast<int>(height);
  image->rgba.resize(static_cast<size_t>(width) * height * 4);
  rows->resize(height);
  for (png_uint_32 y = 0; y < height; ++y) (*rows)[y] = image->pixel(0, static_cast<int>(y));
  png_read_image(png, rows->data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

// libpng allocates a chunk's declared length before reading it (an iTXt
// chunk claiming 1.4 GB in a 57-byte file), so every chunk must be seen to
// fit inside the file first. Throws bad_input naming the chunk.
void check_chunks_fit(const std::string& bytes, const fs::path& path) {
  size_t offset = 8;
  while (offset + 8 <= bytes.size()) {  // a chunk's length and type
    const auto* chunk = reinterpret_cast<png_const_bytep>(bytes.data() + offset);
    const size_t length = png_get_uint_32(chunk);
    if (offset + 12 > bytes.size() || length > bytes.size() - offset - 12)
      throw bad_input(path.string() + ": PNG chunk '" + bytes.substr(offset + 4, 4) + "' at byte " +
                      std::to_string(offset) + " declares " + std::to_string(length) +
                      " bytes, more than the file holds");
    if (std::memcmp(chunk + 4, "IEND", 4) == 0) return;
    offset += 12 + length;
  }
}

}  // namespace

Image read_png(const fs::path& path) {
  const std::string bytes = read_regular_file(path, "PNG file");
  if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0)
    throw bad_input(path.string() + ": not a PNG file");
  check_chunks_fit(bytes, path);
  ReadSource source{&bytes};
  Image image;
  PngError error;
  std::vector<png_bytep> rows;
  if (!decode_raw(&source, &image, &error, &rows))
    throw bad_input(path.string() + ": unreadable PNG: " + error.message);
  return image;
}

}  // namespace recoil::render
