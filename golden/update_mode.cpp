/// @file update_mode.cpp
#include "golden/update_mode.h"

#include "golden/error.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <iostream>

namespace impulse2d::golden {

namespace {

std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

}  // namespace

bool is_ci(const char* ci) {
  const std::string value = lower_case(ci != nullptr ? ci : "");
  return !value.empty() && value != "false" && value != "0" && value != "no" && value != "off";
}

UpdateModeChoice resolve_update_mode(const char* golden_update, const char* ci) {
  const std::string requested = golden_update != nullptr ? golden_update : "";
  UpdateModeChoice choice;
  if (requested.empty() || requested == "none") {
    choice.mode = UpdateMode::None;
  } else if (requested == "missing") {
    choice.mode = UpdateMode::Missing;
  } else if (requested == "changed") {
    choice.mode = UpdateMode::Changed;
  } else if (requested == "all") {
    choice.mode = UpdateMode::All;
  } else {
    throw GoldenError("GOLDEN_UPDATE='" + requested +
                      "' is not a mode; use one of none, missing, changed, all");
  }
  if (is_ci(ci) && choice.mode != UpdateMode::None) {
    choice.note = "GOLDEN_UPDATE=" + requested + " ignored: CI=" + std::string(ci) +
                  " forces none, so CI never writes its own goldens";
    choice.mode = UpdateMode::None;
  }
  return choice;
}

UpdateModeChoice update_mode_from_environment() {
  UpdateModeChoice choice =
      resolve_update_mode(std::getenv("GOLDEN_UPDATE"), std::getenv("CI"));
  if (!choice.note.empty()) std::cerr << "golden: " << choice.note << "\n";
  return choice;
}

std::string update_mode_name(UpdateMode mode) {
  switch (mode) {
    case UpdateMode::None: return "none";
    case UpdateMode::Missing: return "missing";
    case UpdateMode::Changed: return "changed";
    case UpdateMode::All: return "all";
  }
  return "unknown";
}

bool should_write_golden(UpdateMode mode, FailureClass outcome) {
  if (outcome == FailureClass::Nondeterminism) return false;
  switch (mode) {
    case UpdateMode::None: return false;
    case UpdateMode::Missing:
      return outcome == FailureClass::MissingGolden ||
             outcome == FailureClass::NoRendererBaseline ||
             outcome == FailureClass::RendererBaselineRequired;
    case UpdateMode::Changed: return outcome != FailureClass::None;
    case UpdateMode::All: return true;
  }
  return false;
}

}  // namespace impulse2d::golden
