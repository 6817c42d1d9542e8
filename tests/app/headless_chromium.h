#pragma once
/// @file headless_chromium.h
/// One page load in headless Chromium (Debian package `chromium`) for the browser tests: a
/// fixed window, device scale 1, no GPU, no scrollbars, a fresh profile, pinned font
/// rendering, virtual time so the page's images have loaded, and a wall-clock limit so a
/// hung browser fails the test instead of blocking CI.

#include <filesystem>
#include <string>

namespace impulse2d::testing {

/// True when `chromium` is on PATH.
bool have_chromium();

/// What the browser is asked to do.
struct ChromiumRun {
  std::string url;                 ///< the page, e.g. "file:///tmp/x/tutorial.html#frame=3"
  std::filesystem::path work_dir;  ///< profile, font configuration, outputs; must exist
  int width = 600;                 ///< window width, CSS pixels (= screenshot pixels)
  int height = 640;                ///< window height
  int timeout_seconds = 30;        ///< the browser is killed after this long
};

/// What came back.
struct ChromiumResult {
  std::string command;               ///< the shell command that ran
  int status = -1;                   ///< the browser's exit status (124: timed out)
  std::string dom;                   ///< the document after its scripts ran (--dump-dom)
  std::filesystem::path screenshot;  ///< the window as a PNG (absent when it failed)
  std::string log;                   ///< the browser's standard error
  /// The command, status and the log's last lines, for a failure message.
  std::string describe() const;
};

/// Loads `run.url` once and returns the DOM and a screenshot. Fonts: only the DejaVu faces
/// of fonts-dejavu-core, grey-scale anti-aliased with slight hinting, whatever the machine's
/// own fontconfig says (the screenshot's text then depends only on Chromium and FreeType).
ChromiumResult load_in_chromium(const ChromiumRun& run);

/// The directory of the DejaVu fonts `load_in_chromium` uses.
std::filesystem::path dejavu_font_dir();

}  // namespace impulse2d::testing
