// The events overlay (issue 32): marks where each event happened, kept from step to step until
// the frame that shows them, in the legend only when drawn, and no pixel where nothing happened.
#include "core/world.h"
#include "render/event_marks.h"
#include "render/frame_renderer.h"

#include <gtest/gtest.h>

#include <vector>

using namespace impulse2d;
using namespace impulse2d::render;

namespace {

// Ground (top at y = 0), a ball with hit events whose bottom is `drop` m above it, and a
// sensor box around y = 2 that the ball falls through.
struct DropWorld {
  World world;
  BodyId ball;
  explicit DropWorld(float drop) {
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.position = {0.0f, -1.0f};
    world.create_body(ground, make_box({5.0f, 1.0f}));
    BodyDef sensor;
    sensor.type = BodyType::Static;
    sensor.is_sensor = true;
    sensor.position = {0.0f, 2.0f};
    world.create_body(sensor, make_box({1.0f, 0.25f}));
    BodyDef def;
    def.position = {0.0f, 0.5f + drop};
    def.enable_hit_events = true;
    ball = world.create_body(def, make_circle(0.5f));
  }
};

int count_kind(const std::vector<EventMark>& marks, EventKind kind) {
  int count = 0;
  for (const EventMark& mark : marks) count += mark.kind == kind ? 1 : 0;
  return count;
}

}  // namespace

// Recorded step by step, every event of the fall is kept until cleared: the sensor's begin and
// end at the ball's centre, the touch's begin and the hit at the ground, the bounce's end.
TEST(EventMarks, RecordKeepsEveryStepsEventsUntilCleared) {
  DropWorld drop(4.0f);
  EventMarks marks;
  int steps_with_events = 0;
  for (std::int64_t step = 1; step <= 60; ++step) {
    drop.world.step();
    const std::size_t before = marks.marks().size();
    marks.record(drop.world, step);
    if (marks.marks().size() > before) ++steps_with_events;
  }
  const std::vector<EventMark>& all = marks.marks();
  EXPECT_GE(steps_with_events, 3) << "sensor begin, sensor end and the landing come in different steps";
  EXPECT_EQ(count_kind(all, EventKind::sensor_begin), 1);
  EXPECT_EQ(count_kind(all, EventKind::sensor_end), 1);
  ASSERT_EQ(count_kind(all, EventKind::touch_begin), 1);
  ASSERT_EQ(count_kind(all, EventKind::hit), 1);
  for (const EventMark& mark : all) {
    if (mark.kind == EventKind::touch_begin || mark.kind == EventKind::hit) {
      EXPECT_NEAR(mark.point.y, 0.0f, 0.1f) << "at the ground";
      EXPECT_NEAR(mark.point.x, 0.0f, 1e-5f);
    }
    if (mark.kind == EventKind::hit) {
      EXPECT_GT(mark.speed, 8.0f);  // sqrt(2 g 4) = 8.9 m/s
    }
    if (mark.kind == EventKind::sensor_begin) {
      EXPECT_NEAR(mark.point.y, 2.25f + 0.5f, 0.2f) << "entering the box";
    }
  }
  for (std::size_t i = 1; i < all.size(); ++i) EXPECT_LE(all[i - 1].step, all[i].step);
  const EventCounts counts = count_event_marks(all);
  EXPECT_EQ(counts.total(), static_cast<int>(all.size()));
  marks.clear();
  EXPECT_TRUE(marks.marks().empty());
}

// A touch whose body is removed between two steps ends in the next step's events with a stale
// handle, and the world has no contact left to place it: `EventMarks` crosses it where the
// pair touched when it last looked (the record after the step before, or `start` for a run
// that begins there, as one resumed from a saved state does), so both draw the same cross.
TEST(EventMarks, AnEndWhoseBodyWasRemovedIsCrossedWhereThePairLastTouched) {
  std::vector<vec2> crosses;
  for (const bool resumed : {false, true}) {
    DropWorld drop(0.5f);
    EventMarks marks;
    for (std::int64_t step = 1; step <= 90; ++step) {
      drop.world.step();
      if (!resumed) marks.record(drop.world, step);
    }
    ASSERT_EQ(drop.world.contacts().size() + drop.world.sleeping_contacts().size(), 1u) << "the ball rests";
    if (resumed) marks.start(drop.world);
    marks.clear();
    drop.world.remove_body(drop.ball);
    drop.world.step();
    ASSERT_EQ(drop.world.contact_events().end.size(), 1u) << "the removal ends the touch";
    EXPECT_EQ(count_kind(last_step_event_marks(drop.world, 91), EventKind::touch_end), 0)
        << "the world alone has no place for it";
    marks.record(drop.world, 91);
    ASSERT_EQ(marks.marks().size(), 1u);
    const EventMark& mark = marks.marks()[0];
    EXPECT_EQ(mark.kind, EventKind::touch_end);
    EXPECT_EQ(mark.step, 91);
    EXPECT_NEAR(mark.point.x, 0.0f, 1e-4f) << "under the ball";
    EXPECT_NEAR(mark.point.y, 0.0f, 0.02f) << "on the ground's top";
    crosses.push_back(mark.point);
    marks.clear();
    drop.world.step();
    marks.record(drop.world, 92);
    EXPECT_TRUE(marks.marks().empty()) << "ended once";
  }
  EXPECT_EQ(crosses[0], crosses[1]);
}

// The legend names only the kinds drawn; nothing is drawn or listed without events, so frames
// that ask for the overlay where nothing happened equal those that do not ask.
TEST(EventMarks, LegendAndPixelsOnlyWhereSomethingHappened) {
  const DebugPalette palette;
  std::vector<EventMark> marks = {{EventKind::hit, {0.0f, 0.0f}, 5.0f, 1}};
  std::vector<LegendEntry> entries = event_legend_entries(marks, palette);
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].label, "hit");
  marks.push_back({EventKind::touch_end, {0.0f, 0.0f}, 0.0f, 1});
  marks.push_back({EventKind::sensor_begin, {0.0f, 0.0f}, 0.0f, 1});
  entries = event_legend_entries(marks, palette);
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].label, "touch o/x");
  EXPECT_EQ(entries[2].label, "sensor o/x");
  EXPECT_TRUE(event_legend_entries({}, palette).empty());

  DropWorld drop(4.0f);
  FrameRenderer renderer(320, 240);
  const Camera camera = Camera::fit(world_bounds(drop.world), 320, 240);
  FrameOptions plain;
  FrameOptions events = plain;
  events.draw.flags |= draw_events;
  EventMarks recorded;
  events.events = &recorded;
  HudInfo hud;
  hud.scene_name = "drop";
  hud.step = 1;
  drop.world.step();  // nothing happens in the first step
  recorded.record(drop.world, 1);
  ASSERT_TRUE(recorded.marks().empty());
  EXPECT_EQ(renderer.render(drop.world, camera, plain, hud).rgba, renderer.render(drop.world, camera, events, hud).rgba);
  for (std::int64_t step = 2; step <= 60; ++step) {
    drop.world.step();
    recorded.record(drop.world, step);
  }
  ASSERT_FALSE(recorded.marks().empty());
  EXPECT_NE(renderer.render(drop.world, camera, plain, hud).rgba, renderer.render(drop.world, camera, events, hud).rgba);
}
