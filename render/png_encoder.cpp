/// @file png_encoder.cpp
#include "render/png_encoder.h"

#include "render/render_error.h"
#include "render/stb_png.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

namespace impulse2d::render {

namespace {

std::string errno_text(int error) { return std::strerror(error); }

// A name next to `path` that no other writer in this or another process uses.
std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  static std::atomic<unsigned long> counter{0};
  std::filesystem::path temporary = path;
  temporary += ".tmp-" + std::to_string(static_cast<long>(::getpid())) + "-" +
               std::to_string(counter.fetch_add(1));
  return temporary;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Frame& frame, PngEncoding encoding) {
  if (frame.width <= 0 || frame.height <= 0 ||
      frame.rgba.size() != frame.stride() * static_cast<std::size_t>(frame.height)) {
    throw RenderError("encode_png: frame " + std::to_string(frame.width) + "x" +
                      std::to_string(frame.height) + " with " + std::to_string(frame.rgba.size()) +
                      " bytes is not a valid RGBA frame");
  }
  std::vector<std::uint8_t> png;
  const bool ok = encoding == PngEncoding::Fast
                      ? detail::stb_png_fast(frame.rgba.data(), frame.width, frame.height, png)
                      : detail::stb_png_default(frame.rgba.data(), frame.width, frame.height, png);
  if (!ok) {
    throw RenderError("encode_png: stb_image_write failed on a " + std::to_string(frame.width) + "x" +
                      std::to_string(frame.height) + " frame (out of memory?)");
  }
  return png;
}

void write_file_atomically(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  const std::filesystem::path temporary = temporary_path_for(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw RenderError("cannot write '" + path.string() + "': creating '" + temporary.string() +
                      "' failed: " + errno_text(errno));
  }
  const auto fail = [&](const std::string& step, int error) {
    ::close(fd);
    ::unlink(temporary.c_str());
    throw RenderError("cannot write '" + path.string() + "': " + step + " failed: " + errno_text(error));
  };
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t written = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (written < 0) {
      if (errno == EINTR) continue;
      fail("write", errno);
    }
    done += static_cast<std::size_t>(written);
  }
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw RenderError("cannot write '" + path.string() + "': close failed: " + errno_text(error));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw RenderError("cannot write '" + path.string() + "': rename from '" + temporary.string() +
                      "' failed: " + errno_text(error));
  }
}

void write_png(const std::filesystem::path& path, const Frame& frame, PngEncoding encoding) {
  write_file_atomically(path, encode_png(frame, encoding));
}

}  // namespace impulse2d::render
