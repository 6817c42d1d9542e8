#pragma once
/// @file report.h
/// One self-contained HTML page for every failure under an artifact root: images embedded
/// as base64 data URIs, so index.html alone is enough to review a run (e.g. a CI artifact).

#include <filesystem>
#include <string>

namespace impulse2d::golden {

/// Text with &, <, >, " and ' replaced by HTML entities.
std::string escape_html(const std::string& text);

/// Collects every metrics.json below `root` (each written by `write_failure_artifacts`,
/// possibly by different test processes) and writes `root`/index.html atomically: a
/// summary by failure class, then per failure its name, class, message, the expected,
/// actual, diff and heatmap images side by side, and its metrics. Returns how many failures
/// it lists. An unreadable metrics.json is listed as such rather than stopping the report.
int write_html_report(const std::filesystem::path& root);

}  // namespace impulse2d::golden
