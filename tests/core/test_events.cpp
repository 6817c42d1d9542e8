// Events (issue 32): contact begin/end touch, hits and sensor overlaps, read after each step,
// against exact answers taken from a twin world (the step of first contact is the first step
// whose trajectory leaves free fall), and identical across runs.
#include "core/error.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>
#include <tuple>
#include <vector>

using namespace impulse2d;

namespace {

constexpr float ground_top = 0.0f;
constexpr float ball_radius = 0.5f;

BodyId add_ground(World& world) {
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.position = {0.0f, ground_top - 1.0f};
  return world.create_body(ground, make_box({20.0f, 1.0f}));
}

BodyId add_ball(World& world, float drop_height, bool hit_events) {
  BodyDef ball;
  ball.position = {0.0f, ground_top + ball_radius + drop_height};
  ball.enable_hit_events = hit_events;
  return world.create_body(ball, make_circle(ball_radius));
}

bool same_bits(const BodyView& a, const BodyView& b) {
  return std::memcmp(&a.transform.position, &b.transform.position, sizeof(vec2)) == 0 &&
         std::memcmp(&a.linear_velocity, &b.linear_velocity, sizeof(vec2)) == 0 &&
         std::memcmp(&a.angle, &b.angle, sizeof(float)) == 0 &&
         std::memcmp(&a.angular_velocity, &b.angular_velocity, sizeof(float)) == 0;
}

// One step's events, flattened for comparison across runs.
struct StepEvents {
  int step = 0;
  int kind = 0;  // 0 begin, 1 end, 2 hit, 3 sensor begin, 4 sensor end
  std::uint32_t a = 0, b = 0;
  float speed = 0.0f;
  bool operator==(const StepEvents& o) const {
    return step == o.step && kind == o.kind && a == o.a && b == o.b &&
           std::memcmp(&speed, &o.speed, sizeof speed) == 0;
  }
};

void record(const World& world, int step, std::vector<StepEvents>& log) {
  for (const auto& e : world.contact_events().begin) log.push_back({step, 0, e.body_a.index, e.body_b.index, 0});
  for (const auto& e : world.contact_events().end) log.push_back({step, 1, e.body_a.index, e.body_b.index, 0});
  for (const auto& e : world.contact_events().hit)
    log.push_back({step, 2, e.body_a.index, e.body_b.index, e.approach_speed});
  for (const auto& e : world.sensor_events().begin)
    log.push_back({step, 3, e.sensor_body.index, e.visitor_body.index, 0});
  for (const auto& e : world.sensor_events().end)
    log.push_back({step, 4, e.sensor_body.index, e.visitor_body.index, 0});
}

}  // namespace

