/// @file report.cpp
#include "golden/report.h"

#include "golden/base64.h"
#include "golden/error.h"
#include "image/file_io.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <sstream>
#include <vector>

namespace impulse2d::golden {

namespace {

using nlohmann::json;

constexpr const char* kStyle = R"(
body { font-family: sans-serif; margin: 1.5em; background: #fafafa; color: #222; }
h1 { font-size: 1.4em; }
section { background: #fff; border: 1px solid #ddd; border-radius: 6px; padding: 1em;
          margin-bottom: 1.5em; }
h2 { font-size: 1.15em; margin-top: 0; }
.class { display: inline-block; padding: 0.1em 0.5em; border-radius: 4px; background: #c62828;
         color: #fff; font-size: 0.85em; margin-left: 0.5em; }
.message { font-family: monospace; white-space: pre-wrap; background: #f4f4f4;
           padding: 0.6em; border-radius: 4px; }
.images { display: flex; flex-wrap: wrap; gap: 1em; }
figure { margin: 0; }
figure img { border: 1px solid #ccc; image-rendering: pixelated; width: 360px;
             background: repeating-conic-gradient(#ddd 0% 25%, #fff 0% 50%) 0 0 / 16px 16px; }
figcaption { font-size: 0.85em; color: #555; text-align: center; }
table { border-collapse: collapse; font-size: 0.9em; margin-top: 0.8em; }
td, th { border: 1px solid #ddd; padding: 0.2em 0.6em; text-align: left; }
.compare { margin: 0.8em 0; }
.stage { position: relative; display: inline-block; border: 1px solid #ccc; line-height: 0; }
.stage img { image-rendering: pixelated; display: block; }
.top-wrap { position: absolute; top: 0; left: 0; height: 100%; overflow: hidden;
            border-right: 2px solid #c62828; }
.controls { margin-bottom: 0.4em; font-size: 0.9em; }
)";

/// Slider, toggle and zoom over each failure's expected and actual images: the images come
/// from the section's own figures, so the page embeds each PNG once.
constexpr const char* kScript = R"(
document.querySelectorAll('section').forEach(function (section) {
  var expected = section.querySelector('img[data-role=expected]');
  var actual = section.querySelector('img[data-role=actual]');
  var compare = section.querySelector('.compare');
  if (!expected || !actual || !compare) return;
  var base = compare.querySelector('.base'), top = compare.querySelector('.top');
  var wrap = compare.querySelector('.top-wrap'), label = compare.querySelector('.label');
  base.src = expected.src; top.src = actual.src;
  var zoom = 2, swapped = false;
  function layout() {
    var width = (expected.naturalWidth || 320) * zoom;
    base.style.width = width + 'px'; top.style.width = width + 'px';
  }
  base.onload = layout; layout();
  compare.querySelector('input').oninput = function (event) {
    wrap.style.width = event.target.value + '%';
  };
  compare.querySelector('button').onclick = function () {
    swapped = !swapped;
    base.src = swapped ? actual.src : expected.src; top.src = swapped ? expected.src : actual.src;
    label.textContent = swapped ? 'left of the line: expected, right: actual'
                                : 'left of the line: actual, right: expected';
  };
  compare.querySelector('select').onchange = function (event) {
    zoom = Number(event.target.value); layout();
  };
});
)";

/// One failure as read back from its metrics.json.
struct Entry {
  std::filesystem::path directory;  ///< the failure's artifact directory
  std::string relative;             ///< that directory relative to the root
  json metrics;                     ///< parsed metrics.json; null when unreadable
  std::string error;                ///< why it could not be read
};

std::string value_text(const json& value) {
  return value.is_string() ? value.get<std::string>() : value.dump();
}

/// The golden's name from its metrics, else its directory relative to the root.
std::string entry_name(const Entry& entry) {
  if (entry.metrics.is_object() && entry.metrics.contains("name")) {
    return value_text(entry.metrics["name"]);
  }
  return entry.relative;
}

std::string image_figure(const Entry& entry, const std::string& key, const std::string& caption) {
  if (!entry.metrics.contains("files")) return "";
  const json& files = entry.metrics["files"];
  if (!files.is_object() || !files.contains(key) || !files[key].is_string()) return "";
  const std::filesystem::path file = entry.directory / files[key].get<std::string>();
  std::string source;
  try {
    source = "data:image/png;base64," + base64_encode(image::read_file_bytes(file));
  } catch (const GoldenError& error) {
    return "<figure><figcaption>" + escape_html(caption) + ": " + escape_html(error.what()) +
           "</figcaption></figure>\n";
  }
  return "<figure><img data-role=\"" + escape_html(key) + "\" src=\"" + source + "\" alt=\"" +
         escape_html(caption) +
         "\"><figcaption>" + escape_html(caption) + "</figcaption></figure>\n";
}

std::string metrics_table(const json& metrics) {
  std::ostringstream html;
  html << "<table>\n";
  auto row = [&html](const std::string& key, const json& value) {
    html << "<tr><th>" << escape_html(key) << "</th><td>" << escape_html(value_text(value))
         << "</td></tr>\n";
  };
  for (const char* key : {"expected_state_hash", "actual_state_hash", "second_render_identical",
                          "other_process_identical", "expected_renderer", "actual_renderer"}) {
    if (metrics.contains(key)) row(key, metrics[key]);
  }
  const json& comparison = metrics.value("comparison", json(nullptr));
  if (comparison.is_object()) {
    for (const char* key : {"outcome", "expected_size", "actual_size"}) {
      if (comparison.contains(key)) row(key, comparison[key]);
    }
    if (comparison.contains("metrics") && comparison["metrics"].is_object()) {
      for (const auto& item : comparison["metrics"].items()) row(item.key(), item.value());
    }
    if (comparison.contains("tolerance")) row("tolerance", comparison["tolerance"]);
  }
  html << "</table>\n";
  return html.str();
}

std::string entry_section(const Entry& entry) {
  std::ostringstream html;
  const std::string name = escape_html(entry_name(entry));
  if (entry.metrics.is_null()) {
    html << "<section id=\"" << name << "\"><h2>" << name
         << "<span class=\"class\">unreadable</span></h2><p class=\"message\">"
         << escape_html(entry.error) << "</p></section>\n";
    return html.str();
  }
  html << "<section id=\"" << name << "\"><h2>" << name
       << "<span class=\"class\">"
       << escape_html(value_text(entry.metrics.value("class_name", json("failure"))))
       << "</span></h2>\n<p class=\"message\">"
       << escape_html(value_text(entry.metrics.value("message", json("")))) << "</p>\n"
       << "<div class=\"images\">\n"
       << image_figure(entry, "expected", "expected (golden)")
       << image_figure(entry, "actual", "actual")
       << image_figure(entry, "diff", "diff overlay (red: beyond tolerance, yellow: within)")
       << image_figure(entry, "heatmap", "heatmap (largest delta = white)") << "</div>\n"
       << "<div class=\"compare\"><div class=\"controls\">slider <input type=\"range\" "
          "min=\"0\" max=\"100\" value=\"50\"> <button type=\"button\">toggle</button> "
          "zoom <select><option value=\"1\">1x</option><option value=\"2\" selected>2x"
          "</option><option value=\"4\">4x</option><option value=\"8\">8x</option></select> "
          "<span class=\"label\">left of the line: actual, right: expected</span></div>"
          "<div class=\"stage\"><img class=\"base\" alt=\"\"><div class=\"top-wrap\" "
          "style=\"width: 50%\"><img class=\"top\" alt=\"\"></div></div></div>\n"
       << metrics_table(entry.metrics) << "<p>Artifacts: <code>"
       << escape_html(entry.relative) << "</code></p></section>\n";
  return html.str();
}

std::vector<Entry> collect_entries(const std::filesystem::path& root) {
  std::vector<Entry> entries;
  std::error_code error;
  if (!std::filesystem::exists(root, error)) return entries;
  for (std::filesystem::recursive_directory_iterator it(root, error), end; !error && it != end;
       it.increment(error)) {
    std::error_code vanished;  // another test process may be replacing files meanwhile
    if (it->path().filename() != "metrics.json" || !it->is_regular_file(vanished)) continue;
    Entry entry;
    entry.directory = it->path().parent_path();
    entry.relative = entry.directory.lexically_relative(root).generic_string();
    try {
      entry.metrics = json::parse(image::read_text_file(it->path()));
      if (!entry.metrics.is_object()) throw GoldenError("not a JSON object");
    } catch (const std::exception& failure) {
      entry.metrics = nullptr;
      entry.error = it->path().string() + ": " + failure.what();
    }
    entries.push_back(std::move(entry));
  }
  if (error) throw GoldenError("cannot scan '" + root.string() + "': " + error.message());
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.relative < b.relative; });
  return entries;
}

/// The run's metadata (run.json, written by `impulse2d golden`) as a table; empty without it.
std::string run_metadata(const std::filesystem::path& root) {
  const std::filesystem::path file = root / "run.json";
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return "";
  json run;
  try {
    run = json::parse(image::read_text_file(file));
  } catch (const std::exception& failure) {
    return "<p>run.json unreadable: " + escape_html(failure.what()) + "</p>\n";
  }
  if (!run.is_object()) return "";
  std::ostringstream html;
  html << "<table class=\"run\">\n";
  for (const auto& item : run.items()) {
    html << "<tr><th>" << escape_html(item.key()) << "</th><td>"
         << escape_html(value_text(item.value())) << "</td></tr>\n";
  }
  html << "</table>\n";
  return html.str();
}

/// Failures that share one physics change (the same golden and actual state hashes, e.g. a
/// frame with and without overlays): one line per group of two or more.
std::string shared_changes(const std::vector<Entry>& entries) {
  std::map<std::string, std::vector<std::string>> groups;
  for (const Entry& entry : entries) {
    const json& metrics = entry.metrics;
    if (!metrics.is_object() || !metrics.contains("expected_state_hash") ||
        !metrics["expected_state_hash"].is_string() || !metrics.contains("actual_state_hash") ||
        metrics["expected_state_hash"] == metrics["actual_state_hash"]) {
      continue;
    }
    groups[value_text(metrics.value("class_name", json(""))) + ": state " +
           value_text(metrics["expected_state_hash"]) + " -> " +
           value_text(metrics["actual_state_hash"])]
        .push_back(entry_name(entry));
  }
  std::ostringstream html;
  for (const auto& [change, names] : groups) {
    if (names.size() < 2) continue;
    html << "<li>" << names.size() << " failures share one physics change (" << escape_html(change)
         << "): ";
    for (std::size_t i = 0; i < names.size(); ++i) {
      html << (i ? ", " : "") << "<a href=\"#" << escape_html(names[i]) << "\">"
           << escape_html(names[i]) << "</a>";
    }
    html << "</li>\n";
  }
  const std::string items = html.str();
  return items.empty() ? "" : "<h2>Grouped</h2>\n<ul>\n" + items + "</ul>\n";
}

}  // namespace

std::string escape_html(const std::string& text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': escaped += "&amp;"; break;
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '"': escaped += "&quot;"; break;
      case '\'': escaped += "&#39;"; break;
      default: escaped += c;
    }
  }
  return escaped;
}

int write_html_report(const std::filesystem::path& root) {
  const std::vector<Entry> entries = collect_entries(root);
  std::map<std::string, int> counts;
  for (const Entry& entry : entries) {
    ++counts[entry.metrics.is_null()
                 ? std::string("unreadable")
                 : value_text(entry.metrics.value("class_name", json("failure")))];
  }
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
       << "<title>impulse2d golden failures</title>\n<style>" << kStyle << "</style></head>\n"
       << "<body>\n<h1>impulse2d golden images: " << entries.size() << " failure"
       << (entries.size() == 1 ? "" : "s") << "</h1>\n"
       << run_metadata(root) << "<ul>\n";
  for (const auto& [name, count] : counts) {
    html << "<li>" << escape_html(name) << ": " << count << "</li>\n";
  }
  html << "</ul>\n<ol>\n";
  for (const Entry& entry : entries) {
    const std::string name = escape_html(entry_name(entry));
    html << "<li><a href=\"#" << name << "\">" << name << "</a></li>\n";
  }
  html << "</ol>\n" << shared_changes(entries);
  for (const Entry& entry : entries) html << entry_section(entry);
  html << "<script>" << kScript << "</script>\n</body></html>\n";
  image::write_text_file_atomically(root / "index.html", html.str());
  return static_cast<int>(entries.size());
}

}  // namespace impulse2d::golden
