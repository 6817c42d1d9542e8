/// @file renderer_baseline.cpp
#include "golden/renderer_baseline.h"

#include <cctype>
#include <cstdint>

#include "image/hex_hash.h"

namespace impulse2d::golden {

std::string renderer_key(const RendererFingerprint& renderer) {
  std::string word;
  for (const char c : renderer.gl_renderer) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!word.empty()) break;
      continue;
    }
    if (std::isalnum(static_cast<unsigned char>(c))) {
      word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  if (word.empty()) word = "renderer";
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a
  for (const char c : renderer.describe()) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return word + "-" + image::to_hex_hash(hash).substr(0, 8);
}

std::filesystem::path renderer_baseline_png(const std::filesystem::path& golden_dir,
                                            const std::string& name,
                                            const RendererFingerprint& renderer) {
  return golden_dir / std::filesystem::path(name + "@" + renderer_key(renderer) + ".png");
}

std::string baseline_owner(const std::string& name) {
  const std::size_t slash = name.rfind('/');
  const std::size_t at = name.find('@', slash == std::string::npos ? 0 : slash);
  return at == std::string::npos ? name : name.substr(0, at);
}

}  // namespace impulse2d::golden
