// JSON scene files: a complete scene loads with every field; each kind of bad input gives one
// message naming the file, the JSON path and the reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/world.h"
#include "scene_load_error.h"
#include "frames/scene_camera.h"
#include "render/frame_scale.h"
#include "render/hud_layout.h"
#include "scene/scene_loader.h"
#include "scene/scene_run.h"
#include "scene/usage_error.h"

using namespace impulse2d;
using namespace impulse2d::demos;
using impulse2d::demos::test::load_error;

namespace {

/// A valid scene whose first body is `body` (JSON text of one body).
std::string scene_with_body(const std::string& body) {
  return R"({"bodies": [)" + body +
         R"(, {"type": "static", "shape": {"type": "box", "half_extents": [5, 0.5]},
             "position": [0, -1], "material": "Static"}]})";
}

}  // namespace

TEST(SceneFile, LoadsEveryPartOfTheSchema) {
  const char* const text = R"({
    "name": "everything", "description": "all fields", "caption": "a caption",
    "settings": {"gravity": [0, -10], "time_step": 0.01, "substeps": 2, "solver": "per_iteration",
                 "warm_starting": false, "block_solver": false, "position_correction": "linear",
                 "correction_percent": 0.5, "slop": 0.02, "max_correction": 0.1,
                 "restitution_threshold": 0.5, "friction_mixing": "root_sum_squares",
                 "restitution_mixing": "min", "integrator": "explicit_euler",
                 "broad_phase": "brute_force", "sleep_linear_speed": 0.1, "sleep_angular_speed": 0.1,
                 "time_to_sleep": 1, "max_linear_speed": 100},
    "model": {"shapes": ["circle", "box", "polygon"], "rotation": true, "friction": true,
              "restitution": true, "ccd": true, "sleeping": true,
              "velocity_iterations": 6, "position_iterations": 2},
    "materials": {"Ice": {"density": 0.9, "restitution": 0.05, "static_friction": 0.1, "dynamic_friction": 0.03}},
    "bodies": [
      {"name": "floor", "type": "static", "shape": {"type": "box", "half_extents": [10, 1]},
       "position": [0, -1], "material": "Static", "layers": 3},
      {"name": "ball", "shape": {"type": "circle", "radius": 0.5}, "position": [0, 2],
       "velocity": [1, 0], "angular_velocity": 2, "gravity_scale": 0.5, "linear_damping": 0.1,
       "angular_damping": 0.1, "bullet": true, "material": "Ice"},
      {"shape": {"type": "polygon", "vertices": [[0, 0], [2, 0], [1, 1]]}, "position": [3, 1],
       "angle": 0.1, "fixed_rotation": true,
       "material": {"density": 1, "restitution": 0.1, "static_friction": 0.5, "dynamic_friction": 0.4}},
      {"type": "kinematic", "shape": {"type": "oriented_box", "half_extents": [0.5, 0.2]},
       "position": [-3, 3], "velocity": [0.5, 0]}
    ],
    "events": [
      {"step": 5, "type": "impulse", "body": "ball", "impulse": [1, 2], "point": [0, 2.1], "angular_impulse": 0.1},
      {"step": 2, "type": "spawn", "body": {"name": "late", "shape": {"type": "circle", "radius": 0.2}, "position": [1, 4]}},
      {"step": 8, "type": "remove", "body": "late"},
      {"step": 9, "type": "remove", "body": 2}
    ],
    "camera": {"center": [0, 1], "pixels_per_metre": 30},
    "run": {"steps": 50, "frames": "0:50:5"},
    "overlays": ["normals", "impulses"]
  })";
  const Scene scene = parse_scene(text, "everything.json");
  EXPECT_EQ(scene.name, "everything");
  EXPECT_EQ(scene.settings.substeps, 2);
  EXPECT_EQ(scene.settings.solver, SolverMethod::PerIteration);
  EXPECT_EQ(scene.settings.broad_phase, BroadPhaseMethod::BruteForce);
  EXPECT_TRUE(scene.model.ccd);
  EXPECT_EQ(scene.model.velocity_iterations, 6);
  EXPECT_EQ(scene.view.steps, 50);
  EXPECT_EQ(scene.view.camera.mode, CameraSpec::Mode::Centered);
  EXPECT_NE(scene.view.draw.flags & draw_contact_normals, 0u);
  ASSERT_EQ(scene.events.size(), 4u);

  SceneRun run(scene, Params{});
  EXPECT_EQ(run.world().body_count(), 4);
  for (int i = 0; i < 10; ++i) run.step();
  EXPECT_EQ(run.world().body_count(), 3);  // spawned one at 2, removed it at 8 and body 2 at 9
}