// A ball dropped from h onto the ground: one begin touch and one hit at the step of first
// contact, an end touch when it bounces off, and none once it rests or falls asleep.
TEST(Events, BallDropBeginHitEndAndSleep) {
  const float h = 5.0f;
  WorldSettings settings;
  settings.enable_sleeping = true;
  World world(settings);
  const BodyId ground = add_ground(world);
  const BodyId ball = add_ball(world, h, true);
  // The twin without ground gives the step of first contact: the first whose state differs.
  World twin(settings);
  const BodyId twin_ball = add_ball(twin, h, true);

  int first_contact = -1;
  int falls_asleep = -1;
  std::vector<StepEvents> log;
  for (int step = 1; step <= 900; ++step) {
    world.step();
    twin.step();
    if (first_contact < 0 && !same_bits(world.body(ball), twin.body(twin_ball))) first_contact = step;
    if (falls_asleep < 0 && !world.body(ball).awake) falls_asleep = step;
    record(world, step, log);
    for (const auto& e : world.contact_events().begin) {
      EXPECT_EQ(e.body_a, ground);
      EXPECT_EQ(e.body_b, ball);
      EXPECT_EQ(e.shape_b.body, ball);
      EXPECT_EQ(e.shape_b.index, 0u);
    }
  }
  ASSERT_GT(first_contact, 0);
  ASSERT_GT(falls_asleep, 0) << "the ball never slept";

  // Exactly one begin at the step of first contact, and it is the first event of all.
  ASSERT_FALSE(log.empty());
  EXPECT_EQ(log[0].step, first_contact);
  EXPECT_EQ(log[0].kind, 0);
  int begins_at_contact = 0, hits_at_contact = 0;
  float hit_speed = 0.0f;
  for (const StepEvents& e : log) {
    if (e.step != first_contact) continue;
    begins_at_contact += e.kind == 0;
    if (e.kind == 2) {
      ++hits_at_contact;
      hit_speed = e.speed;
    }
  }
  EXPECT_EQ(begins_at_contact, 1);
  ASSERT_EQ(hits_at_contact, 1);
  // The approach speed is the speed the ball reaches by the end of the impact step k in free
  // fall, v_k = k g dt (semi-implicit Euler), and the ball's drop after k steps is
  // d_k = g dt^2 k (k + 1) / 2, so d_{k-1} < h <= d_k gives
  // 2 g h k / (k + 1) <= v_k^2 < 2 g h k / (k - 1): |v_k / sqrt(2 g h) - 1| < 1 / (2 (k - 1)).
  // Here k = 61 (t = 1.01 s at 60 Hz): 0.83 %, inside 1 %.
  const float g = 9.81f;
  const float exact = std::sqrt(2.0f * g * h);
  const float tolerance = 1.0f / (2.0f * static_cast<float>(first_contact - 1));
  EXPECT_LT(tolerance, 0.01f);
  EXPECT_NEAR(hit_speed / exact, 1.0f, tolerance) << "hit " << hit_speed << " exact " << exact;

  // It bounces: the first end comes after the first begin; begins and ends alternate and it
  // ends touching.
  int begins = 0, ends = 0, last_event_step = 0;
  bool touching = false;
  for (const StepEvents& e : log) {
    if (e.kind == 0) {
      EXPECT_FALSE(touching) << "two begins in a row at step " << e.step;
      touching = true;
      ++begins;
    } else if (e.kind == 1) {
      EXPECT_TRUE(touching) << "end without begin at step " << e.step;
      touching = false;
      ++ends;
    }
    last_event_step = e.step;
  }
  EXPECT_GE(ends, 1) << "no end touch: it never bounced off";
  EXPECT_EQ(begins, ends + 1);
  EXPECT_TRUE(touching);
  // Once it settles nothing more is reported; falling asleep is not an end.
  EXPECT_LT(last_event_step, falls_asleep);
  std::printf("first contact step %d, hit %.4f m/s (exact %.4f), %d bounces, asleep at %d\n",
              first_contact, hit_speed, exact, ends, falls_asleep);

  // Identical across runs.
  World again(settings);
  add_ground(again);
  add_ball(again, h, true);
  std::vector<StepEvents> log_again;
  for (int step = 1; step <= 900; ++step) {
    again.step();
    record(again, step, log_again);
  }
  EXPECT_EQ(log, log_again);
}

// Hits are off by default; contact events can be turned off; removing a body ends its touches.
TEST(Events, FlagsAndRemoval) {
  World world;
  add_ground(world);
  const BodyId ball = add_ball(world, 1.0f, false);
  int begins = 0;
  for (int i = 0; i < 120; ++i) {
    world.step();
    EXPECT_TRUE(world.contact_events().hit.empty());
    begins += static_cast<int>(world.contact_events().begin.size());
  }
  EXPECT_GE(begins, 1);
  world.remove_body(ball);
  world.step();
  ASSERT_EQ(world.contact_events().end.size(), 1u);
  EXPECT_EQ(world.contact_events().end[0].body_b, ball);
  world.step();
  EXPECT_TRUE(world.contact_events().end.empty());

  World quiet;
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.enable_contact_events = false;
  ground.position = {0.0f, -1.0f};
  quiet.create_body(ground, make_box({20.0f, 1.0f}));
  BodyDef def;
  def.enable_contact_events = false;
  def.position = {0.0f, 1.0f};
  quiet.create_body(def, make_circle(0.5f));
  for (int i = 0; i < 120; ++i) {
    quiet.step();
    EXPECT_TRUE(quiet.contact_events().begin.empty());
  }
  EXPECT_THROW(quiet.set_hit_event_threshold(-1.0f), Error);
}

