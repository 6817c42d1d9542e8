/// @file lab_output.cpp
#include "lab/lab_output.h"

#include <unistd.h>

#include <algorithm>
#include <stdexcept>

#include "scene/interrupt.h"
#include "scene/usage_error.h"

namespace impulse2d::lab {
namespace {

namespace fs = std::filesystem;

/// The shard count N of "lab_shard_K_of_N.csv", or 0 when `name` is not a shard CSV.
int shard_count_of(const std::string& name) {
  const std::string prefix = "lab_shard_", middle = "_of_", suffix = ".csv";
  if (name.size() <= prefix.size() + middle.size() + suffix.size() ||
      name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) {
    return 0;
  }
  const std::string numbers = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  const std::size_t split = numbers.find(middle);
  if (split == std::string::npos || split == 0) return 0;
  const std::string index = numbers.substr(0, split), count = numbers.substr(split + middle.size());
  const auto digits = [](const std::string& text) {
    return !text.empty() && text.size() <= 5 &&
           std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  return digits(index) && digits(count) ? std::stoi(count) : 0;
}

/// True for the names a lab run writes into its folder.
bool is_lab_output(const std::string& name) {
  static const char* const outputs[] = {"lab.csv", "charts", "stability.csv", "stability.png",
                                        "stability_sheets"};
  return std::find(std::begin(outputs), std::end(outputs), name) != std::end(outputs) ||
         shard_count_of(name) > 0;
}

/// The nearest of `path` and its ancestors that exists ("." for a relative path none of whose
/// parts exist).
fs::path nearest_existing(const fs::path& path) {
  fs::path at = path;
  std::error_code error;
  while (!at.empty() && !fs::exists(at, error)) at = at.parent_path();
  return at.empty() ? fs::path(".") : at;
}

/// Throws `demos::UsageError` unless `folder` (an existing path) is a folder this process may
/// write into.
void check_writable_folder(const fs::path& folder, const std::string& option, const fs::path& asked) {
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw demos::UsageError(option + " " + asked.string() + ": " + folder.string() +
                            " is not a folder");
  }
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    throw demos::UsageError(option + " " + asked.string() + ": cannot write into " +
                            folder.string() + " (permission denied)");
  }
}

}  // namespace

std::vector<std::string> other_runs_results(const fs::path& directory,
                                            const std::vector<std::string>& own_files,
                                            int sweep_shards) {
  std::vector<std::string> found;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (!is_lab_output(name)) continue;
    const int shards = shard_count_of(name);
    const bool own = std::find(own_files.begin(), own_files.end(), name) != own_files.end();
    // A shard CSV of the same sweep (or any shard CSV when merging) belongs with this run.
    if (shards > 0 && !own && (sweep_shards == 0 || shards == sweep_shards)) continue;
    found.push_back(name);
  }
  std::sort(found.begin(), found.end());
  return found;
}

void check_output_directory(const fs::path& directory, const std::vector<std::string>& other_results,
                            bool clean, const std::string& option) {
  check_writable_folder(nearest_existing(directory), option, directory);
  if (other_results.empty() || clean) return;
  std::string names;
  for (const std::string& name : other_results) names += (names.empty() ? "" : ", ") + name;
  throw demos::UsageError(option + " " + directory.string() + ": the folder already holds " +
                          names + " from another lab run; pass --clean to replace that run's " +
                          "results, or choose another " + option);
}

void check_output_file(const fs::path& file, const std::string& option) {
  std::error_code error;
  if (fs::is_directory(file, error)) {
    throw demos::UsageError(option + " " + file.string() + ": is a folder, expected a file name");
  }
  const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
  check_writable_folder(nearest_existing(folder), option, file);
}

OutputTransaction::OutputTransaction(const fs::path& directory, std::vector<std::string> replaced)
    : directory_(directory), replaced_(std::move(replaced)) {
  guard_.will_create_directory(directory_);
  std::error_code error;
  fs::create_directories(directory_, error);
  if (error) {
    throw std::runtime_error("cannot create the output folder " + directory_.string() + ": " +
                             error.message());
  }
  staging_ = std::make_unique<demos::StagingDirectory>(directory_, "lab");
}

OutputTransaction::~OutputTransaction() { staging_.reset(); }

std::string OutputTransaction::in_output_terms(const std::string& message) const {
  const std::string staged = staging_->path().string();
  std::string text = message;
  for (std::size_t at = text.find(staged); at != std::string::npos; at = text.find(staged, at)) {
    text.replace(at, staged.size(), directory_.string());
  }
  return text;
}

void OutputTransaction::commit() {
  demos::check_interrupt();
  std::vector<fs::path> staged;
  for (const fs::directory_entry& entry : fs::directory_iterator(staging_->path())) {
    staged.push_back(entry.path().filename());
  }
  std::sort(staged.begin(), staged.end());
  const demos::StagingDirectory aside(directory_, "lab-replaced");
  std::vector<fs::path> moved_aside, moved_in;
  const auto move = [](const fs::path& from, const fs::path& to) {
    std::error_code error;
    fs::rename(from, to, error);
    if (error) {
      throw std::runtime_error("cannot move " + from.string() + " to " + to.string() + ": " +
                               error.message());
    }
  };
  try {
    for (const std::string& name : replaced_) {
      move(directory_ / name, aside.path() / name);
      moved_aside.push_back(name);
    }
    for (const fs::path& name : staged) {
      guard_.will_write_file(directory_ / name);
      move(staging_->path() / name, directory_ / name);
      moved_in.push_back(name);
    }
  } catch (const std::runtime_error& error) {
    std::error_code ignored;
    for (auto name = moved_in.rbegin(); name != moved_in.rend(); ++name) {
      fs::rename(directory_ / *name, staging_->path() / *name, ignored);
    }
    for (auto name = moved_aside.rbegin(); name != moved_aside.rend(); ++name) {
      fs::rename(aside.path() / *name, directory_ / *name, ignored);
    }
    throw std::runtime_error(in_output_terms(error.what()));
  }
  guard_.commit();
}

}  // namespace impulse2d::lab
