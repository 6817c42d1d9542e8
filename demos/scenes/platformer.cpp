/// @file platformer.cpp
/// The platformer character (gameplay/character.h) on a course that shows every move: a short
/// hop and a full jump, up through a one-way platform and down through it again, idle on a
/// 30-degree slope, a coyote jump off a ledge followed by a double jump, a buffered jump on
/// landing, a ride on a moving kinematic platform, and wall jumps up a shaft. The run is
/// scripted with button events (left, right, jump, down), so it is the same every time.
#include "core/world.h"
#include "scene/character_script.h"
#include "scene/scene.h"
#include "scene/script_state.h"
#include "demos/scene_helpers.h"

#include <optional>

namespace impulse2d::demos::scenes {
namespace {

// Tags in `BodyDef::user_data` by which the controller finds the bodies the builder made.
constexpr std::uint64_t moving_platform_tag = 2;

constexpr vec2 spawn{-1.5f, 0.5f};          // character centre at the start, metres
constexpr float platform_left = 22.2f;      // moving platform centre, leftmost x, metres
constexpr float platform_right = 27.8f;     // rightmost x, metres
constexpr float platform_speed = 2.0f;      // m/s
constexpr float platform_top = 3.6f;        // metres
constexpr vec2 platform_half{1.0f, 0.2f};   // metres

Material course_material() { return Material{"Course", 0.0f, 0.0f, 0.6f, 0.4f}; }

BodyId add_tagged_box(World& world, BodyType type, vec2 lower, vec2 upper, std::uint64_t tag) {
  BodyDef def;
  def.type = type;
  def.position = 0.5f * (lower + upper);
  def.material = course_material();
  def.user_data = tag;
  return world.create_body(def, make_box(0.5f * (upper - lower)));
}

void build(World& world, const Params&) {
  const Material course = course_material();
  add_tagged_box(world, BodyType::Static, {-3.0f, -1.0f}, {40.0f, 0.0f}, 0);    // floor
  add_tagged_box(world, BodyType::Static, {1.5f, 2.0f}, {4.5f, 2.2f}, one_way_platform_tag);
  // 30-degree slope from (7, 0) up to the plateau at x = 12.
  const CosSin slope_angle = cos_sin(radians(30.0f));  // the engine's own, not libm's
  const float slope_top = 5.0f * slope_angle.sine / slope_angle.cosine;
  const vec2 slope[3] = {{7.0f, 0.0f}, {12.0f, 0.0f}, {12.0f, slope_top}};
  vec2 slope_centroid;
  const Shape slope_shape = make_polygon(slope, 3, &slope_centroid);
  add_body(world, BodyType::Static, slope_shape, slope_centroid, course);
  add_tagged_box(world, BodyType::Static, {12.0f, 0.0f}, {15.0f, slope_top}, 0);  // plateau
  add_tagged_box(world, BodyType::Static, {18.5f, 0.0f}, {21.0f, platform_top}, 0);  // ledge
  add_tagged_box(world, BodyType::Kinematic,
                 {platform_left - platform_half.x, platform_top - 2.0f * platform_half.y},
                 {platform_left + platform_half.x, platform_top}, moving_platform_tag);
  add_tagged_box(world, BodyType::Static, {29.0f, 0.0f}, {31.5f, platform_top}, 0);  // landing
  // The shaft: a wall hanging over a gap the character walks under, and a tall block.
  add_tagged_box(world, BodyType::Static, {33.0f, 1.3f}, {34.0f, 8.0f}, 0);
  add_tagged_box(world, BodyType::Static, {36.5f, 0.0f}, {40.0f, 6.3f}, 0);
}

/// The character from the buttons, plus the moving platform shuttling between its ends at
/// constant speed (moved before the character reads its contacts).
class PlatformerScript final : public CharacterScript {
 public:
  PlatformerScript() : CharacterScript(character_def()) {}

  void before_step(World& world, std::int64_t step) override {
    if (platform_.is_null()) {
      for (const BodyId id : world.body_ids()) {
        if (world.body(id).user_data == moving_platform_tag) platform_ = id;
      }
    }
    const float x = world.body(platform_).transform.position.x;
    if (x >= platform_right) platform_direction_ = -1.0f;
    if (x <= platform_left) platform_direction_ = 1.0f;
    world.set_linear_velocity(platform_, {platform_direction_ * platform_speed, 0.0f});
    CharacterScript::before_step(world, step);
  }