// Events only read the step: a pyramid steps bit for bit alike with every event on or off.
TEST(Events, EventsDoNotChangeTheStep) {
  auto run = [](bool events) {
    World world;
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.position = {0.0f, -1.0f};
    ground.enable_contact_events = events;
    ground.enable_hit_events = events;
    world.create_body(ground, make_box({20.0f, 1.0f}));
    for (int row = 0; row < 6; ++row) {
      for (int i = 0; i < 6 - row; ++i) {
        BodyDef def;
        def.position = {-2.5f + static_cast<float>(i) + 0.5f * static_cast<float>(row),
                        0.5f + static_cast<float>(row)};
        def.enable_contact_events = events;
        def.enable_hit_events = events;
        world.create_body(def, make_oriented_box({0.45f, 0.45f}));
      }
    }
    for (int i = 0; i < 200; ++i) world.step();
    return world.state_hash();
  };
  EXPECT_EQ(run(true), run(false));
}

// A ball falling through a sensor box: begin at the step its shape first overlaps the box,
// end at the step it has left it, and a trajectory bit-identical to the run without the sensor.
TEST(Events, SensorBeginEndAndNoResponse) {
  const float radius = 0.25f;
  const float sensor_y = 5.0f, half_height = 0.5f;
  World plain;
  World sensed;
  BodyDef ball;
  ball.position = {0.0f, 10.0f};
  const BodyId plain_ball = plain.create_body(ball, make_circle(radius));
  const BodyId sensed_ball = sensed.create_body(ball, make_circle(radius));
  BodyDef sensor;
  sensor.type = BodyType::Static;
  sensor.is_sensor = true;
  sensor.position = {0.0f, sensor_y};
  const BodyId box = sensed.create_body(sensor, make_box({1.0f, half_height}));
  // A static body the sensor ignores by default.
  BodyDef wall;
  wall.type = BodyType::Static;
  wall.position = {0.9f, sensor_y};
  sensed.create_body(wall, make_box({0.2f, 0.2f}));

  int expected_begin = -1, expected_end = -1, begin = -1, end = -1;
  for (int step = 1; step <= 150; ++step) {
    plain.step();
    sensed.step();
    ASSERT_TRUE(same_bits(plain.body(plain_ball), sensed.body(sensed_ball))) << "step " << step;
    const float y = plain.body(plain_ball).transform.position.y;
    const bool overlapping = y - radius < sensor_y + half_height && y + radius > sensor_y - half_height;
    if (overlapping && expected_begin < 0) expected_begin = step;
    if (!overlapping && expected_begin > 0 && expected_end < 0) expected_end = step;
    for (const auto& e : sensed.sensor_events().begin) {
      EXPECT_EQ(e.sensor_body, box);
      EXPECT_EQ(e.visitor_body, sensed_ball);
      EXPECT_EQ(begin, -1);
      begin = step;
    }
    for (const auto& e : sensed.sensor_events().end) {
      EXPECT_EQ(e.visitor_body, sensed_ball);
      EXPECT_EQ(end, -1);
      end = step;
    }
    EXPECT_TRUE(sensed.contacts().empty());
  }
  ASSERT_GT(expected_begin, 0);
  ASSERT_GT(expected_end, 0);
  EXPECT_EQ(begin, expected_begin);
  EXPECT_EQ(end, expected_end);

  // Static bodies when asked for.
  World statics;
  sensor.sensor_detects_static = true;
  statics.create_body(sensor, make_box({1.0f, half_height}));
  const BodyId seen = statics.create_body(wall, make_box({0.2f, 0.2f}));
  statics.step();
  ASSERT_EQ(statics.sensor_events().begin.size(), 1u);
  EXPECT_EQ(statics.sensor_events().begin[0].visitor_body, seen);
  statics.remove_body(seen);
  statics.step();
  ASSERT_EQ(statics.sensor_events().end.size(), 1u);
}