TEST(SceneFile, PolygonVerticesAreAroundTheGivenPosition) {
  const Scene scene = parse_scene(scene_with_body(R"({"shape": {"type": "polygon",
      "vertices": [[0, 0], [2, 0], [2, 2], [0, 2]]}, "position": [10, 20]})"),
                                  "square.json");
  SceneRun run(scene, Params{});
  EXPECT_EQ(run.world().body(run.world().body_ids()[0]).transform.position, vec2(11.0f, 21.0f));
}

TEST(SceneFile, WithoutAModelTheLeastOneCoveringTheBodiesIsInferred) {
  const Scene scene = parse_scene(
      scene_with_body(R"({"shape": {"type": "box", "half_extents": [1, 1]}, "position": [0, 3]})"),
      "boxes.json");
  EXPECT_TRUE(scene.model.boxes);
  EXPECT_FALSE(scene.model.circles);
  EXPECT_FALSE(scene.model.polygons);
  EXPECT_FALSE(scene.model.rotation);  // boxes never rotate
  EXPECT_FALSE(scene.model.ccd);
}

struct BadFile {
  const char* name;
  std::string text;
  const char* message;  // expected inside "bad.json: <message>"
};

class BadSceneFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(BadSceneFile, NamesFilePathAndReason) {
  const std::string message = load_error(GetParam().text);
  EXPECT_NE(message.find(std::string("bad.json: ") + GetParam().message), std::string::npos)
      << "got: " << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadSceneFile,
    ::testing::Values(
        BadFile{"Malformed", R"({"bodies": [ {"shape": } ]})",
                "bodies[0].shape: malformed JSON at line 1, column"},
        BadFile{
            "NaN",
            scene_with_body(R"({"shape": {"type": "circle", "radius": NaN}, "position": [0, 0]})"),
            "bodies[0].shape.radius: malformed JSON"},
        BadFile{"Infinite",
                scene_with_body(
                    R"({"shape": {"type": "circle", "radius": 1e999}, "position": [0, 0]})"),
                "bodies[0].shape.radius: malformed JSON at line 1, column"},
        BadFile{"TooLargeForFloat",
                scene_with_body(
                    R"({"shape": {"type": "circle", "radius": 1e200}, "position": [0, 0]})"),
                "bodies[0].shape.radius: must fit a float"},
        BadFile{"WrongType",
                scene_with_body(
                    R"({"shape": {"type": "circle", "radius": "big"}, "position": [0, 0]})"),
                "bodies[0].shape.radius: expected a number, got string \"big\""},
        BadFile{"MissingField", scene_with_body(R"({"shape": {"type": "circle", "radius": 1}})"),
                "bodies[0]: missing field \"position\""},
        BadFile{"MissingBodies", R"({"name": "empty"})", "(root): missing field \"bodies\""},
        BadFile{
            "NegativeRadius",
            scene_with_body(R"({"shape": {"type": "circle", "radius": -1}, "position": [0, 0]})"),
            "bodies[0].shape.radius: must be in 0.001..1000 (m; below 1 mm the solver's 1 cm slop swallows the body, above 1 km float positions lose millimetres), got -1"},
        BadFile{"NegativeDensity",
                scene_with_body(R"({"shape": {"type": "circle", "radius": 1}, "position": [0, 0],
                    "material": {"density": -2, "restitution": 0, "static_friction": 0, "dynamic_friction": 0}})"),
                "bodies[0].material.density: must be >= 0, got -2"},
        BadFile{
            "ConcavePolygon",
            scene_with_body(
                R"({"shape": {"type": "polygon", "vertices": [[0,0],[4,0],[1,1],[0,4]]}, "position": [0, 0]})"),
            "bodies[0].shape.vertices: the outline is not convex"},
        BadFile{
            "DegeneratePolygon",
            scene_with_body(
                R"({"shape": {"type": "polygon", "vertices": [[0,0],[1,0],[2,0]]}, "position": [0, 0]})"),
            "bodies[0].shape.vertices: "},
        BadFile{
            "TwoVertices",
            scene_with_body(
                R"({"shape": {"type": "polygon", "vertices": [[0,0],[1,0]]}, "position": [0, 0]})"),
            "bodies[0].shape.vertices: a polygon needs 3..8 vertices, got 2"},
        BadFile{
            "UnknownMaterial",
            scene_with_body(
                R"({"shape": {"type": "circle", "radius": 1}, "position": [0, 0], "material": "Cheese"})"),
            "bodies[0].material: unknown material \"Cheese\""},
        BadFile{
            "DynamicWithoutMass",
            scene_with_body(
                R"({"shape": {"type": "circle", "radius": 1}, "position": [0, 0], "material": "Static"})"),
            "bodies[0].material: a dynamic body needs density > 0"},
        BadFile{"UnknownShape",
                scene_with_body(R"({"shape": {"type": "hexagon"}, "position": [0, 0]})"),
                "bodies[0].shape.type: unknown shape type \"hexagon\""},
        BadFile{"ChainOnADynamicBody",
                scene_with_body(
                    R"({"shape": {"type": "chain", "points": [[0, 0], [1, 0]]}, "position": [0, 0]})"),
                "bodies[0].shape.type: a chain is level geometry"},
        BadFile{
            "Misspelt",
            scene_with_body(R"({"shape": {"type": "circle", "raduis": 1}, "position": [0, 0]})"),
            "bodies[0].shape: unknown field \"raduis\""},
        BadFile{"BadVector",
                scene_with_body(R"({"shape": {"type": "circle", "radius": 1}, "position": [0]})"),
                "bodies[0].position: expected [x, y]"},
        BadFile{"BadSolver", R"({"settings": {"solver": "magic"}, "bodies": []})",
                "settings.solver: unknown value \"magic\" (expected one of: per_iteration, "
                "accumulated, soft_step)"},
        BadFile{"RetiredSolverName", R"({"settings": {"solver": "iter"}, "bodies": []})",
                "settings.solver: \"iter\" is no longer a solver's name: write \"per_iteration\""},
        BadFile{"BadTimeStep", R"({"settings": {"time_step": 0}, "bodies": []})",
                "settings.time_step: must be in 1e-05..0.1 (s;"},
        BadFile{"UnknownEventBody",
                R"({"bodies": [], "events": [{"step": 1, "type": "remove", "body": "ghost"}]})",
                "events[0].body: no body is named \"ghost\""},
        BadFile{"NegativeStep",
                R"({"bodies": [], "events": [{"step": -1, "type": "button", "button": "jump"}]})",
                "events[0].step: must be in 0..100000000, got -1"},
        BadFile{"BadFrames", R"({"bodies": [], "run": {"frames": "9:3"}})", "run.frames: "},
        BadFile{"BadOverlay", R"({"bodies": [], "overlays": ["sparkles"]})",
                "overlays[0]: unknown overlay 'sparkles'"},
        BadFile{"BadCamera", R"({"bodies": [], "camera": {"bounds": [[1, 1], [0, 0]]}})",
                "camera.bounds: the second corner must be above and right of the first"},
        BadFile{"FollowUnknownBody",
                R"({"bodies": [], "camera": {"follow": "hero", "pixels_per_metre": 40}})",
                "camera.follow: no body is named \"hero\""},
        BadFile{"FollowAndBounds",
                R"({"bodies": [], "camera": {"follow": 0, "pixels_per_metre": 40,
                                             "bounds": [[0, 0], [1, 1]]}})",
                "camera: give one of \"bounds\""},
        BadFile{"ShapeAndShapes",
                scene_with_body(R"({"position": [0, 0], "shape": {"type": "circle", "radius": 1},
                                    "shapes": [{"type": "circle", "radius": 1}]})"),
                "bodies[0]: give a body either \"shape\""},
        BadFile{"EmptyShapes", scene_with_body(R"({"position": [0, 0], "shapes": []})"),
                "bodies[0].shapes"},
        BadFile{"CompoundChain",
                scene_with_body(R"({"type": "static", "position": [0, 0], "shapes": [
                    {"type": "circle", "radius": 1},
                    {"type": "chain", "points": [[0, 0], [1, 0]]}]})"),
                "bodies[0].shapes[1].type: a chain cannot be one of a body's shapes"},
        BadFile{"CompoundBadRadius",
                scene_with_body(R"({"position": [0, 0], "shapes": [
                    {"type": "circle", "radius": 1}, {"type": "circle", "radius": -1}]})"),
                "bodies[0].shapes[1].radius"},
        BadFile{"CompoundOnlySegments",
                scene_with_body(R"({"position": [0, 0], "shapes": [
                    {"type": "segment", "point1": [0, 0], "point2": [1, 0]}]})"),
                "bodies[0].shapes: a dynamic body needs a shape with area"},
        BadFile{"CompoundWeightlessShape",
                scene_with_body(R"({"position": [0, 0], "shapes": [
                    {"type": "circle", "radius": 1},
                    {"type": "circle", "radius": 1, "position": [2, 0], "material": "Static"}]})"),
                "bodies[0].shapes[1].material: a dynamic body's shapes need density > 0"},
        BadFile{"CompoundUnknownField",
                scene_with_body(R"({"position": [0, 0], "shapes": [
                    {"type": "circle", "radius": 1, "offset": [1, 0]}]})"),
                "bodies[0].shapes[0]: unknown field \"offset\""}),
    [](const auto& test) { return std::string(test.param.name); });

