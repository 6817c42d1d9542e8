/// @file lab_scenario.cpp
#include "lab/lab_scenario.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "scene/json_cursor.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#include "scene/usage_error.h"
#include "scene/user_file.h"

namespace impulse2d::lab {
namespace {

/// How many bodies the scene body `body` creates: one, or one per link of a chain shape (the
/// scene loader validates the chain; here only its count matters).
int created_bodies(const nlohmann::json& body) {
  if (!body.is_object() || !body.contains("shape")) return 1;
  const nlohmann::json& shape = body["shape"];
  if (!shape.is_object() || shape.value("type", nlohmann::json()) != "chain") return 1;
  const nlohmann::json points = shape.value("points", nlohmann::json::array());
  const bool loop = shape.value("loop", nlohmann::json(false)) == true;
  if (!points.is_array() || points.empty()) return 1;
  return static_cast<int>(points.size()) - (loop ? 0 : 1);
}

/// Creation index of the scene body called `name` (a chain's links each count one body; a
/// chain is named by its first link).
int body_index(const demos::JsonCursor& reference, const nlohmann::json& scene_bodies) {
  const std::string name = reference.string();
  int index = 0;
  for (std::size_t i = 0; i < scene_bodies.size(); ++i) {
    const nlohmann::json& body = scene_bodies[i];
    if (body.is_object() && body.contains("name") && body["name"] == name) return index;
    index += created_bodies(body);
  }
  reference.fail("no body named \"" + name + "\" in scene.bodies");
}

/// Index in the scene's `joints` of the joint called `name`, which must be of one of `types`
/// (scene file spelling; empty: any).
int joint_index(const demos::JsonCursor& reference, const nlohmann::json& scene_joints,
                const std::vector<std::string>& types) {
  const std::string name = reference.string();
  for (std::size_t i = 0; i < scene_joints.size(); ++i) {
    const nlohmann::json& joint = scene_joints[i];
    if (!joint.is_object() || !joint.contains("name") || joint["name"] != name) continue;
    const std::string type = joint.value("type", std::string());
    if (!types.empty() && std::find(types.begin(), types.end(), type) == types.end()) {
      std::string allowed;
      for (const std::string& t : types) allowed += (allowed.empty() ? "" : " or ") + t;
      reference.fail("joint \"" + name + "\" is a " + type + " joint; the metric needs a " + allowed +
                     " joint");
    }
    return static_cast<int>(i);
  }
  reference.fail("no joint named \"" + name + "\" in scene.joints");
}

MetricSpec read_metric(const demos::JsonCursor& node, const nlohmann::json& scene_bodies,
                       const nlohmann::json& scene_joints) {
  node.allow_only({"kind", "body", "bodies", "surface", "rolls", "ground", "apexes",
                   "rest_height", "joint", "joints", "after", "measure", "unit", "threshold",
                   "meaning"});
  MetricSpec spec;
  spec.kind = node.field("kind").choice<MetricKind>({{"free_flight", MetricKind::FreeFlight},
                                                     {"slope_motion", MetricKind::SlopeMotion},
                                                     {"bounce_apexes", MetricKind::BounceApexes},
                                                     {"collision_1d", MetricKind::Collision1d},
                                                     {"cradle", MetricKind::Cradle},
                                                     {"energy", MetricKind::Energy},
                                                     {"rest", MetricKind::Rest},
                                                     {"tunnel", MetricKind::Tunnel},
                                                     {"peak_speed", MetricKind::PeakSpeed},
                                                     {"pendulum_period", MetricKind::PendulumPeriod},
                                                     {"spring_frequency", MetricKind::SpringFrequency},
                                                     {"joint_drift", MetricKind::JointDrift},
                                                     {"rope_slack", MetricKind::RopeSlack},
                                                     {"surface_ride", MetricKind::SurfaceRide}});
  if (auto field = node.optional_field("body")) spec.bodies.push_back(body_index(*field, scene_bodies));
  if (auto field = node.optional_field("bodies")) {
    for (std::size_t i = 0; i < field->size(); ++i)
      spec.bodies.push_back(body_index(field->element(i), scene_bodies));
  }
  if (auto field = node.optional_field("surface")) spec.surface = body_index(*field, scene_bodies);
  if (auto field = node.optional_field("rolls")) spec.rolls = field->boolean();
  if (auto field = node.optional_field("ground")) spec.bodies.push_back(body_index(*field, scene_bodies));
  if (auto field = node.optional_field("apexes"))
    spec.apex_count = static_cast<int>(field->integer(1, 100));
  if (auto field = node.optional_field("rest_height")) spec.rest_height = field->real();
  if (auto field = node.optional_field("after")) {
    if (spec.kind != MetricKind::JointDrift && spec.kind != MetricKind::SurfaceRide) {
      field->fail("only a joint_drift or surface_ride metric takes \"after\"");
    }
    spec.after = field->real();
  }
  if (auto field = node.optional_field("measure")) {
    if (spec.kind != MetricKind::SurfaceRide) field->fail("only a surface_ride metric takes \"measure\"");
    spec.measure = field->choice<RideMeasure>({{"normal_speed", RideMeasure::NormalSpeed},
                                               {"angular_speed", RideMeasure::AngularSpeed},
                                               {"acceleration", RideMeasure::Acceleration}});
  }
  std::vector<std::string> joint_types;
  if (spec.kind == MetricKind::PendulumPeriod) joint_types = {"revolute", "distance"};
  if (spec.kind == MetricKind::SpringFrequency || spec.kind == MetricKind::RopeSlack) joint_types = {"distance"};
  if (spec.kind == MetricKind::JointDrift) joint_types = {"revolute", "weld", "distance"};
  if (auto field = node.optional_field("joint")) spec.joints.push_back(joint_index(*field, scene_joints, joint_types));
  if (auto field = node.optional_field("joints")) {
    for (std::size_t i = 0; i < field->size(); ++i)
      spec.joints.push_back(joint_index(field->element(i), scene_joints, joint_types));
  }
  spec.unit = node.field("unit").string();
  spec.threshold = node.field("threshold").positive();
  spec.meaning = node.field("meaning").string();

  const auto need = [&](std::size_t count, const char* what) {
    if (spec.bodies.size() != count) node.fail(std::string("metric needs ") + what);
  };
  switch (spec.kind) {
    case MetricKind::FreeFlight: need(1, "\"body\""); break;
    case MetricKind::SlopeMotion:
      need(1, "\"body\"");
      if (spec.surface < 0) node.fail("metric needs \"surface\"");
      break;
    case MetricKind::SurfaceRide:
      need(1, "\"body\"");
      if (spec.surface < 0) node.fail("metric needs \"surface\"");
      if (!node.optional_field("measure")) {
        node.fail("metric needs \"measure\" (normal_speed, angular_speed or acceleration)");
      }
      if (spec.measure == RideMeasure::Acceleration && spec.after > 0.0) {
        node.field("after").fail("the acceleration measure is the mean over the whole run: no \"after\"");
      }
      break;
    case MetricKind::BounceApexes: need(2, "\"body\" and \"ground\""); break;
    case MetricKind::Collision1d: need(2, "\"bodies\" with two names"); break;
    case MetricKind::Cradle:
      if (spec.bodies.size() < 2) node.fail("metric needs \"bodies\": the row, at least two");
      break;
    case MetricKind::Tunnel:
      need(1, "\"body\"");
      if (spec.surface < 0) node.fail("metric needs \"surface\" (the wall)");
      break;
    case MetricKind::PendulumPeriod:
    case MetricKind::RopeSlack:
      need(1, "\"body\"");
      if (spec.joints.size() != 1) node.fail("metric needs \"joint\"");
      break;
    case MetricKind::SpringFrequency:
      need(0, "no \"body\" (the joint's body B is measured)");
      if (spec.joints.size() != 1) node.fail("metric needs \"joint\"");
      break;
    case MetricKind::JointDrift:
    case MetricKind::Energy:
    case MetricKind::Rest:
    case MetricKind::PeakSpeed: break;
  }
  return spec;
}

}  // namespace

LabScenario load_lab_scenario(const std::string& path) {
  const demos::UserFileKind scenario_file{
      "scenario file", "a plain .json file",
      static_cast<std::uintmax_t>(demos::limits::max_scene_file_bytes), "4 MiB"};
  return parse_lab_scenario(demos::read_user_file(path, scenario_file), path);
}

LabScenario parse_lab_scenario(const std::string& text, const std::string& path) {
  const nlohmann::json document = demos::parse_json_document(text, path);
  const demos::JsonCursor root(document, path);
  root.expect_object();
  root.allow_only({"description", "answer", "duration", "metric", "scene"});

  LabScenario scenario;
  scenario.source = path;
  scenario.name = std::filesystem::path(path).stem().string();
  scenario.description = root.field("description").string();
  scenario.answer = root.field("answer").string();
  scenario.duration = root.field("duration").positive();
  const demos::JsonCursor scene = root.field("scene");
  scene.expect_object();
  const nlohmann::json bodies = scene.value().value("bodies", nlohmann::json::array());
  const nlohmann::json joints = scene.value().value("joints", nlohmann::json::array());
  scenario.metric = read_metric(root.field("metric"), bodies, joints);
  // The scene loader names the file in its messages; the embedded scene is reported as
  // "<file> (scene)" so paths read "<file> (scene): bodies[2].shape...".
  scenario.scene = demos::parse_scene(scene.value().dump(), path + " (scene)");
  scenario.scene.name = scenario.name;
  scenario.scene.source = path;
  return scenario;
}

std::vector<LabScenario> load_lab_scenarios(const std::string& directory) {
  std::error_code error;
  std::vector<std::string> paths;
  for (std::filesystem::directory_iterator it(directory, error), end; !error && it != end;
       it.increment(error)) {
    if (it->path().extension() == ".json") paths.push_back(it->path().string());
  }
  if (error) throw demos::UsageError(directory + ": cannot read the scenario directory: " + error.message());
  if (paths.empty()) throw demos::UsageError(directory + ": no scenario files (*.json)");
  std::sort(paths.begin(), paths.end());
  std::vector<LabScenario> scenarios;
  for (const std::string& path : paths) scenarios.push_back(load_lab_scenario(path));
  return scenarios;
}

std::string lab_data_directory() {
  std::error_code error;
  // Installed: <prefix>/bin/impulse2d finds <prefix>/share/impulse2d/lab.
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path installed =
      error ? std::filesystem::path()
            : (program.parent_path() / IMPULSE2D_LAB_FROM_PROGRAM).lexically_normal();
  // Built: the source tree the program was built from.
  const std::filesystem::path source = IMPULSE2D_LAB_SOURCE_DIR;
  for (const std::filesystem::path& candidate : {installed, source}) {
    if (!candidate.empty() && std::filesystem::is_directory(candidate / "scenarios", error)) {
      return candidate.string();
    }
  }
  throw std::runtime_error(
      "the lab's scenarios were not found: looked in " +
      (installed.empty() ? std::string("the install prefix (/proc/self/exe is unreadable)")
                         : (installed / "scenarios").string() + " (installed beside the program)") +
      " and " + (source / "scenarios").string() +
      " (the source tree it was built from); give a directory with --scenarios DIR");
}

std::string default_scenario_directory() { return lab_data_directory() + "/scenarios"; }

}  // namespace impulse2d::lab
