/// @file tutorial.cpp
/// The tutorial's demo (part 1 and part 3 videos): a static circle and a platform with bodies
/// raining on them. Two copies side by side, each in its own collision layer: on the left
/// every surface is frictionless (part 1: bodies slide off the platform), on the right the
/// tutorial's materials keep their friction (part 3: they come to rest). Both copies receive
/// the same bodies at the same places.
#include <vector>

#include "core/world.h"
#include "scene/scene.h"
#include "scene/script_state.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float half_offset = 11.0f;      // x of each copy's centre, metres
constexpr float spawn_height = 15.0f;     // metres
constexpr float spawn_half_width = 4.5f;  // spawns in [-w, w] around a copy's centre, metres
constexpr float lost_below = -10.0f;      // bodies that fall below this are removed, metres
constexpr std::uint32_t left_layer = 1u, right_layer = 2u;

/// Drops one random body on each copy every `interval` steps until `count` have fallen, and
/// removes bodies that left the screen (the tutorial's bodies drift off the platform).
class Rain final : public StepScript {
 public:
  explicit Rain(const Params& params)
      : random_(static_cast<std::uint32_t>(params.integer("seed"))),
        count_(params.integer("bodies")),
        interval_(params.integer("interval")) {}

  void before_step(World& world, std::int64_t step) override {
    remove_lost_bodies(world);
    if (step % interval_ != 0 || dropped_ >= count_) return;
    ++dropped_;
    const Drop drop = next_drop();
    add_body(world, BodyType::Dynamic, drop.shape, {drop.x - half_offset, spawn_height},
             frictionless(drop.material), drop.angle, left_layer);
    add_body(world, BodyType::Dynamic, drop.shape, {drop.x + half_offset, spawn_height},
             drop.material, drop.angle, right_layer);
  }

  // The bodies dropped so far; the generator is the seed's after that many drops.
  std::vector<std::uint8_t> save_state() const override {
    ScriptStateWriter out(state_version);
    out.i32(dropped_);
    return out.bytes();
  }

  void restore_state(World&, const std::vector<std::uint8_t>& bytes) override {
    ScriptStateReader in(bytes, "script tutorial", state_version);
    const int dropped = in.i32(0, count_);
    in.finish();
    for (; dropped_ < dropped; ++dropped_) next_drop();  // the generator's draws, again
  }

 private:
  static constexpr std::uint32_t state_version = 1;

  // One body to drop on both copies, at `x` from a copy's centre.
  struct Drop {
    Material material;
    Shape shape;
    float x = 0.0f;
    float angle = 0.0f;
  };

  // Draws the next drop from the generator (the same draws in the same order every run).
  Drop next_drop() {
    const std::vector<Material> falling = {materials::rock(),       materials::wood(),
                                           materials::metal(),      materials::bouncy_ball(),
                                           materials::super_ball(), materials::pillow()};
    Drop drop;
    drop.material = falling[static_cast<std::size_t>(random_.integer(0, 5))];
    const bool circle = random_.unit() < 0.5f;
    drop.shape = circle ? make_circle(random_.uniform(0.35f, 0.9f))
                        : random_convex_polygon(random_, random_.uniform(0.5f, 1.1f));
    drop.x = random_.uniform(-spawn_half_width, spawn_half_width);
    drop.angle = random_.uniform(0.0f, 6.2831853f);
    return drop;
  }

  void remove_lost_bodies(World& world) const {
    for (BodyId id : world.body_ids()) {
      if (world.body(id).transform.position.y < lost_below) world.remove_body(id);
    }
  }

  SceneRandom random_;
  int count_;
  int interval_;
  int dropped_ = 0;
};

void build(World& world, const Params&) {
  const Material ground = materials::static_ground();
  for (const bool with_friction : {false, true}) {
    const float x = with_friction ? half_offset : -half_offset;
    const std::uint32_t layer = with_friction ? right_layer : left_layer;
    const Material material = with_friction ? ground : frictionless(ground);
    add_static_box(world, {x, 0.0f}, {7.0f, 0.4f}, material, layer);
    add_body(world, BodyType::Static, make_circle(1.6f), {x, 5.5f}, material, 0.0f, layer);
  }
}

}  // namespace

Scene tutorial() {
  Scene scene;
  scene.name = "tutorial";
  scene.description =
      "the tutorial's demo: static circle and platform, bodies raining on them; left without "
      "friction, right with friction";
  scene.params = {
      {"bodies", "bodies dropped on each side", 40, 1, 500, true},
      {"interval", "steps between drops", 12, 1, 600, true},
      {"seed", "random seed of shapes, sizes and places", 1, 0, 4294967295.0, true},
  };
  scene.model.circles = true;
  scene.model.boxes = true;
  scene.model.polygons = true;
  scene.model.velocity_iterations = 10;
  scene.model.position_iterations = 0;
  // The tutorial's methods: fresh impulses every iteration, linear projection (40%, 5 cm
  // slop), restitution min(eA, eB), friction sqrt(a^2 + b^2).
  scene.settings = settings_for(SolverMethod::PerIteration);
  scene.settings.position_correction = PositionCorrection::LinearProjection;
  scene.settings.correction_percent = 0.4f;
  scene.settings.slop = 0.05f;
  scene.settings.restitution_mixing = RestitutionMixing::Minimum;
  scene.settings.friction_mixing = FrictionMixing::RootSumSquares;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-19.0f, -3.0f}, {19.0f, 17.0f});
  scene.view.steps = 900;
  scene.view.frames = "::3";
  scene.view.draw.impulse_scale = 8.0f;  // light bodies: 0.05 N s of weight per step -> 0.4 m
  scene.view.draw.normal_length = 0.8f;
  scene.view.caption = "left: no friction | right: friction";
  scene.build = build;
  scene.script = [](const Params& params) { return std::make_unique<Rain>(params); };
  return scene;
}

}  // namespace impulse2d::demos::scenes