TEST(SceneFile, CompoundBodiesOfTheManualLand) {
  // The manual's example (docs/scene_files.md#shapes) on a floor: the hammer's centre of mass
  // lies towards its metal head, the ledge is one static body of two shapes, and the keel on
  // layer 2 passes through the floor while the rest of its body lands.
  const Scene scene = parse_scene(R"({"bodies": [
    {"name": "hammer", "position": [0, 3],
     "shapes": [{"type": "oriented_box", "half_extents": [0.06, 0.55], "material": "Wood"},
                {"type": "oriented_box", "half_extents": [0.3, 0.12], "position": [0, 0.6], "material": "Metal"}]},
    {"name": "ledge", "type": "static", "position": [4, 0],
     "shapes": [{"type": "oriented_box", "half_extents": [2, 0.1]},
                {"type": "oriented_box", "half_extents": [0.1, 1], "position": [1.9, 1]}]},
    {"name": "ghost_keel", "position": [-4, 2],
     "shapes": [{"type": "oriented_box", "half_extents": [0.5, 0.25], "position": [0, 0.25]},
                {"type": "capsule", "center1": [-0.4, 0], "center2": [0.4, 0], "radius": 0.1, "position": [0, -0.2], "layers": 2}]},
    {"type": "static", "shape": {"type": "box", "half_extents": [20, 0.5]}, "position": [0, -0.5], "material": "Static"}
  ]})", "compound.json");
  EXPECT_TRUE(scene.model.polygons);
  EXPECT_TRUE(scene.model.capsules);
  SceneRun run(scene, Params{});
  const std::vector<BodyId> ids = run.world().body_ids();
  ASSERT_EQ(ids.size(), 4u);
  const BodyView hammer = run.world().body(ids[0]);
  // Handle 0.12 x 1.1 of wood (0.3), head 0.6 x 0.24 of metal (1.2) at 0.6: the centre of mass
  // at 0.6 m_head / (m_handle + m_head) above the handle's centre.
  const float handle = 0.3f * 0.12f * 1.1f;
  const float head = 1.2f * 0.6f * 0.24f;
  EXPECT_NEAR(hammer.transform.position.y, 3.0f + 0.6f * head / (handle + head), 1e-5f);
  EXPECT_EQ(hammer.shape_count, 2);
  EXPECT_EQ(run.world().body(ids[1]).shape_count, 2);
  for (int i = 0; i < 180; ++i) run.step();
  // The keel's box rests on the floor (its bottom at y = 0); its capsule hangs through it.
  const BodyView keel = run.world().body(ids[2]);
  EXPECT_NEAR(keel.aabb.lower.y, -0.3f, 0.02f);
  EXPECT_GT(keel.transform.position.y, 0.0f);
}

