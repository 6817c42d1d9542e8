/// @file state_file.cpp
#include "app/state_file.h"

#include <cstring>
#include <vector>

#include "core/error.h"
#include "core/snapshot.h"
#include "image/file_io.h"
#include "image/error.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

constexpr char state_magic[8] = {'I', '2', 'D', 'S', 'T', 'A', 'T', 'E'};
constexpr std::uint32_t state_version = 1;
constexpr std::size_t max_name_bytes = 4096;

void put(std::vector<std::uint8_t>& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

std::uint64_t get(const std::vector<std::uint8_t>& in, std::size_t at, int bytes) {
  std::uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value |= static_cast<std::uint64_t>(in[at + i]) << (8 * i);
  return value;
}

}  // namespace

std::uint64_t scene_fingerprint(const SceneRun& fresh_run) {
  const std::vector<std::uint8_t> snapshot = fresh_run.world().save_snapshot();
  // The core header's payload hash (bytes 16..23) covers settings, bodies, joints, contacts.
  return snapshot.size() >= 24 ? get(snapshot, 16, 8) : 0;
}

void save_state_file(const std::string& file, const SceneRun& run, std::uint64_t fingerprint) {
  std::vector<std::uint8_t> bytes(state_magic, state_magic + 8);
  put(bytes, state_version, 4);
  put(bytes, fingerprint, 8);
  const std::string& name = run.scene().name;
  put(bytes, name.size(), 4);
  bytes.insert(bytes.end(), name.begin(), name.end());
  const std::vector<std::uint8_t> snapshot = run.world().save_snapshot();
  bytes.insert(bytes.end(), snapshot.begin(), snapshot.end());
  try {
    image::write_file_atomically(file, bytes);
  } catch (const image::ImageError& error) {
    throw UsageError(std::string("--save-state: ") + error.what());
  }
}

void load_state_file(const std::string& file, SceneRun& run) {
  const std::string prefix = "--load-state " + file + ": ";
  std::vector<std::uint8_t> bytes;
  try {
    bytes = image::read_file_bytes(file);
  } catch (const image::ImageError& error) {
    throw UsageError(std::string("--load-state: ") + error.what());
  }
  if (bytes.size() < 24 || std::memcmp(bytes.data(), state_magic, 8) != 0) {
    throw UsageError(prefix + "not an impulse2d state file (write one with trace --save-state)");
  }
  const std::uint32_t version = static_cast<std::uint32_t>(get(bytes, 8, 4));
  if (version != state_version) {
    throw UsageError(prefix + "state file layout version " + std::to_string(version) +
                     "; this impulse2d reads version " + std::to_string(state_version));
  }
  const std::uint64_t fingerprint = get(bytes, 12, 8);
  const std::size_t name_size = static_cast<std::size_t>(get(bytes, 20, 4));
  if (name_size > max_name_bytes || 24 + name_size > bytes.size()) {
    throw UsageError(prefix + "the file is truncated or corrupt (scene name length " +
                     std::to_string(name_size) + ")");
  }
  const std::string name(bytes.begin() + 24, bytes.begin() + 24 + static_cast<std::ptrdiff_t>(name_size));
  if (fingerprint != scene_fingerprint(run)) {
    throw UsageError(prefix + "saved from scene '" + name +
                     "' as built then; this is scene '" + run.scene().name +
                     "' (another scene, other --param values or a changed scene file)");
  }
  const std::vector<std::uint8_t> snapshot(bytes.begin() + 24 + static_cast<std::ptrdiff_t>(name_size),
                                           bytes.end());
  try {
    run.restore_snapshot(snapshot);
  } catch (const UsageError& error) {
    throw UsageError(prefix + error.what());
  } catch (const Error& error) {
    throw UsageError(prefix + "the saved world is refused: " + error.what());
  }
}

}  // namespace impulse2d::demos
