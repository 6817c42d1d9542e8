/// @file compare_report.cpp
#include "bench/compare/compare_report.h"

#include <cstdio>
#include <string>

namespace impulse2d::compare {
namespace {

bool is_peer(const Contender& contender) { return contender.method.engine != lab::Engine::Impulse2d; }

// "box2d 8/3" -> "box2d".
std::string engine_word(const Contender& contender) {
  return contender.label.substr(0, contender.label.find(' '));
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string ratio(double ours, double theirs) {
  return ours > 0.0 && theirs > 0.0 ? format("%.2f", ours / theirs) : "-";
}

// The stability figures as text: sag, side, moved, depth, out ("-" where they do not apply).
std::vector<std::string> stability_cells(const SceneResult& result, const Stability& s) {
  const bool pyramids = result.judge == Judge::Pyramids;
  std::vector<std::string> cells{
      pyramids ? format("%.3f", s.sag) : "-", pyramids ? format("%.3f", s.side) : "-",
      pyramids ? std::to_string(s.moved) : "-", format("%.4f", s.depth),
      pyramids ? "-" : std::to_string(s.out)};
  if (s.non_finite > 0) cells.back() += " (" + std::to_string(s.non_finite) + " non-finite)";
  return cells;
}

}  // namespace

void print_scene_table(std::ostream& out, const std::vector<Contender>& contenders,
                       const SceneResult& result) {
  out << "\n" << result.name << ": " << result.description << " (" << result.bodies
      << " bodies, " << result.steps << " steps; " << format("%.0f", result.seconds)
      << " s in all)\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-24s %9s", "engine", "ms/step");
  out << line;
  for (const Contender& peer : contenders) {
    if (!is_peer(peer)) continue;
    std::snprintf(line, sizeof line, " %9s", ("/" + engine_word(peer)).c_str());
    out << line;
  }
  std::snprintf(line, sizeof line, " %7s %7s %6s %8s %6s\n", "sag m", "side m", "moved", "depth m",
                result.judge == Judge::Rain ? "recyc" : "out");
  out << line;
  for (std::size_t e = 0; e < contenders.size(); ++e) {
    const Outcome& outcome = result.outcomes[e];
    if (!outcome.ran) {
      std::snprintf(line, sizeof line, "%-24s %9s (left out at this size: --peers-max)\n",
                    contenders[e].label.c_str(), "skipped");
      out << line;
      continue;
    }
    std::snprintf(line, sizeof line, "%-24s %9.3f", contenders[e].label.c_str(), outcome.ms_per_step);
    out << line;
    for (std::size_t p = 0; p < contenders.size(); ++p) {
      if (!is_peer(contenders[p])) continue;
      std::snprintf(line, sizeof line, " %9s",
                    ratio(outcome.ms_per_step, result.outcomes[p].ms_per_step).c_str());
      out << line;
    }
    const std::vector<std::string> cells = stability_cells(result, outcome.stability);
    std::snprintf(line, sizeof line, " %7s %7s %6s %8s %6s\n", cells[0].c_str(), cells[1].c_str(),
                  cells[2].c_str(), cells[3].c_str(), cells[4].c_str());
    out << line;
  }
}

void print_ratios(std::ostream& out, const std::vector<Contender>& contenders,
                  const std::vector<SceneResult>& results) {
  out << "\nratios ours/theirs (ms per step; below 1: impulse2d is faster)\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-16s %7s", "scene", "bodies");
  out << line;
  for (const Contender& ours : contenders) {
    if (is_peer(ours)) continue;
    for (const Contender& peer : contenders) {
      if (!is_peer(peer)) continue;
      const std::string name = ours.label.substr(ours.label.find(' ') + 1) + "/" + engine_word(peer);
      std::snprintf(line, sizeof line, " %20s", name.c_str());
      out << line;
    }
  }
  out << "\n";
  for (const SceneResult& result : results) {
    std::snprintf(line, sizeof line, "%-16s %7d", result.name.c_str(), result.bodies);
    out << line;
    for (std::size_t o = 0; o < contenders.size(); ++o) {
      if (is_peer(contenders[o])) continue;
      for (std::size_t p = 0; p < contenders.size(); ++p) {
        if (!is_peer(contenders[p])) continue;
        std::snprintf(line, sizeof line, " %20s",
                      ratio(result.outcomes[o].ms_per_step, result.outcomes[p].ms_per_step).c_str());
        out << line;
      }
    }
    out << "\n";
  }
}

void write_csv(std::ostream& out, const std::vector<Contender>& contenders,
               const std::vector<SceneResult>& results) {
  out << "scene,bodies,steps,engine,ms_per_step,sag_m,side_m,moved,depth_m,out,non_finite\n";
  for (const SceneResult& result : results) {
    for (std::size_t e = 0; e < contenders.size(); ++e) {
      const Outcome& o = result.outcomes[e];
      if (!o.ran) continue;  // left out at this size
      const Stability& s = o.stability;
      out << result.name << "," << result.bodies << "," << result.steps << ","
          << contenders[e].label << "," << format("%.4f", o.ms_per_step) << ","
          << format("%.4f", s.sag) << "," << format("%.4f", s.side) << "," << s.moved << ","
          << format("%.5f", s.depth) << "," << s.out << "," << s.non_finite << "\n";
    }
  }
}

void write_markdown(std::ostream& out, const std::vector<Contender>& contenders,
                    const std::vector<SceneResult>& results) {
  out << "| scene | bodies | steps | engine | ms/step |";
  for (const Contender& peer : contenders) {
    if (is_peer(peer)) out << " ÷ " << engine_word(peer) << " |";
  }
  out << " sag m | side m | moved | depth m | out |\n|---|---:|---:|---|---:|";
  for (const Contender& peer : contenders) {
    if (is_peer(peer)) out << "---:|";
  }
  out << "---:|---:|---:|---:|---:|\n";
  for (const SceneResult& result : results) {
    for (std::size_t e = 0; e < contenders.size(); ++e) {
      const Outcome& outcome = result.outcomes[e];
      if (!outcome.ran) {
        out << "| " << (e == 0 ? result.name : "") << " | | | " << contenders[e].label
            << " | skipped (too slow at this size) |";
        for (const Contender& peer : contenders) {
          if (is_peer(peer)) out << " |";
        }
        out << " | | | | |\n";
        continue;
      }
      out << "| " << (e == 0 ? result.name : "") << " | " << (e == 0 ? std::to_string(result.bodies) : "")
          << " | " << (e == 0 ? std::to_string(result.steps) : "") << " | " << contenders[e].label
          << " | " << format("%.3f", outcome.ms_per_step) << " |";
      for (std::size_t p = 0; p < contenders.size(); ++p) {
        if (is_peer(contenders[p])) out << " " << ratio(outcome.ms_per_step, result.outcomes[p].ms_per_step) << " |";
      }
      for (const std::string& cell : stability_cells(result, outcome.stability)) out << " " << cell << " |";
      out << "\n";
    }
  }
}

}  // namespace impulse2d::compare
