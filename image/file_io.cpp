/// @file file_io.cpp
#include "image/file_io.h"

#include "image/error.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <atomic>
#include <fstream>
#include <iterator>
#include <system_error>

namespace impulse2d::image {

namespace {

/// A name beside `file` that no other writer (thread or process) uses at the same time.
std::filesystem::path temporary_sibling(const std::filesystem::path& file) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temporary = file;
  temporary += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
  return temporary;
}

}  // namespace

std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& file) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(file, error);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw ImageError("cannot read '" + file.string() + "': not a regular file");
  }
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (!error && size > kMaxReadBytes) {
    throw ImageError("cannot read '" + file.string() + "': " + std::to_string(size) +
                      " bytes; the limit is " + std::to_string(kMaxReadBytes));
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ImageError("cannot open '" + file.string() + "' for reading");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
  if (in.bad()) throw ImageError("error reading '" + file.string() + "'");
  return bytes;
}

std::string read_text_file(const std::filesystem::path& file) {
  std::vector<std::uint8_t> bytes = read_file_bytes(file);
  return std::string(bytes.begin(), bytes.end());
}

void write_file_atomically(const std::filesystem::path& file, const void* data, std::size_t size) {
  std::error_code error;
  if (file.has_parent_path()) {
    std::filesystem::create_directories(file.parent_path(), error);
    if (error) {
      throw ImageError("cannot write '" + file.string() + "': creating the directory '" +
                       file.parent_path().string() + "' failed: " + error.message());
    }
  }
  const std::filesystem::path temporary = temporary_sibling(file);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw ImageError("cannot write '" + file.string() + "': creating '" + temporary.string() +
                     "' failed: " + std::strerror(errno));
  }
  const auto fail = [&](const std::string& step, int reason) {
    ::unlink(temporary.c_str());
    throw ImageError("cannot write '" + file.string() + "': " + step + " failed: " +
                     std::strerror(reason));
  };
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t written = ::write(fd, bytes + done, size - done);
    if (written < 0) {
      if (errno == EINTR) continue;
      const int reason = errno;
      ::close(fd);
      fail("write", reason);
    }
    done += static_cast<std::size_t>(written);
  }
  if (::close(fd) != 0) fail("close", errno);
  if (std::rename(temporary.c_str(), file.c_str()) != 0) {
    fail("rename from '" + temporary.string() + "'", errno);
  }
}

void write_file_atomically(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes) {
  write_file_atomically(file, bytes.data(), bytes.size());
}

void write_text_file_atomically(const std::filesystem::path& file, const std::string& text) {
  write_file_atomically(file, text.data(), text.size());
}

}  // namespace impulse2d::image
