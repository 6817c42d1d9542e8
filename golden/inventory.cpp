/// @file inventory.cpp
#include "golden/inventory.h"

#include "golden/error.h"
#include "golden/renderer_baseline.h"

#include <algorithm>
#include <iterator>
#include <set>

namespace impulse2d::golden {

GoldenInventory scan_goldens(const std::filesystem::path& golden_dir) {
  std::set<std::string> images;
  std::set<std::string> sidecars;
  std::error_code error;
  if (std::filesystem::exists(golden_dir, error)) {
    for (std::filesystem::recursive_directory_iterator it(golden_dir, error), end;
         !error && it != end; it.increment(error)) {
      std::error_code ignored;
      if (!it->is_regular_file(ignored)) continue;
      const std::filesystem::path& file = it->path();
      std::filesystem::path name = file.lexically_relative(golden_dir);
      name.replace_extension();
      if (file.extension() == ".png") images.insert(name.generic_string());
      if (file.extension() == ".json") sidecars.insert(name.generic_string());
    }
  }
  if (error) throw GoldenError("cannot scan '" + golden_dir.string() + "': " + error.message());

  GoldenInventory inventory;
  std::set_intersection(images.begin(), images.end(), sidecars.begin(), sidecars.end(),
                        std::back_inserter(inventory.goldens));
  std::set_difference(images.begin(), images.end(), sidecars.begin(), sidecars.end(),
                      std::back_inserter(inventory.missing_sidecar));
  std::set_difference(sidecars.begin(), sidecars.end(), images.begin(), images.end(),
                      std::back_inserter(inventory.missing_image));
  return inventory;
}

std::vector<std::string> unused_goldens(const std::vector<std::string>& goldens,
                                        const std::vector<std::string>& used) {
  const std::set<std::string> used_set(used.begin(), used.end());
  std::vector<std::string> unused;
  for (const std::string& name : goldens) {
    if (used_set.count(baseline_owner(name)) == 0) unused.push_back(name);
  }
  std::sort(unused.begin(), unused.end());
  return unused;
}

}  // namespace impulse2d::golden
