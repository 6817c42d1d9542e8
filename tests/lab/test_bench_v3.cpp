// bench_v3's parts that need no Box2D v3: the runner line (round trip and strict rejection,
// naming the runner), the pair statistics, the command line, the scenes by name, the scaling
// series shared with bench_compare and its per-body statistics (--scale).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "bench/v3/v3_options.h"
#include "bench/v3/v3_pairs.h"
#include "bench/v3/v3_protocol.h"
#include "bench/v3/v3_scale.h"

using namespace impulse2d::bench_v3;

namespace {

const std::string commit = "617d32ab02570930625bbcb8479f54be9bf8d045";

RunResult sample_run() {
  RunResult run;
  run.scene = "large_pyramid";
  run.width = "avx2";
  run.commit = commit;
  run.steps = 500;
  run.warmup = 1;
  run.median_ms = 2.4375;
  run.min_ms = 2.25;
  run.stability.sag = 0.732f;
  run.stability.side = 0.182f;
  run.stability.moved = 1114;
  run.stability.depth = 0.0041f;
  run.heap_bytes = 403964160.0;
  return run;
}

// The message of the runtime_error `parse_runner_line(line, "runner_x")` throws ("" if none).
std::string rejection(const std::string& line) {
  try {
    parse_runner_line(line, "runner_x");
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

}  // namespace

TEST(BenchV3Protocol, RunnerLineRoundTrips) {
  const std::string line = format_runner_line(sample_run());
  EXPECT_EQ(line.rfind("v3_runner scene=large_pyramid width=avx2 commit=" + commit + " steps=500 warmup=1 ", 0), 0u)
      << line;
  const RunResult parsed = parse_runner_line(line + "\n", "runner_x");
  EXPECT_EQ(parsed.scene, "large_pyramid");
  EXPECT_EQ(parsed.width, "avx2");
  EXPECT_EQ(parsed.commit, commit);
  EXPECT_EQ(parsed.steps, 500);
  EXPECT_EQ(parsed.warmup, 1);
  EXPECT_DOUBLE_EQ(parsed.median_ms, 2.4375);
  EXPECT_DOUBLE_EQ(parsed.min_ms, 2.25);
  EXPECT_NEAR(parsed.stability.sag, 0.732f, 1e-6f);
  EXPECT_NEAR(parsed.stability.side, 0.182f, 1e-6f);
  EXPECT_EQ(parsed.stability.moved, 1114);
  EXPECT_EQ(parsed.stability.out, 0);
  EXPECT_EQ(parsed.stability.non_finite, 0);
  EXPECT_NEAR(parsed.stability.depth, 0.0041f, 1e-6f);
  EXPECT_DOUBLE_EQ(parsed.heap_bytes, 403964160.0);
  EXPECT_NE(line.find(" depth=0.004100 heap_bytes=403964160"), std::string::npos) << line;
}

TEST(BenchV3Protocol, MalformedLinesAreErrorsNamingTheRunner) {
  const std::string good = format_runner_line(sample_run());
  ASSERT_EQ(rejection(good), "");
  const std::string bad_lines[] = {
      "",
      "hello",
      good + " extra=1",
      good.substr(0, good.rfind(" depth=")),                  // fields missing
      good.substr(0, good.rfind(" heap_bytes=")),             // the last field missing
      replaced(good, "heap_bytes=403964160", "heap_bytes=403964160.5"),
      replaced(good, "heap_bytes=403964160", "heap_bytes=-1"),
      replaced(good, "scene=large_pyramid", "scene=tower"),   // unknown scene
      replaced(good, "width=avx2", "width=avx512"),
      replaced(good, "commit=" + commit, "commit=617d32ab"),  // short hash
      replaced(good, "steps=500", "steps=500x"),              // trailing characters
      replaced(good, "steps=500", "steps=0"),
      replaced(good, "median_ms=2.437500", "median_ms=-2.4"),
      replaced(good, "median_ms=2.437500", "median_ms=nan"),
      replaced(good, "median_ms=2.437500", "median_ms=1e3"),
      replaced(good, "min_ms=2.250000", "min_ms=9.0"),        // fastest above the median
      replaced(good, " warmup=1 ", "  warmup=1 "),            // two spaces
      replaced(good, "moved=1114", "moved=11.5"),
      replaced(replaced(good, "sag=", "SAG="), "side=", "sag="),  // keys out of order
      good + "\n\n",
      "v3_runner " + good,
  };
  for (const std::string& line : bad_lines) {
    const std::string message = rejection(line);
    EXPECT_NE(message.find("runner runner_x"), std::string::npos) << "accepted or unnamed: '" << line << "' -> " << message;
  }
}

TEST(BenchV3Protocol, ScenesAreBenchCompares) {
  ASSERT_EQ(scene_names().size(), 3u);
  EXPECT_EQ(scene_by_name("large_pyramid").dynamic_count, 5050);
  EXPECT_EQ(scene_by_name("large_pyramid").steps, 500);
  EXPECT_EQ(scene_by_name("many_pyramids").dynamic_count, 22000);
  EXPECT_EQ(scene_by_name("many_pyramids").steps, 200);
  EXPECT_EQ(scene_by_name("ball_pit").dynamic_count, 5000);
  EXPECT_EQ(scene_by_name("ball_pit").steps, 300);
  EXPECT_THROW(scene_by_name("rain"), std::invalid_argument);
}

TEST(BenchV3Protocol, MedianAndCounts) {
  EXPECT_DOUBLE_EQ(median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_DOUBLE_EQ(median({4.0, 1.0, 2.0, 3.0}), 2.5);
  EXPECT_DOUBLE_EQ(median({}), 0.0);
  EXPECT_EQ(parse_count("12"), 12);
  EXPECT_EQ(parse_count("0"), -1);
  EXPECT_EQ(parse_count("0", 0), 0);
  EXPECT_EQ(parse_count("-3", 0), -1);
  EXPECT_EQ(parse_count("3 "), -1);
  EXPECT_EQ(parse_count(""), -1);
  EXPECT_EQ(parse_count("1000000000"), -1);
}

TEST(BenchV3Pairs, SummaryGivesMedianSpreadAndVerdicts) {
  const PairSummary summary = summarize_pairs({0.85, 0.95, 0.80, 0.88, 0.99});
  EXPECT_DOUBLE_EQ(summary.median, 0.88);
  EXPECT_DOUBLE_EQ(summary.min, 0.80);
  EXPECT_DOUBLE_EQ(summary.max, 0.99);
  EXPECT_TRUE(summary.all_below_one);
  EXPECT_TRUE(summary.median_meets_goal);
  EXPECT_EQ(summary.ratios.size(), 5u);

  const PairSummary one_above = summarize_pairs({0.80, 1.01, 0.85});
  EXPECT_FALSE(one_above.all_below_one);
  EXPECT_TRUE(one_above.median_meets_goal);
  const PairSummary at_one = summarize_pairs({1.0});
  EXPECT_FALSE(at_one.all_below_one);  // equal is not faster
  EXPECT_FALSE(at_one.median_meets_goal);
  EXPECT_TRUE(summarize_pairs({0.9}).median_meets_goal);

  EXPECT_THROW(summarize_pairs({}), std::invalid_argument);
  EXPECT_THROW(summarize_pairs({0.9, -1.0}), std::invalid_argument);
}

TEST(BenchV3Pairs, ReportNamesTheCommitAndEveryPair) {
  WidthSeries width{"impulse2d 4 lanes", "Box2D v3 SSE2", {}, {}, ""};
  for (const double ours : {3.0, 3.3}) {
    RunResult run = sample_run();
    run.median_ms = ours;
    width.ours_runs.push_back(run);
    run.median_ms = 3.0;
    width.theirs_runs.push_back(run);
  }
  EXPECT_EQ(pair_ratios(width).size(), 2u);
  SceneSeries scene;
  scene.scene = "large_pyramid";
  scene.widths = {width, WidthSeries{"impulse2d 8 lanes", "Box2D v3 AVX2", {}, {}, "this CPU has no AVX2"}};
  Report report;
  report.commit = commit;
  report.rounds = 2;
  report.scenes = {scene};
  for (const bool markdown : {false, true}) {
    std::ostringstream out;
    write_report(out, report, markdown);
    const std::string text = out.str();
    if (markdown) {
      EXPECT_NE(text.find("### large_pyramid"), std::string::npos) << text;
    } else {
      EXPECT_EQ(text.find("### "), std::string::npos) << text;
    }
    EXPECT_NE(text.find("large_pyramid (0 bodies, 0 steps timed after 0 untimed) - Box2D v3 " + commit),
              std::string::npos) << text;
    EXPECT_NE(text.find("| 1.000 1.100 | 1.050 | [1.000-1.100] | no | no |"), std::string::npos) << text;
    EXPECT_NE(text.find("skipped: this CPU has no AVX2"), std::string::npos) << text;
  }
}

TEST(BenchV3Options, DefaultsAndValues) {
  const Options defaults = parse_options({});
  EXPECT_EQ(defaults.rounds, 5);
  EXPECT_EQ(defaults.steps, -1);
  EXPECT_EQ(defaults.warmup, 1);
  EXPECT_EQ(defaults.scenes, scene_names());
  EXPECT_EQ(measured_steps(defaults, 500), 500);

  const Options chosen = parse_options({"--rounds", "3", "--scene", "ball_pit,large_pyramid", "--quick",
                                        "--warmup", "0", "--out", "dir"});
  EXPECT_EQ(chosen.rounds, 3);
  EXPECT_EQ(chosen.warmup, 0);
  EXPECT_EQ(chosen.out, "dir");
  EXPECT_EQ(chosen.scenes, (std::vector<std::string>{"large_pyramid", "ball_pit"}));  // bench_v3's order
  EXPECT_EQ(measured_steps(chosen, 500), 100);
  EXPECT_EQ(measured_steps(parse_options({"--scene", "ball_pit", "--scene", "many_pyramids", "--steps", "7"}), 500), 7);
}

TEST(BenchV3Options, BadArgumentsAreUsageErrors) {
  const std::vector<std::vector<std::string>> bad{
      {"--rounds"}, {"--rounds", "0"}, {"--rounds", "two"}, {"--steps", "-5"}, {"--warmup", "x"},
      {"--scene", "rain"}, {"--scene", "ball_pit,"}, {"--out", ""}, {"--fast"}, {"large_pyramid"}};
  for (const std::vector<std::string>& arguments : bad) {
    EXPECT_THROW(parse_options(arguments), UsageError) << arguments.front();
  }
}

TEST(BenchV3Scale, SeriesIsBenchComparesAndNamedAlike) {
  const std::vector<impulse2d::compare::ScalingSize>& sizes = impulse2d::compare::scaling_sizes();
  ASSERT_EQ(sizes.size(), 7u);
  const int bodies[] = {990, 1980, 5005, 10010, 20020, 50050, 100100};
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    EXPECT_EQ(sizes[i].bodies, bodies[i]);
    EXPECT_EQ(sizes[i].bodies, 55 * sizes[i].pyramids);
  }
  const impulse2d::compare::CompareScene direct = impulse2d::compare::scaling_scene(18, 100);
  const impulse2d::compare::CompareScene named = scene_by_name("scaling_990");
  EXPECT_EQ(direct.name, "scaling_990");
  EXPECT_TRUE(named.scaling);
  EXPECT_EQ(named.steps, scaling_steps);
  EXPECT_EQ(named.dynamic_count, 990);
  ASSERT_EQ(named.bodies.size(), direct.bodies.size());
  for (std::size_t i = 0; i < named.bodies.size(); ++i) {
    EXPECT_EQ(named.bodies[i].def.position.x, direct.bodies[i].def.position.x);
    EXPECT_EQ(named.bodies[i].def.position.y, direct.bodies[i].def.position.y);
  }
  EXPECT_EQ(scene_by_name("scaling_5005").dynamic_count, 5005);
  EXPECT_TRUE(known_scene("scaling_100100"));
  EXPECT_TRUE(known_scene("ball_pit"));
  EXPECT_FALSE(known_scene("scaling_1000"));
  EXPECT_THROW(scene_by_name("scaling_1000"), std::invalid_argument);

  RunResult run = sample_run();
  run.scene = "scaling_990";
  EXPECT_EQ(parse_runner_line(format_runner_line(run), "runner_x").scene, "scaling_990");
  EXPECT_NE(rejection(replaced(format_runner_line(run), "scene=scaling_990", "scene=scaling_991")).find("runner runner_x"),
            std::string::npos);
}

TEST(BenchV3Scale, OptionsChooseTheSizes) {
  const Options all = parse_options({"--scale", "--rounds", "3"});
  EXPECT_TRUE(all.scale);
  EXPECT_TRUE(all.scenes.empty());
  EXPECT_EQ(scale_sizes(all).size(), 7u);
  EXPECT_EQ(measured_steps(all, scaling_steps), 100);
  EXPECT_EQ(measured_steps(parse_options({"--scale", "--quick"}), scaling_steps), 20);
  EXPECT_EQ(scale_sizes(parse_options({"--scale-max", "20020", "--scale"})).size(), 5u);
  EXPECT_EQ(scale_sizes(parse_options({"--scale", "--scale-max", "20019"})).back().bodies, 10010);
  EXPECT_EQ(scale_sizes(parse_options({"--scale", "--scale-max", "990"})).size(), 1u);
  EXPECT_FALSE(parse_options({}).scale);

  const std::vector<std::vector<std::string>> bad{
      {"--scale-max", "20020"},  // without --scale
      {"--scale", "--scale-max", "989"},
      {"--scale", "--scale-max", "0"},
      {"--scale", "--scale-max", "2e4"},
      {"--scale", "--scale-max"},
      {"--scale", "--scene", "ball_pit"},
      {"--scene", "scaling_990"}};
  for (const std::vector<std::string>& arguments : bad) {
    EXPECT_THROW(parse_options(arguments), UsageError) << arguments.back();
  }
}

TEST(BenchV3Scale, SpreadRatiosAndCostPerBody) {
  const Spread spread = spread_of({1.2, 1.0, 1.5});
  EXPECT_DOUBLE_EQ(spread.median, 1.2);
  EXPECT_DOUBLE_EQ(spread.min, 1.0);
  EXPECT_DOUBLE_EQ(spread.max, 1.5);
  EXPECT_DOUBLE_EQ(spread_of({2.0, 1.0}).median, 1.5);
  EXPECT_THROW(spread_of({}), std::invalid_argument);
  EXPECT_THROW(spread_of({1.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(spread_of({1.0, std::nan("")}), std::invalid_argument);

  EXPECT_DOUBLE_EQ(micros_per_body(2.0, 1000), 2.0);  // 2 ms over 1000 bodies: 2 µs each
  const std::vector<double> ratios = per_round_ratios({3.0, 4.0}, {2.0, 1.0});
  ASSERT_EQ(ratios.size(), 2u);
  EXPECT_DOUBLE_EQ(ratios[0], 1.5);
  EXPECT_DOUBLE_EQ(ratios[1], 4.0);
  EXPECT_THROW(per_round_ratios({1.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(per_round_ratios({1.0}, {0.0}), std::invalid_argument);

  RunResult run = sample_run();
  run.median_ms = 1.98;
  const std::vector<double> costs = per_body_costs({run, run}, 990);
  ASSERT_EQ(costs.size(), 2u);
  EXPECT_DOUBLE_EQ(costs[1], 2.0);
  EXPECT_DOUBLE_EQ(heap_per_body({run}, 990)[0], 403964160.0 / 990.0);
}

TEST(BenchV3Scale, ReportGivesCostGrowthAndRatioPerRound) {
  // Two sizes, two rounds. ours: 2.0 then 3.0 µs/body at 1000 bodies, 2.6 and 3.3 at 2000
  // (growth 1.30 and 1.10); v3: 1.0 at both sizes in both rounds.
  const auto runs = [](std::vector<double> micros, int bodies) {
    std::vector<RunResult> list;
    for (const double value : micros) {
      RunResult run = sample_run();
      run.median_ms = value * bodies / 1000.0;
      run.heap_bytes = 4000.0 * value * bodies;  // 4000 B per body per µs, to tell them apart
      list.push_back(run);
    }
    return list;
  };
  ScaleWidth width{"impulse2d 4 lanes", "Box2D v3 SSE2", {}, ""};
  width.points.push_back(ScalePoint{1000, runs({2.0, 3.0}, 1000), runs({1.0, 1.0}, 1000)});
  width.points.push_back(ScalePoint{2000, runs({2.6, 3.3}, 2000), runs({1.0, 1.0}, 2000)});
  ScaleReport report;
  report.commit = commit;
  report.rounds = 2;
  report.steps = 100;
  report.warmup = 1;
  report.widths = {width, ScaleWidth{"impulse2d 8 lanes", "Box2D v3 AVX2", {}, "this CPU has no AVX2"}};
  for (const bool markdown : {false, true}) {
    std::ostringstream out;
    write_scale_report(out, report, markdown);
    const std::string text = out.str();
    EXPECT_EQ(text.find("### ") != std::string::npos, markdown) << text;
    EXPECT_NE(text.find("impulse2d 4 lanes / Box2D v3 SSE2 - Box2D v3 " + commit), std::string::npos) << text;
    EXPECT_NE(text.find("| 1000 | 2.500 [2.000-3.000] | 1.00 1.00; 1.00 | 1.000 [1.000-1.000] | 1.00 1.00; 1.00 | "
                        "2.00 3.00; 2.50 | 10000 / 4000 |"),
              std::string::npos) << text;
    EXPECT_NE(text.find("| 2000 | 2.950 [2.600-3.300] | 1.30 1.10; 1.20 | 1.000 [1.000-1.000] | 1.00 1.00; 1.00 | "
                        "2.60 3.30; 2.95 | 11800 / 4000 |"),
              std::string::npos) << text;
    EXPECT_NE(text.find("from 1000 to 2000 bodies, median of the rounds [min-max]: impulse2d 4 lanes 1.20x "
                        "[1.10-1.30], Box2D v3 SSE2 1.00x [1.00-1.00]; impulse2d 4 lanes below 1.3x (issue 33, "
                        "goal 4): yes"),
              std::string::npos) << text;
    EXPECT_NE(text.find("skipped: this CPU has no AVX2"), std::string::npos) << text;
  }
  ScaleReport uneven = report;
  uneven.widths[0].points[1].theirs_runs.pop_back();
  std::ostringstream ignored;
  EXPECT_THROW(write_scale_report(ignored, uneven, true), std::invalid_argument);
}