TEST(SceneFile, ButtonsTheSceneDoesNotHaveAreRejectedBeforeTheRun) {
  const Scene scene =
      parse_scene(R"({"bodies": [], "events": [{"step": 3, "type": "button", "button": "jump"}]})",
                  "buttons.json");
  try {
    SceneRun run(scene, Params{});
    FAIL() << "expected UsageError";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("buttons.json: events[0]: scene buttons has no button 'jump'"),
              std::string::npos)
        << error.what();
  }
}

// The centre of the space the HUD band (top) and the legend band (bottom) leave free.
TEST(SceneFile, AFollowingCameraKeepsTheNamedBodyInTheMiddleBetweenTheBands) {
  const Scene scene = parse_scene(
      R"({"bodies": [{"type": "static", "shape": {"type": "box", "half_extents": [5, 0.5]},
                      "position": [0, -1], "material": "Static"},
                     {"name": "ball", "shape": {"type": "circle", "radius": 0.25},
                      "position": [2, 8], "velocity": [3, 0]}],
          "camera": {"follow": "ball", "pixels_per_metre": 20}})",
      "follow.json");
  ASSERT_EQ(scene.view.camera.mode, CameraSpec::Mode::Follow);
  EXPECT_EQ(scene.view.camera.follow_body, 1);
  SceneRun run(scene, Params(scene.params));
  const render::Camera camera = scene_camera(scene.view.camera, run.world(), 200, 100);
  for (int i = 0; i < 30; ++i) run.step();
  const vec2 ball = run.world().body(run.world().body_ids()[1]).transform.position;
  ASSERT_TRUE(run.followed_position().has_value());
  EXPECT_EQ(*run.followed_position(), ball);
  const render::Camera followed = frame_camera(camera, run);
  const vec2 pixel = followed.world_to_pixel(ball);
  const render::PanelBands bands = render::panel_bands(render::frame_scale(200, 100));
  EXPECT_GT(bands.top, 0.0f);
  EXPECT_NEAR(pixel.x, 100.0f, 1e-3f);
  EXPECT_NEAR(pixel.y, bands.top + (100.0f - bands.top - bands.bottom) / 2.0f, 1e-3f);
  EXPECT_FLOAT_EQ(followed.pixels_per_metre(), 20.0f);
}

