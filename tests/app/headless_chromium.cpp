/// @file headless_chromium.cpp
#include "tests/app/headless_chromium.h"

#include <sys/wait.h>

#include <cstdlib>

#include "image/file_io.h"

namespace impulse2d::testing {
namespace {

/// `text` in single quotes for sh.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// A fontconfig file that sees only the DejaVu faces and fixes how glyphs are rasterised:
/// a user's or a distribution's font settings (hinting style alone moves 3-6% of the
/// page's pixels) must not change the screenshot.
std::string font_config(const std::filesystem::path& cache_dir) {
  return "<?xml version=\"1.0\"?>\n<!DOCTYPE fontconfig SYSTEM \"fonts.dtd\">\n<fontconfig>\n"
         "  <dir>" + dejavu_font_dir().string() + "</dir>\n"
         "  <cachedir>" + cache_dir.string() + "</cachedir>\n"
         "  <alias><family>monospace</family><prefer><family>DejaVu Sans Mono</family></prefer></alias>\n"
         // Every other family Chromium asks for (its defaults are Arial, Times New Roman...)
         // ends in DejaVu Sans, as Debian's own configuration resolves them.
         "  <match target=\"pattern\">\n"
         "    <edit name=\"family\" mode=\"append_last\"><string>DejaVu Sans</string></edit>\n"
         "  </match>\n"
         "  <match target=\"font\">\n"
         "    <edit name=\"antialias\" mode=\"assign\"><bool>true</bool></edit>\n"
         "    <edit name=\"hinting\" mode=\"assign\"><bool>true</bool></edit>\n"
         "    <edit name=\"hintstyle\" mode=\"assign\"><const>hintslight</const></edit>\n"
         "    <edit name=\"autohint\" mode=\"assign\"><bool>false</bool></edit>\n"
         "    <edit name=\"rgba\" mode=\"assign\"><const>none</const></edit>\n"
         "    <edit name=\"embeddedbitmap\" mode=\"assign\"><bool>false</bool></edit>\n"
         "  </match>\n</fontconfig>\n";
}

}  // namespace

bool have_chromium() { return std::system("command -v chromium > /dev/null 2>&1") == 0; }

std::filesystem::path dejavu_font_dir() { return "/usr/share/fonts/truetype/dejavu"; }

std::string ChromiumResult::describe() const {
  // The last lines of the log: Chromium writes many harmless D-Bus complaints before them.
  std::size_t from = log.size();
  for (int lines = 0; lines < 9 && from != 0 && from != std::string::npos; ++lines) {
    from = log.rfind('\n', from - 1);
  }
  const std::string tail = from == std::string::npos ? log : log.substr(from + 1);
  return command + "\nexit status " + std::to_string(status) +
         (status == 124 ? " (timed out)" : "") + "; standard error ends:\n" + tail;
}

ChromiumResult load_in_chromium(const ChromiumRun& run) {
  const std::filesystem::path fonts = run.work_dir / "fonts.conf";
  image::write_text_file_atomically(fonts, font_config(run.work_dir / "fontconfig-cache"));
  ChromiumResult result;
  result.screenshot = run.work_dir / "screenshot.png";
  const std::filesystem::path dom = run.work_dir / "dom.html";
  const std::filesystem::path log = run.work_dir / "chromium.log";
  // timeout(1) signals the browser's whole process group; -k kills it when TERM is ignored.
  // --no-sandbox: Chromium refuses to start its sandbox as root, which CI containers are.
  // --virtual-time-budget lets the page load its frames and run its scripts before the
  // capture without waiting in real time.
  result.command = "FONTCONFIG_FILE=" + quoted(fonts.string()) + " timeout -k 5 " +
                   std::to_string(run.timeout_seconds) +
                   " chromium --headless --no-sandbox --disable-gpu --hide-scrollbars"
                   " --force-device-scale-factor=1 --no-first-run --mute-audio"
                   " --window-size=" + std::to_string(run.width) + "," +
                   std::to_string(run.height) +
                   " --user-data-dir=" + quoted((run.work_dir / "profile").string()) +
                   " --virtual-time-budget=2000 --dump-dom --screenshot=" +
                   quoted(result.screenshot.string()) + " " + quoted(run.url);
  const int status =
      std::system((result.command + " > " + quoted(dom.string()) + " 2> " + quoted(log.string()))
                      .c_str());
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.dom = image::read_text_file(dom);
  result.log = image::read_text_file(log);
  return result;
}

}  // namespace impulse2d::testing
