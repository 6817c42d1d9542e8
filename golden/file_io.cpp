/// @file file_io.cpp
#include "golden/file_io.h"

#include "golden/error.h"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <iterator>
#include <system_error>

namespace impulse2d::golden {

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
    throw GoldenError("cannot read '" + file.string() + "': not a regular file");
  }
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (!error && size > kMaxReadBytes) {
    throw GoldenError("cannot read '" + file.string() + "': " + std::to_string(size) +
                      " bytes; the limit is " + std::to_string(kMaxReadBytes));
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw GoldenError("cannot open '" + file.string() + "' for reading");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
  if (in.bad()) throw GoldenError("error reading '" + file.string() + "'");
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
      throw GoldenError("cannot create directory '" + file.parent_path().string() +
                        "': " + error.message());
    }
  }
  const std::filesystem::path temporary = temporary_sibling(file);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw GoldenError("cannot open '" + temporary.string() + "' for writing");
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
      std::filesystem::remove(temporary, error);
      throw GoldenError("error writing '" + temporary.string() + "'");
    }
  }
  std::filesystem::rename(temporary, file, error);
  if (error) {
    const std::string reason = error.message();
    std::filesystem::remove(temporary, error);
    throw GoldenError("cannot rename '" + temporary.string() + "' to '" + file.string() +
                      "': " + reason);
  }
}

void write_text_file_atomically(const std::filesystem::path& file, const std::string& text) {
  write_file_atomically(file, text.data(), text.size());
}

}  // namespace impulse2d::golden