namespace {
// A floor (top at y = 0), a one-way shelf whose top is at y = 2.3, and a character on the floor.
std::string character_scene(const std::string& events) {
  // The character controller's solver (its scenes pick the accumulated one; see
  // demos/scenes/character.json).
  return R"({"settings": {"solver": "accumulated"}, "bodies": [
      {"type": "static", "shape": {"type": "box", "half_extents": [12, 0.5]},
       "position": [0, -0.5], "material": "Static"},
      {"type": "static", "shape": {"type": "box", "half_extents": [1.5, 0.1]},
       "position": [0, 2.2], "material": "Static", "one_way": true}],
    "character": {"position": [0, 0.5], "jump_height": 1.2},
    "camera": {"follow": "character", "pixels_per_metre": 40},
    "events": [)" + events + "]}";
}
}  // namespace

TEST(SceneFile, ACharacterJumpsFromButtonEventsToItsJumpHeight) {
  // A tap: jump pressed before step 10, released before step 11, so the first step of the
  // flight is held (gravity scale 1/2) and the rest falls at g. The continuous apex of that
  // schedule is Y = v0 dt - (g/2) dt^2 / 2 + v1^2 / (2 g) with v1 = v0 - (g/2) dt and
  // v0 = sqrt(2 g h); semi-implicit Euler's discrete apex lies in
  // [Y - v0 dt / 2, Y - v0 dt / 2 + g dt^2 / 8] (see tests/test_character_jump.cpp), give or
  // take 1e-4 m of float rounding in the summed positions.
  const Scene scene = parse_scene(
      character_scene(R"({"step": 10, "type": "button", "button": "jump"},
                         {"step": 11, "type": "button", "button": "jump", "pressed": false})"),
      "character.json");
  EXPECT_EQ(scene.view.camera.follow_body, -1);
  SceneRun run(scene, Params(scene.params));
  for (int i = 0; i < 10; ++i) run.step();
  ASSERT_TRUE(run.followed_position().has_value());
  const double take_off = run.followed_position()->y;
  double apex = take_off;
  for (int i = 0; i < 90; ++i) {
    run.step();
    apex = std::max(apex, static_cast<double>(run.followed_position()->y));
  }
  const double g = 9.81, h = 1.2, dt = run.world().settings().time_step;
  const double v0 = std::sqrt(2 * g * h), v1 = v0 - g / 2 * dt;
  const double continuous = v0 * dt - g / 2 * dt * dt / 2 + v1 * v1 / (2 * g);
  EXPECT_GE(apex - take_off, continuous - v0 * dt / 2 - 1e-4);
  EXPECT_LE(apex - take_off, continuous - v0 * dt / 2 + g * dt * dt / 8 + 1e-4);
}