  std::vector<std::uint8_t> save_state() const override {
    ScriptStateWriter out(state_version);
    out.body(platform_);
    out.f32(platform_direction_);
    out.nested(CharacterScript::save_state());
    return out.bytes();
  }

  void restore_state(World& world, const std::vector<std::uint8_t>& bytes) override {
    ScriptStateReader in(bytes, "script platformer", state_version);
    platform_ = in.body();
    if (!platform_.is_null() && !world.is_valid(platform_)) {
      in.fail("the moving platform is not a body of the saved world");
    }
    platform_direction_ = in.f32();
    const std::vector<std::uint8_t> character = in.nested();
    in.finish();
    CharacterScript::restore_state(world, character);
  }

 private:
  static CharacterDef character_def() {
    CharacterDef def;
    def.position = spawn;
    return def;
  }

  static constexpr std::uint32_t state_version = 1;
  BodyId platform_;
  float platform_direction_ = 1.0f;
};

/// The scripted run: (step, button, pressed) at 60 steps per second.
struct Press {
  std::int64_t step;
  const char* button;
  bool pressed;
};

const Press run_script[] = {
    {10, "jump", true}, {11, "jump", false},                       // a tap: short hop (h)
    {75, "right", true}, {118, "right", false},                    // walk under the one-way
    {125, "jump", true}, {165, "jump", false},                     // held: up through it, land
    {200, "down", true}, {200, "jump", true},                      // down + jump: drop through
    {202, "down", false}, {202, "jump", false},
    {245, "right", true}, {320, "right", false},                   // up the slope, stop on it
    {380, "right", true},                                          // on to the plateau and off
    {447, "jump", true}, {460, "jump", false},                     // coyote jump after the edge
    {472, "jump", true}, {476, "right", false}, {480, "jump", false},  // double jump to the ledge
    {541, "jump", true}, {543, "jump", false},                     // pressed early: buffered hop
    {660, "right", true}, {684, "right", false},                   // onto the moving platform
    {830, "right", true}, {890, "right", false},                   // off it, over the edge
    {945, "right", true},                                          // under the wall, into the shaft
    {962, "jump", true}, {972, "jump", false},                     // jump at the right wall
    {990, "right", false}, {990, "left", true},                    // wall jump left
    {990, "jump", true}, {1004, "jump", false},
    {1012, "left", false}, {1012, "right", true},                  // wall jump right, over the top
    {1012, "jump", true}, {1026, "jump", false},
    {1048, "right", false},
};

}  // namespace

Scene platformer() {
  Scene scene;
  scene.name = "platformer";
  scene.description =
      "a scripted platformer character: hop and full jump, one-way platform up and down, "
      "slope, coyote + double jump, buffered jump, moving platform, wall jumps";
  // The character controller is tuned and tested on the accumulated solver at one sub-step
  // (tests/test_character_*.cpp); the scene picks it.
  scene.settings = settings_for(SolverMethod::Accumulated);
  scene.model.velocity_iterations = scene.settings.velocity_iterations;
  scene.model.boxes = true;
  scene.model.polygons = true;
  scene.model.rotation = false;
  scene.model.restitution = false;
  // The camera follows the character (the script's followed body), close enough to read its
  // overlays while still showing the part of the level it is in.
  scene.view.camera.mode = CameraSpec::Mode::Follow;
  scene.view.camera.center = spawn;
  scene.view.camera.pixels_per_metre = 32.0f;
  scene.view.steps = 1110;
  scene.view.frames = "::4";
  scene.view.draw.flags = draw_shapes | draw_contact_normals;
  scene.view.caption = "every move of the character, scripted";
  scene.build = build;
  scene.script = [](const Params&) { return std::make_unique<PlatformerScript>(); };
  for (const Press& press : run_script) {
    SceneEvent event;
    event.step = press.step;
    event.kind = SceneEventKind::Button;
    event.button = press.button;
    event.pressed = press.pressed;
    event.origin = "platformer script";
    scene.events.push_back(event);
  }
  return scene;
}

}  // namespace impulse2d::demos::scenes
