/// @file state_file.cpp
#include "app/state_file.h"

#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "image/file_io.h"
#include "image/error.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

constexpr char state_magic[8] = {'I', '2', 'D', 'S', 'T', 'A', 'T', 'E'};
constexpr std::uint32_t state_version = 2;
constexpr std::size_t max_name_bytes = 4096;

void put(std::vector<std::uint8_t>& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

std::uint64_t get(const std::vector<std::uint8_t>& in, std::size_t at, int bytes) {
  std::uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value |= static_cast<std::uint64_t>(in[at + i]) << (8 * i);
  return value;
}

constexpr std::uint64_t fnv_offset_basis = 14695981039346656037ull;

// FNV-1a 64 of `size` bytes at `data`, continuing from `hash`.
std::uint64_t fnv1a(std::uint64_t hash, const std::uint8_t* data, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ data[i]) * 1099511628211ull;
  return hash;
}

// Reads the sections after the scene name from `at` on: u64 numbers (byte counts, a hash) and
// runs of bytes. Throws `UsageError` with `prefix`, naming `what`, when the file ends first.
class SectionReader {
 public:
  SectionReader(const std::vector<std::uint8_t>& bytes, std::size_t at, std::string prefix)
      : bytes_(bytes), at_(at), prefix_(std::move(prefix)) {}

  std::uint64_t number(const char* what) {
    if (bytes_.size() - at_ < 8) truncated(what);
    const std::uint64_t value = get(bytes_, at_, 8);
    at_ += 8;
    return value;
  }

  std::vector<std::uint8_t> take(std::uint64_t count, const char* what) {
    if (count > bytes_.size() - at_) truncated(what);
    const auto begin = bytes_.begin() + static_cast<std::ptrdiff_t>(at_);
    at_ += static_cast<std::size_t>(count);
    return std::vector<std::uint8_t>(begin, begin + static_cast<std::ptrdiff_t>(count));
  }

  bool at_end() const { return at_ == bytes_.size(); }

 private:
  [[noreturn]] void truncated(const char* what) const {
    throw UsageError(prefix_ + "the file is truncated or corrupt (it ends inside " + what + ")");
  }
  const std::vector<std::uint8_t>& bytes_;
  std::size_t at_;
  std::string prefix_;
};

}  // namespace

std::uint64_t scene_fingerprint(const SceneRun& fresh_run) {
  const std::vector<std::uint8_t> snapshot = fresh_run.world().save_snapshot();
  // The core header's payload hash (bytes 16..23) covers settings, bodies, joints, contacts;
  // the parameters' summary covers the ones only a script reads (a seed, a push).
  const std::string params = fresh_run.params().summary();
  const std::uint64_t world =
      snapshot.size() >= 24 ? fnv1a(fnv_offset_basis, snapshot.data() + 16, 8) : fnv_offset_basis;
  return fnv1a(world, reinterpret_cast<const std::uint8_t*>(params.data()), params.size());
}

void save_state_file(const std::string& file, const SceneRun& run, std::uint64_t fingerprint) {
  std::vector<std::uint8_t> bytes(state_magic, state_magic + 8);
  put(bytes, state_version, 4);
  put(bytes, fingerprint, 8);
  const std::string& name = run.scene().name;
  put(bytes, name.size(), 4);
  bytes.insert(bytes.end(), name.begin(), name.end());
  const std::vector<std::uint8_t> snapshot = run.world().save_snapshot();
  put(bytes, snapshot.size(), 8);
  bytes.insert(bytes.end(), snapshot.begin(), snapshot.end());
  const std::vector<std::uint8_t> script = run.save_script_state();
  put(bytes, script.size(), 8);
  put(bytes, fnv1a(fnv_offset_basis, script.data(), script.size()), 8);
  bytes.insert(bytes.end(), script.begin(), script.end());
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
                     "; this impulse2d reads version " + std::to_string(state_version) +
                     " (save the state again with this impulse2d)");
  }
  const std::uint64_t fingerprint = get(bytes, 12, 8);
  const std::size_t name_size = static_cast<std::size_t>(get(bytes, 20, 4));
  if (name_size > max_name_bytes || 24 + name_size > bytes.size()) {
    throw UsageError(prefix + "the file is truncated or corrupt (scene name length " +
                     std::to_string(name_size) + ")");
  }
  const std::string name(bytes.begin() + 24, bytes.begin() + 24 + static_cast<std::ptrdiff_t>(name_size));
  // The file's frame first (a corrupt file says so whatever scene it names), then its scene.
  SectionReader sections(bytes, 24 + name_size, prefix);
  const std::vector<std::uint8_t> snapshot = sections.take(sections.number("the world's size"), "the world");
  const std::uint64_t script_size = sections.number("the script state's size");
  const std::uint64_t script_hash = sections.number("the script state's hash");
  const std::vector<std::uint8_t> script = sections.take(script_size, "the script's state");
  if (!sections.at_end()) {
    throw UsageError(prefix + "the file is corrupt (bytes after the script's state)");
  }
  if (fnv1a(fnv_offset_basis, script.data(), script.size()) != script_hash) {
    throw UsageError(prefix + "the script's state is corrupt (its hash does not match its bytes)");
  }
  if (fingerprint != scene_fingerprint(run)) {
    throw UsageError(prefix + "saved from scene '" + name +
                     "' as built then; this is scene '" + run.scene().name +
                     "' (another scene, other --param values or a changed scene file)");
  }
  try {
    run.restore_snapshot(snapshot, script);
  } catch (const UsageError& error) {
    throw UsageError(prefix + error.what());
  } catch (const Error& error) {
    throw UsageError(prefix + "the saved state is refused: " + error.what());
  }
}

}  // namespace impulse2d::demos