namespace {

constexpr vec2 triangle_vertices[3] = {{-0.5f, 0.0f}, {0.5f, 0.0f}, {0.0f, 0.8f}};

// A triangle (centroid 0.8 / 3 m above its base) with hit events, base `drop` metres above the
// ground, turned by `angle` radians, sliding at `speed` m/s.
BodyId add_triangle(World& world, float drop, float angle, float speed) {
  BodyDef def;
  def.enable_hit_events = true;
  def.position = {0.0f, ground_top + 0.8f / 3.0f + drop};
  def.angle = angle;
  def.linear_velocity = {speed, 0.0f};
  return world.create_body(def, make_polygon(triangle_vertices, 3));
}

}  // namespace

// Issue 32 (c): a triangle dropped flat while sliding lands once. The speculative contact lets
// it arrive at the ground surface in one step (it begins touching there) and stops it in the
// next, the first step that leaves free fall: that step, and only it, reports the hit, with the
// speed it arrives with (it used to be reported in both steps, with no end touch between).
TEST(Events, SlidingTriangleLandingHitsOnceWhenStopped) {
  World world;
  add_ground(world);
  const BodyId triangle = add_triangle(world, 0.5f, 0.0f, 4.0f);
  World twin;  // no ground: free fall
  const BodyId twin_triangle = add_triangle(twin, 0.5f, 0.0f, 4.0f);
  int stopped = -1, first_end = -1;
  std::vector<int> hit_steps;
  float hit_speed = 0.0f, arrival_speed = 0.0f;
  for (int step = 1; step <= 120 && first_end < 0; ++step) {
    world.step();
    twin.step();
    if (stopped < 0 && !same_bits(world.body(triangle), twin.body(twin_triangle))) {
      stopped = step;
      arrival_speed = -twin.body(twin_triangle).linear_velocity.y;
    }
    for (const auto& e : world.contact_events().hit) {
      hit_steps.push_back(step);
      hit_speed = e.approach_speed;
    }
    if (!world.contact_events().end.empty()) first_end = step;
  }
  ASSERT_GT(stopped, 0);
  ASSERT_EQ(hit_steps.size(), 1u) << "hits at steps " << ::testing::PrintToString(hit_steps) << ", stopped at "
                                  << stopped << ", first end at " << first_end;
  EXPECT_EQ(hit_steps[0], stopped);
  EXPECT_NEAR(hit_speed, arrival_speed, 1e-4f);
}

// A hit is an impact at a point the step must stop: a corner still in the air while another
// one rests is not hit until it lands. For each hit of a tumbling, sliding triangle, the vertex
// nearest the hit point, moving at the hit's approach speed from where it was when the step
// began, would reach the ground within the step.
TEST(Events, TumblingTriangleHitsOnlyCornersThatLand) {
  struct Throw {
    float drop, angle, speed;
  };
  int hits = 0;
  for (const Throw t : {Throw{0.05f, 0.1f, 10.0f}, Throw{1.0f, 0.3f, 6.0f}, Throw{2.0f, 0.7f, 8.0f},
                        Throw{0.2f, 1.0f, 3.0f}, Throw{3.0f, 2.0f, 5.0f}}) {
    World world;
    add_ground(world);
    const BodyId triangle = add_triangle(world, t.drop, t.angle, t.speed);
    const float dt = world.settings().time_step;
    for (int step = 1; step <= 240; ++step) {
      const Transform before = world.body(triangle).transform;
      world.step();
      for (const auto& e : world.contact_events().hit) {
        ++hits;
        float nearest = 1e9f, height = 0.0f;
        for (const vec2 local : triangle_vertices) {
          const vec2 vertex = before.apply(local - vec2(0.0f, 0.8f / 3.0f));
          const float distance = glm::length(vertex - e.point);
          if (distance < nearest) {
            nearest = distance;
            height = vertex.y - ground_top;
          }
        }
        EXPECT_LT(height - e.approach_speed * dt, 0.0f)
            << "drop " << t.drop << " angle " << t.angle << " speed " << t.speed << ": hit at step " << step << " ("
            << e.approach_speed << " m/s) of a corner " << height << " m above the ground";
      }
    }
  }
  EXPECT_GE(hits, 5);
}