TEST(SceneFile, ACharacterPassesUpThroughAOneWayBodyLandsOnItAndDropsThrough) {
  const Scene scene = parse_scene(
      character_scene(R"({"step": 10, "type": "button", "button": "jump"},
                         {"step": 60, "type": "button", "button": "jump", "pressed": false},
                         {"step": 120, "type": "button", "button": "down"},
                         {"step": 120, "type": "button", "button": "jump"},
                         {"step": 122, "type": "button", "button": "down", "pressed": false},
                         {"step": 122, "type": "button", "button": "jump", "pressed": false})"),
      "character.json");
  SceneRun run(scene, Params(scene.params));
  while (run.step_count() < 115) run.step();
  const float slop = run.world().settings().slop;
  EXPECT_NEAR(run.followed_position()->y, 2.3f + 0.5f, slop) << "standing on the shelf";
  while (run.step_count() < 220) run.step();
  EXPECT_NEAR(run.followed_position()->y, 0.5f, slop) << "dropped back to the floor";
}

TEST(SceneFile, ACharacterNeedsBoxesInADeclaredModel) {
  EXPECT_NE(load_error(R"({"bodies": [], "model": {"shapes": ["circle"]},
                          "character": {"position": [0, 1]}})")
                .find("bad.json: character: the character is a box"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"bodies": [], "character": {"position": [0, 1], "jump_height": -1}})")
                .find("bad.json: character.jump_height: must be > 0"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"bodies": [], "character": {"position": [0, 1], "wings": true}})")
                .find("character"),
            std::string::npos);
}

TEST(SceneFile, EveryExampleSceneFileLoadsAndRunsItsWholeLength) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(IMPULSE2D_SCENES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    const Scene scene = load_scene_file(entry.path().string());
    SceneRun run(scene, Params(scene.params));
    while (run.step_count() < scene.view.steps) run.step();
    EXPECT_TRUE(run.world().diverged_bodies().empty()) << entry.path();
  }
  EXPECT_GE(files, 3);  // projectile, seesaw_events, character
}

TEST(SceneFile, TheSoftStepSolverAndItsSettingsCanBeChosen) {
  const Scene scene = parse_scene(
      R"({"settings": {"solver": "soft_step", "substeps": 4, "contact_hertz": 45,
                       "contact_damping_ratio": 5, "contact_push_max_speed": 2},
          "bodies": []})",
      "soft.json");
  EXPECT_EQ(scene.settings.solver, SolverMethod::SoftStep);
  EXPECT_EQ(scene.settings.substeps, 4);
  EXPECT_FLOAT_EQ(scene.settings.contact_hertz, 45.0f);
  EXPECT_FLOAT_EQ(scene.settings.contact_damping_ratio, 5.0f);
  EXPECT_FLOAT_EQ(scene.settings.contact_push_max_speed, 2.0f);
  EXPECT_NE(load_error(R"({"settings": {"contact_hertz": 0}, "bodies": []})")
                .find("bad.json: settings.contact_hertz: must be > 0"),
            std::string::npos);
}

TEST(SceneFile, AnUnreadableFileIsNamed) {
  try {
    load_scene_file("/nonexistent/scene.json");
    FAIL() << "expected UsageError";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/scene.json: cannot open"),
              std::string::npos);
  }
}
