// The lab's results: CSV round trip, Pareto front and recommendation, label layout without
// overlaps, --shard parsing.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lab/label_layout.h"
#include "lab/option_numbers.h"
#include "lab/lab_result.h"
#include "scene/usage_error.h"

namespace impulse2d::lab {
namespace {

LabResult row(std::int64_t job, double cost, double error, bool pass,
              Engine engine = Engine::Impulse2d) {
  LabResult result;
  result.job = job;
  result.scenario = "s";
  result.method.engine = engine;
  result.method.velocity_iterations = static_cast<int>(job) + 1;
  result.us_per_simulated_second = cost;
  result.error = error;
  result.pass = pass;
  result.unit = "m";
  result.threshold = 0.1;
  return result;
}

TEST(LabResults, CsvRoundTripKeepsEveryField) {
  LabResult result = row(7, 123.456789, 0.0123456789, false);
  result.method.solver = SolverMethod::SoftStep;
  result.method.substeps = 4;
  result.method.time_step = 1.0f / 120.0f;
  result.method.friction_mixing = FrictionMixing::Product;
  result.method.continuous = false;
  result.method.speculative_margin = 0.05f;
  result.failure = "error 0.0123 m > 0.01 m, \"quoted\"";
  result.steps = 600;
  result.bodies = 21;
  result.ns_per_step = 1234.5;
  const std::vector<LabResult> back =
      parse_csv(csv_header() + "\n" + csv_line(result) + "\n", "x.csv");
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(csv_line(back[0]), csv_line(result));
  EXPECT_EQ(back[0].method.time_step, result.method.time_step);
  EXPECT_EQ(back[0].failure, result.failure);
}

TEST(LabResults, CsvErrorsNameFileLineAndField) {
  try {
    parse_csv(csv_header() + "\n1,s,impulse2d\n", "x.csv");
    FAIL();
  } catch (const demos::UsageError& error) {
    EXPECT_EQ(std::string(error.what()), "x.csv:2: expected 32 fields, got 3");
  }
  try {
    parse_csv("a,b\n", "y.csv");
    FAIL();
  } catch (const demos::UsageError& error) {
    EXPECT_EQ(std::string(error.what()), "y.csv:1: not a lab CSV (header differs)");
  }
}

// Front: no other point is both cheaper and more accurate; the recommendation is the cheapest
// passing impulse2d method (a cheaper passing peer is not recommended).
TEST(LabResults, ParetoFrontAndRecommendation) {
  std::vector<LabResult> results{row(0, 10, 1.0, false), row(1, 20, 0.05, true),
                                 row(2, 30, 0.5, false), row(3, 40, 0.01, true),
                                 row(4, 5, 0.02, true, Engine::Box2d),
                                 row(5, 50, std::numeric_limits<double>::infinity(), false)};
  mark_fronts(results);
  const bool front[] = {false, false, false, true, true, false};
  for (std::size_t i = 0; i < results.size(); ++i) EXPECT_EQ(results[i].pareto, front[i]) << i;
  results.erase(results.begin() + 4);
  mark_fronts(results);
  const bool front_without_peer[] = {true, true, false, true, false};
  for (std::size_t i = 0; i < results.size(); ++i)
    EXPECT_EQ(results[i].pareto, front_without_peer[i]) << i;
  for (std::size_t i = 0; i < results.size(); ++i) EXPECT_EQ(results[i].recommended, i == 1) << i;
}

TEST(LabResults, PlacedLabelsNeverOverlapEachOtherOrAPoint) {
  std::mt19937 random(5);
  std::vector<LabelRequest> requests;
  for (int i = 0; i < 80; ++i) {
    requests.push_back({100.0 + random() % 800, 100.0 + random() % 500,
                        "method " + std::to_string(i), static_cast<int>(random() % 3)});
  }
  const double char_width = 5.6, line_height = 11.0, radius = 7.0;
  const std::vector<PlacedLabel> placed =
      layout_labels(requests, 50, 950, 50, 650, char_width, line_height, radius);
  int count = 0;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (!placed[i].placed) continue;
    ++count;
    const double left = placed[i].x, right = left + char_width * placed[i].text.size();
    const double bottom = placed[i].y - line_height / 2, top = placed[i].y + line_height / 2;
    EXPECT_GE(left, 50);
    EXPECT_LE(right, 950);
    for (std::size_t j = 0; j < placed.size(); ++j) {
      const LabelRequest& point = requests[j];
      EXPECT_FALSE(point.x + radius > left && point.x - radius < right && point.y + radius > bottom &&
                   point.y - radius < top)
          << "label " << i << " covers point " << j;
      if (j == i || !placed[j].placed) continue;
      const double other_left = placed[j].x;
      const double other_right = other_left + char_width * placed[j].text.size();
      EXPECT_FALSE(left < other_right && other_left < right &&
                   bottom < placed[j].y + line_height / 2 && placed[j].y - line_height / 2 < top)
          << "labels " << i << " and " << j << " overlap";
    }
  }
  EXPECT_GT(count, 40);  // most points get their label on an 900x600 area
}

TEST(LabResults, ShardIsKOverN) {
  EXPECT_EQ(parse_shard("2/4"), std::make_pair(2, 4));
  EXPECT_EQ(parse_shard("1/1"), std::make_pair(1, 1));
  for (const char* bad : {"0/4", "5/4", "2", "2/0", "a/b", "2/4x", " 1/ 2", "+1/2", "1/0x2", "1/2 "}) {
    EXPECT_THROW(parse_shard(bad), demos::UsageError) << bad;
  }
}

}  // namespace
}  // namespace impulse2d::lab