// The touch of each awake contact is judged as prepare passes it, that of each set-aside one at
// the end of the step. Recomputed here from the definition (events.h) over every contact the
// world holds after each step, with the velocities the bodies had before it, the touching set
// must move by exactly the begin and end events, in every solver, with bodies falling asleep.
TEST(Events, BeginAndEndFollowTheDefinitionOfTouchInEverySolver) {
  for (const SolverMethod method : {SolverMethod::SoftStep, SolverMethod::Accumulated, SolverMethod::PerIteration}) {
    WorldSettings settings = settings_for(method);
    settings.enable_sleeping = true;
    World world(settings);
    add_ground(world);
    for (int i = 0; i < 12; ++i) {
      BodyDef def;
      def.position = {-3.0f + 0.55f * static_cast<float>(i), 0.6f + 0.9f * static_cast<float>(i % 4)};
      def.angular_velocity = 0.3f * static_cast<float>(i % 3) - 0.3f;
      def.material.restitution = i % 3 == 0 ? 0.6f : 0.0f;
      world.create_body(def, i % 2 == 0 ? make_circle(0.3f) : make_oriented_box({0.3f, 0.2f}));
    }
    using Key = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>;
    std::set<Key> touching;
    int begins = 0;
    int ends = 0;
    int asleep_steps = 0;
    for (int step = 0; step < 600; ++step) {
      std::vector<vec2> linear(64, vec2(0.0f));
      std::vector<float> angular(64, 0.0f);
      const float dt = world.settings().time_step;
      for (const BodyId id : world.body_ids()) {
        const BodyView body = world.body(id);
        linear[id.index] = body.linear_velocity;
        angular[id.index] = body.angular_velocity;
        if (body.type == BodyType::Dynamic && body.awake) {
          linear[id.index] += (world.settings().gravity * body.gravity_scale + vec2(0.0f)) * dt;
        }
      }
      world.step();
      std::set<Key> now;
      for (const std::vector<Contact>* list : {&world.contacts(), &world.sleeping_contacts()}) {
        for (const Contact& contact : *list) {
          if (!contact.enabled) continue;
          const std::uint32_t a = contact.body_a.index;
          const std::uint32_t b = contact.body_b.index;
          for (int i = 0; i < contact.point_count; ++i) {
            const ContactPoint& point = contact.points[i];
            const vec2 relative = (linear[b] + cross(angular[b], point.anchor_b)) -
                                  (linear[a] + cross(angular[a], point.anchor_a));
            const float approach = -glm::dot(relative, contact.normal);
            if (-point.depth - approach * dt <= world.settings().slop) {
              now.insert({a, b, contact.child_a, contact.child_b});
              break;
            }
          }
        }
      }
      std::set<Key> expected_begin;
      std::set<Key> expected_end;
      for (const Key& key : now) if (!touching.count(key)) expected_begin.insert(key);
      for (const Key& key : touching) if (!now.count(key)) expected_end.insert(key);
      std::set<Key> got_begin;
      std::set<Key> got_end;
      for (const auto& e : world.contact_events().begin) {
        got_begin.insert({e.body_a.index, e.body_b.index, e.shape_a.index, e.shape_b.index});
      }
      for (const auto& e : world.contact_events().end) {
        got_end.insert({e.body_a.index, e.body_b.index, e.shape_a.index, e.shape_b.index});
      }
      ASSERT_EQ(got_begin, expected_begin) << solver_name(method) << ", step " << step + 1;
      ASSERT_EQ(got_end, expected_end) << solver_name(method) << ", step " << step + 1;
      begins += static_cast<int>(got_begin.size());
      ends += static_cast<int>(got_end.size());
      if (!world.sleeping_contacts().empty()) ++asleep_steps;
      touching = now;
    }
    // The run really has touches beginning and ending, and contacts set aside asleep.
    EXPECT_GT(begins, 12) << solver_name(method);
    EXPECT_GT(ends, 3) << solver_name(method);
    EXPECT_GT(asleep_steps, 10) << solver_name(method);
  }
}
