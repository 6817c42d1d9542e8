#pragma once
/// @file file_io.h
/// Whole-file reads and atomic whole-file writes.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace impulse2d::image {

/// Largest file `read_file_bytes` reads, bytes (256 MiB).
constexpr std::uintmax_t kMaxReadBytes = 256u * 1024 * 1024;

/// The bytes of a file. Throws `ImageError` naming the file when it cannot be read, is not
/// a regular file (a directory, a device) or is larger than `kMaxReadBytes`.
std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& file);

/// The text of a file. Throws `ImageError` naming the file when it cannot be read.
std::string read_text_file(const std::filesystem::path& file);

/// Writes `size` bytes to a temporary file beside `file`, then renames it over `file`, so a
/// reader sees the old content or the new, never a mix. Creates missing parent directories.
/// On failure nothing is left behind and `ImageError` names the file, the step and the
/// system's reason (e.g. "No space left on device").
void write_file_atomically(const std::filesystem::path& file, const void* data, std::size_t size);
/// `write_file_atomically` for a byte vector.
void write_file_atomically(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes);

/// `write_file_atomically` for text.
void write_text_file_atomically(const std::filesystem::path& file, const std::string& text);

}  // namespace impulse2d::image
