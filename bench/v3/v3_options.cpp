/// @file v3_options.cpp
#include "bench/v3/v3_options.h"

#include <algorithm>

#include "bench/v3/v3_protocol.h"

namespace impulse2d::bench_v3 {

const char* usage_text() {
  return "usage: bench_v3 [--rounds R] [--steps N] [--warmup W] [--quick]\n"
         "                [--scene large_pyramid,many_pyramids,ball_pit... | --scale [--scale-max BODIES]]\n"
         "                [--out DIR]\n"
         "  --rounds:    alternated rounds, each impulse2d 4 lanes, v3 SSE2, impulse2d 8 lanes,\n"
         "               v3 AVX2 (default 5)\n"
         "  --steps:     measured steps per run (default: the scene's own, as bench_compare:\n"
         "               large_pyramid 500, many_pyramids 200, ball_pit 300, scaling sizes 100)\n"
         "  --warmup:    untimed steps before them (default 1)\n"
         "  --quick:     a fifth of the scenes' steps\n"
         "  --scene:     only these scenes (repeatable, or a comma list)\n"
         "  --scale:     bench_compare's scaling series instead (many pyramids of 990, 1980, 5005,\n"
         "               10010, 20020, 50050, 100100 bodies): cost per body per step and its growth\n"
         "  --scale-max: the series' largest size, bodies (default 100100)\n"
         "  --out:       also write DIR/table.md (all or nothing)";
}

Options parse_options(const std::vector<std::string>& arguments) {
  Options options;
  std::vector<std::string> named;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& arg = arguments[i];
    const auto value = [&]() -> const std::string& {
      if (i + 1 >= arguments.size()) throw UsageError(arg + " wants a value");
      return arguments[++i];
    };
    if (arg == "--rounds" || arg == "--steps" || arg == "--warmup") {
      const std::string& text = value();
      const int number = parse_count(text, arg == "--warmup" ? 0 : 1);
      if (number < 0) {
        throw UsageError(arg + " wants a whole number" + (arg == "--warmup" ? "" : " above 0") +
                         ", not '" + text + "'");
      }
      (arg == "--rounds" ? options.rounds : arg == "--steps" ? options.steps : options.warmup) = number;
    } else if (arg == "--quick") {
      options.quick = true;
    } else if (arg == "--scene") {
      const std::string& list = value();
      std::size_t start = 0;
      while (true) {
        const std::size_t comma = list.find(',', start);
        const std::string name = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (std::find(scene_names().begin(), scene_names().end(), name) == scene_names().end()) {
          throw UsageError("--scene: no scene named '" + name + "' (large_pyramid, many_pyramids, ball_pit)");
        }
        named.push_back(name);
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
    } else if (arg == "--scale") {
      options.scale = true;
    } else if (arg == "--scale-max") {
      const std::string& text = value();
      options.scale_max = parse_count(text);
      if (options.scale_max < 0) throw UsageError("--scale-max wants a whole number of bodies, not '" + text + "'");
      const int smallest = compare::scaling_sizes().front().bodies;
      if (options.scale_max < smallest) {
        throw UsageError("--scale-max " + text + " is below the series' smallest size, " +
                         std::to_string(smallest) + " bodies");
      }
    } else if (arg == "--out") {
      options.out = value();
      if (options.out.empty()) throw UsageError("--out wants a directory");
    } else if (arg == "--help" || arg == "-h") {
      options.help = true;
    } else {
      throw UsageError("unknown argument '" + arg + "'");
    }
  }
  if (options.scale && !named.empty()) throw UsageError("--scene and --scale exclude each other");
  if (options.scale_max >= 0 && !options.scale) throw UsageError("--scale-max is for --scale");
  if (options.scale) return options;
  for (const std::string& name : scene_names()) {
    if (named.empty() || std::find(named.begin(), named.end(), name) != named.end()) {
      options.scenes.push_back(name);
    }
  }
  return options;
}

int measured_steps(const Options& options, int full_steps) {
  if (options.steps > 0) return options.steps;
  return std::max(1, options.quick ? full_steps / 5 : full_steps);
}

std::vector<compare::ScalingSize> scale_sizes(const Options& options) {
  std::vector<compare::ScalingSize> sizes;
  for (const compare::ScalingSize& size : compare::scaling_sizes()) {
    if (options.scale_max < 0 || size.bodies <= options.scale_max) sizes.push_back(size);
  }
  return sizes;
}

}  // namespace impulse2d::bench_v3
