// Which steps become frames: the `A:B:k` syntax of `--frames` and of a scene file's
// `run.frames`, and its errors naming the spec.
#include "scene/frame_selection.h"
#include "scene/usage_error.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>

using namespace impulse2d::demos;

TEST(FrameSelection, EveryKthAndRanges) {
  const FrameSelection all;
  EXPECT_TRUE(all.contains(0));
  EXPECT_TRUE(all.contains(12345));
  EXPECT_FALSE(all.last().has_value());

  const FrameSelection every = FrameSelection::every(10);
  EXPECT_TRUE(every.contains(0));
  EXPECT_TRUE(every.contains(30));
  EXPECT_FALSE(every.contains(31));

  const FrameSelection ranges = FrameSelection::parse("5,10:20:5,100:");
  EXPECT_TRUE(ranges.contains(5));
  EXPECT_FALSE(ranges.contains(6));
  EXPECT_TRUE(ranges.contains(10));
  EXPECT_TRUE(ranges.contains(15));
  EXPECT_TRUE(ranges.contains(20));
  EXPECT_FALSE(ranges.contains(25));
  EXPECT_FALSE(ranges.contains(99));
  EXPECT_TRUE(ranges.contains(100));
  EXPECT_TRUE(ranges.contains(101));
  EXPECT_FALSE(ranges.last().has_value());

  EXPECT_TRUE(FrameSelection::parse("::25").contains(50));
  EXPECT_FALSE(FrameSelection::parse("::25").contains(51));
  EXPECT_EQ(FrameSelection::parse("0:59:10").last(), std::optional<std::int64_t>(50));
  EXPECT_EQ(FrameSelection::parse("3").last(), std::optional<std::int64_t>(3));
}

TEST(FrameSelection, BadSpecsNameTheProblem) {
  for (const char* spec : {"", "a", "1:2:3:4", "5:1", "0:10:0", "-1:", "1,,2"}) {
    try {
      FrameSelection::parse(spec);
      FAIL() << "'" << spec << "' was accepted";
    } catch (const UsageError& error) {
      EXPECT_NE(std::string(error.what()).find(std::string("'") + spec + "'"), std::string::npos) << error.what();
    }
  }
  EXPECT_THROW(FrameSelection::every(0), UsageError);
}
