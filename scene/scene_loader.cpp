/// @file scene_loader.cpp
#include "scene/scene_loader.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "core/error.h"
#include "core/material.h"
#include "core/world.h"
#include "scene/character_script.h"
#include "scene/json_cursor.h"
#include "scene/overlays.h"
#include "scene/scene_joint_reader.h"
#include "scene/scene_limits.h"
#include "scene/usage_error.h"
#include "scene/user_file.h"
#include "scene/frame_selection.h"

namespace impulse2d::demos {
namespace {

/// The core's message without the function name it starts with ("make_polygon: ...").
std::string core_reason(const Error& error) {
  const std::string message = error.what();
  const std::size_t colon = message.find(": ");
  return colon == std::string::npos ? message : message.substr(colon + 2);
}

WorldSettings read_settings(const JsonCursor& node) {
  node.allow_only({"gravity", "time_step", "substeps", "solver", "warm_starting", "block_solver",
                   "shock_propagation",
                   "position_correction", "correction_percent", "slop", "max_correction",
                   "restitution_threshold", "friction_mixing", "restitution_mixing", "integrator",
                   "broad_phase", "sleep_linear_speed", "sleep_angular_speed", "time_to_sleep",
                   "max_linear_speed", "contact_hertz", "contact_damping_ratio",
                   "contact_push_max_speed", "speculative_margin", "contact_recycle_distance",
                   "hit_event_speed"});
  // ("hit_event_speed" is the world's hit-event threshold, not a WorldSettings field: the
  // caller reads it.)
  // A named solver starts from its own sub-steps and passes (`settings_for`).
  WorldSettings settings;
  if (auto field = node.optional_field("solver")) {
    if (const std::optional<SolverMethod> meant = retired_solver_name(field->string())) {
      field->fail("\"" + field->string() + "\" is no longer a solver's name: write \"" +
                  solver_name(*meant) + "\"");
    }
    std::vector<std::pair<const char*, SolverMethod>> names;
    for (const SolverMethod method : solver_methods()) names.emplace_back(solver_name(method), method);
    settings = settings_for(field->choice<SolverMethod>(names));
  }
  if (auto field = node.optional_field("gravity")) {
    settings.gravity = field->vector_at_most(limits::max_gravity, limits::gravity_reason);
  }
  if (auto field = node.optional_field("time_step")) {
    settings.time_step = field->in_range(limits::min_time_step, limits::max_time_step,
                                         limits::time_step_reason);
  }
  if (auto field = node.optional_field("substeps"))
    settings.substeps = static_cast<int>(field->integer(1, 64));
  if (auto field = node.optional_field("contact_hertz")) settings.contact_hertz = field->positive();
  if (auto field = node.optional_field("contact_damping_ratio")) {
    settings.contact_damping_ratio = field->non_negative();
  }
  if (auto field = node.optional_field("contact_push_max_speed")) {
    settings.contact_push_max_speed = field->non_negative();
  }
  if (auto field = node.optional_field("speculative_margin")) {
    settings.speculative_margin = field->non_negative();
  }
  if (auto field = node.optional_field("contact_recycle_distance")) {
    settings.contact_recycle_distance = field->non_negative();
  }
  if (auto field = node.optional_field("warm_starting")) settings.warm_starting = field->boolean();
  if (auto field = node.optional_field("block_solver")) settings.block_solver = field->boolean();
  if (auto field = node.optional_field("shock_propagation")) {
    settings.shock_propagation = field->boolean();
  }
  if (auto field = node.optional_field("position_correction")) {
    settings.position_correction = field->choice<PositionCorrection>(
        {{"none", PositionCorrection::None},
         {"linear", PositionCorrection::LinearProjection},
         {"nonlinear_gauss_seidel", PositionCorrection::NonlinearGaussSeidel}});
  }
  if (auto field = node.optional_field("correction_percent"))
    settings.correction_percent = field->non_negative();
  if (auto field = node.optional_field("slop")) settings.slop = field->non_negative();
  if (auto field = node.optional_field("max_correction"))
    settings.max_correction = field->positive();
  if (auto field = node.optional_field("restitution_threshold")) {
    settings.restitution_threshold = field->non_negative();
  }
  if (auto field = node.optional_field("friction_mixing")) {
    settings.friction_mixing =
        field->choice<FrictionMixing>({{"root_sum_squares", FrictionMixing::RootSumSquares},
                                       {"geometric_mean", FrictionMixing::GeometricMean},
                                       {"product", FrictionMixing::Product},
                                       {"average", FrictionMixing::Average},
                                       {"min", FrictionMixing::Minimum},
                                       {"max", FrictionMixing::Maximum}});
  }
  if (auto field = node.optional_field("restitution_mixing")) {
    settings.restitution_mixing =
        field->choice<RestitutionMixing>({{"min", RestitutionMixing::Minimum},
                                          {"max", RestitutionMixing::Maximum},
                                          {"average", RestitutionMixing::Average}});
  }
  if (auto field = node.optional_field("integrator")) {
    settings.integrator =
        field->choice<Integrator>({{"semi_implicit_euler", Integrator::SemiImplicitEuler},
                                   {"explicit_euler", Integrator::ExplicitEuler}});
  }
  if (auto field = node.optional_field("broad_phase")) {
    settings.broad_phase =
        field->choice<BroadPhaseMethod>({{"dynamic_tree", BroadPhaseMethod::DynamicTree},
                                         {"sort_and_sweep", BroadPhaseMethod::SortAndSweep},
                                         {"brute_force", BroadPhaseMethod::BruteForce}});
  }
  if (auto field = node.optional_field("sleep_linear_speed"))
    settings.sleep_linear_speed = field->non_negative();
  if (auto field = node.optional_field("sleep_angular_speed"))
    settings.sleep_angular_speed = field->non_negative();
  if (auto field = node.optional_field("time_to_sleep"))
    settings.time_to_sleep = field->non_negative();
  if (auto field = node.optional_field("max_linear_speed")) {
    settings.max_linear_speed = field->in_range(1e-3f, limits::max_speed, limits::speed_reason);
  }
  try {
    validate_settings(settings);
  } catch (const Error& error) {
    // "WorldSettings.correction_percent: must be in [0, 1]": reported at that field.
    const std::string message = error.what();
    const std::string prefix = "WorldSettings.";
    const std::size_t colon = message.find(": ");
    if (message.rfind(prefix, 0) == 0 && colon != std::string::npos) {
      const std::string field = message.substr(prefix.size(), colon - prefix.size());
      if (node.has(field)) {
        node.field(field).fail(message.substr(colon + 2) + ", got " + node.field(field).value().dump());
      }
      node.fail(message.substr(prefix.size()));  // a field the solver's defaults set
    }
    node.fail(core_reason(error));
  }
  return settings;
}

// The model block; iterations it does not name are the settings' (the solver's own).
SceneModel read_model(const JsonCursor& node, const WorldSettings& settings) {
  node.allow_only({"shapes", "rotation", "friction", "restitution", "ccd", "sleeping",
                   "velocity_iterations", "position_iterations"});
  SceneModel model;
  model.velocity_iterations = settings.velocity_iterations;
  model.position_iterations = settings.position_iterations;
  const JsonCursor shapes = node.field("shapes");
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const JsonCursor kind = shapes.element(i);
    switch (kind.choice<ShapeType>({{"circle", ShapeType::Circle},
                                    {"box", ShapeType::Box},
                                    {"polygon", ShapeType::Polygon},
                                    {"capsule", ShapeType::Capsule},
                                    {"segment", ShapeType::Segment},
                                    {"chain", ShapeType::Segment}})) {
      case ShapeType::Circle:
        model.circles = true;
        break;
      case ShapeType::Box:
        model.boxes = true;
        break;
      case ShapeType::Polygon:
        model.polygons = true;
        break;
      case ShapeType::Capsule:
        model.capsules = true;
        break;
      case ShapeType::Segment:
        model.segments = true;
        break;
    }
  }
  if (auto field = node.optional_field("rotation")) model.rotation = field->boolean();
  if (auto field = node.optional_field("friction")) model.friction = field->boolean();
  if (auto field = node.optional_field("restitution")) model.restitution = field->boolean();
  if (auto field = node.optional_field("ccd")) model.ccd = field->boolean();
  if (auto field = node.optional_field("sleeping")) model.sleeping = field->boolean();
  if (auto field = node.optional_field("velocity_iterations")) {
    model.velocity_iterations = static_cast<int>(field->integer(0, 1000));
  }
  if (auto field = node.optional_field("position_iterations")) {
    model.position_iterations = static_cast<int>(field->integer(0, 1000));
  }
  return model;
}

Material read_material_object(const JsonCursor& node, const std::string& name) {
  node.allow_only({"density", "restitution", "static_friction", "dynamic_friction"});
  Material material;
  material.name = name;
  const JsonCursor density = node.field("density");
  material.density = density.non_negative();
  if (material.density != 0.0f) {
    material.density =
        density.in_range(limits::min_density, limits::max_density, limits::density_reason);
  }
  material.restitution = node.field("restitution").non_negative();
  material.static_friction = node.field("static_friction").non_negative();
  material.dynamic_friction = node.field("dynamic_friction").non_negative();
  if (material.static_friction < material.dynamic_friction) {
    node.field("static_friction")
        .fail("must be >= dynamic_friction (" + node.field("dynamic_friction").value().dump() +
              ")");
  }
  return material;
}

using MaterialTable = std::map<std::string, Material>;

Material read_body_material(const JsonCursor& node, const MaterialTable& table) {
  if (node.value().is_object()) return read_material_object(node, "custom");
  const std::string name = node.string();
  const auto found = table.find(name);
  if (found == table.end()) {
    std::string known;
    for (const auto& [each, material] : table) known += (known.empty() ? "" : ", ") + each;
    node.fail("unknown material \"" + name + "\" (known: " + known + ")");
  }
  return found->second;
}

/// True for a name usable as the prefix of output files: [A-Za-z0-9_.-], not starting with
/// '.', 1..64 characters (so never "." or "..").
bool is_file_name_prefix(const std::string& name) {
  if (name.empty() || name.size() > 64 || name.front() == '.') return false;
  for (const char c : name) {
    const bool allowed = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                         (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    if (!allowed) return false;
  }
  return true;
}

/// The shape, and the offset from the body's given position to its centre of mass (non-zero
/// for polygons whose vertices are not centred on the origin, and for capsules and segments
/// not centred on it), body-local.
struct ReadShape {
  Shape shape;
  vec2 centroid{0.0f, 0.0f};
  std::vector<ChainLink> chain;  ///< a chain's links (then `shape` is the first link's)
};

/// A "chain" shape object's links: "points" (at least 2, 3 for a loop) and "loop".
std::vector<ChainLink> read_chain(const JsonCursor& node) {
  node.allow_only({"type", "points", "loop"});
  const bool loop = node.has("loop") && node.field("loop").boolean();
  const JsonCursor list = node.field("points");
  const std::size_t count = list.size();
  const std::size_t least = loop ? 3 : 2;
  if (count < least || count > limits::max_chain_points) {
    list.fail(std::string(loop ? "a loop" : "an open chain") + " needs " + std::to_string(least) +
              ".." + std::to_string(limits::max_chain_points) + " points, got " +
              std::to_string(count));
  }
  std::vector<vec2> points;
  for (std::size_t i = 0; i < count; ++i) {
    points.push_back(list.element(i).vector_at_most(limits::max_coordinate, limits::coordinate_reason));
    if (i > 0 && !(glm::length(points[i] - points[i - 1]) >= limits::min_size)) {
      list.element(i).fail("must be at least " + compact_number(limits::min_size) +
                           " m from the point before it (consecutive chain points must differ)");
    }
  }
  if (loop && !(glm::length(points.front() - points.back()) >= limits::min_size)) {
    list.element(count - 1).fail("repeats the first point: a loop closes itself, leave it out");
  }
  try {
    return make_chain(points.data(), static_cast<int>(count), loop);
  } catch (const Error& error) {
    list.fail(core_reason(error));
  }
}

/// The fields a shape object may have besides `own` (its kind's): a shape in a body's "shapes"
/// list also has its placement, material, layers and sensor switch.
std::vector<const char*> shape_fields(std::vector<const char*> own, bool placed) {
  if (placed) own.insert(own.end(), {"position", "angle", "material", "layers", "sensor"});
  return own;
}

/// A shape object: `placed` for one of a body's "shapes" (which may also give "position",
/// "angle", "material", "layers" and "sensor", read by `read_placed_shapes`).
ReadShape read_shape(const JsonCursor& node, bool placed = false) {
  const JsonCursor type = node.field("type");
  const std::string name = type.string();
  ReadShape result;
  if (name == "circle") {
    node.allow_only(shape_fields({"type", "radius"}, placed));
    result.shape = make_circle(
        node.field("radius").in_range(limits::min_size, limits::max_size, limits::size_reason));
  } else if (name == "box" || name == "oriented_box") {
    node.allow_only(shape_fields({"type", "half_extents"}, placed));
    const JsonCursor extents = node.field("half_extents");
    if (extents.size() != 2) extents.fail("expected [half width, half height]");
    const vec2 half(
        extents.element(0).in_range(limits::min_size, limits::max_size, limits::size_reason),
        extents.element(1).in_range(limits::min_size, limits::max_size, limits::size_reason));
    result.shape = name == "box" ? make_box(half) : make_oriented_box(half);
  } else if (name == "capsule") {
    node.allow_only(shape_fields({"type", "center1", "center2", "radius"}, placed));
    const JsonCursor first = node.field("center1");
    const JsonCursor second = node.field("center2");
    const vec2 center1 = first.vector_at_most(limits::max_size, limits::size_reason);
    const vec2 center2 = second.vector_at_most(limits::max_size, limits::size_reason);
    const float radius =
        node.field("radius").in_range(limits::min_size, limits::max_size, limits::size_reason);
    if (!(glm::length(center2 - center1) >= limits::min_size)) {
      second.fail("center2 must be at least " + compact_number(limits::min_size) +
                  " m from center1 (equal centres: use a circle)");
    }
    result.shape = make_capsule(center1, center2, radius, &result.centroid);
  } else if (name == "segment") {
    node.allow_only(shape_fields({"type", "point1", "point2"}, placed));
    const JsonCursor first = node.field("point1");
    const JsonCursor second = node.field("point2");
    const vec2 point1 = first.vector_at_most(limits::max_size, limits::size_reason);
    const vec2 point2 = second.vector_at_most(limits::max_size, limits::size_reason);
    if (!(glm::length(point2 - point1) >= limits::min_size)) {
      second.fail("point2 must be at least " + compact_number(limits::min_size) +
                  " m from point1 (a segment needs a length)");
    }
    result.shape = make_segment(point1, point2, &result.centroid);
  } else if (name == "chain") {
    if (placed) type.fail("a chain cannot be one of a body's shapes (give it its own body)");
    result.chain = read_chain(node);
    result.shape = result.chain.front().shape;
  } else if (name == "polygon") {
    node.allow_only(shape_fields({"type", "vertices", "radius"}, placed));
    const JsonCursor list = node.field("vertices");
    const std::size_t count = list.size();
    if (count < 3 || count > static_cast<std::size_t>(max_polygon_vertices)) {
      list.fail("a polygon needs 3.." + std::to_string(max_polygon_vertices) + " vertices, got " +
                std::to_string(count));
    }
    std::vector<vec2> vertices;
    vec2 lower(limits::max_size), upper(-limits::max_size);
    for (std::size_t i = 0; i < count; ++i) {
      vertices.push_back(list.element(i).vector_at_most(limits::max_size, limits::size_reason));
      lower = glm::min(lower, vertices.back());
      upper = glm::max(upper, vertices.back());
    }
    if (!(upper.x - lower.x >= limits::min_size && upper.y - lower.y >= limits::min_size)) {
      list.fail("the polygon must be at least " + compact_number(limits::min_size) +
                " m wide and high (" + limits::size_reason + ")");
    }
    float rounding = 0.0f;
    if (auto field = node.optional_field("radius")) {
      rounding = field->non_negative();
      if (rounding != 0.0f) rounding = field->in_range(limits::min_size, limits::max_size, limits::size_reason);
    }
    try {
      result.shape = make_rounded_polygon(vertices.data(), static_cast<int>(count), rounding,
                                          &result.centroid);
    } catch (const Error& error) {
      list.fail(core_reason(error));
    }
  } else {
    type.fail("unknown shape type \"" + name +
              "\" (expected one of: circle, box, oriented_box, polygon, capsule, segment, chain)");
  }
  return result;
}

/// A compound body's "shapes": 1..max_body_shapes shape objects, each with an optional
/// "position" and "angle" (of its frame in the body's; a polygon's or capsule's own centroid
/// offset is kept), "material" and "layers" (the body's by default) and "sensor" (false).
std::vector<ShapeDef> read_placed_shapes(const JsonCursor& list, const BodyDef& def,
                                         const MaterialTable& table) {
  const std::size_t count = list.size();
  if (count < 1 || count > static_cast<std::size_t>(max_body_shapes)) {
    list.fail("a body takes 1.." + std::to_string(max_body_shapes) + " shapes, got " + std::to_string(count));
  }
  std::vector<ShapeDef> shapes;
  bool has_area = false;
  for (std::size_t i = 0; i < count; ++i) {
    const JsonCursor node = list.element(i);
    const ReadShape read = read_shape(node, true);
    ShapeDef placed;
    placed.shape = read.shape;
    if (auto field = node.optional_field("angle")) placed.angle = field->magnitude_at_most(1e4f, "rad");
    vec2 position(0.0f);
    if (auto field = node.optional_field("position")) {
      position = field->vector_at_most(limits::max_size, limits::size_reason);
    }
    placed.position = position + Rotation::from_angle(placed.angle).rotate(read.centroid);
    placed.material = def.material;
    if (auto field = node.optional_field("material")) placed.material = read_body_material(*field, table);
    placed.collision_layers = def.collision_layers;
    if (auto field = node.optional_field("layers")) {
      placed.collision_layers = static_cast<std::uint32_t>(field->integer(0, 0xFFFFFFFFll));
    }
    if (auto field = node.optional_field("sensor")) placed.is_sensor = field->boolean();
    const bool area = read.shape.type() != ShapeType::Segment;
    if (def.type == BodyType::Dynamic && area && !(placed.material.density > 0.0f)) {
      (node.has("material") ? node.field("material") : node)
          .fail("a dynamic body's shapes need density > 0 (material " + placed.material.name +
                " has density 0); make the body \"static\" or pick another material");
    }
    has_area = has_area || area;
    shapes.push_back(placed);
  }
  if (def.type == BodyType::Dynamic && !has_area) {
    list.fail("a dynamic body needs a shape with area (all its shapes are segments: give the body "
              "\"type\": \"static\" or \"kinematic\", or add a capsule or polygon)");
  }
  return shapes;
}

/// A body object; a chain's links go to `chain` (one static body each, at their midpoints
/// placed by the body's position and angle), or fail where `chain` is null (spawned bodies).
BodySpawn read_body(const JsonCursor& node, const MaterialTable& table,
                    std::vector<ChainLink>* chain = nullptr) {
  node.allow_only({"name", "type", "shape", "shapes", "position", "angle", "velocity", "angular_velocity",
                   "gravity_scale", "linear_damping", "angular_damping", "fixed_rotation", "bullet",
                   "layers", "material", "one_way", "sensor", "sensor_detects_static", "events"});
  BodySpawn body;
  BodyDef& def = body.def;
  if (auto field = node.optional_field("type")) {
    def.type = field->choice<BodyType>({{"dynamic", BodyType::Dynamic},
                                        {"static", BodyType::Static},
                                        {"kinematic", BodyType::Kinematic}});
  }
  if (node.has("shape") == node.has("shapes")) {
    node.fail("give a body either \"shape\" (one shape) or \"shapes\" (a list: a compound body)");
  }
  // A compound body's first shape stands for it in the checks below (its kinds are all
  // read with `read_placed_shapes` once the body's material and layers are known).
  const ReadShape shape = node.has("shape") ? read_shape(node.field("shape"))
                                            : read_shape(node.field("shapes").element(0), true);
  body.shape = shape.shape.type() == ShapeType::Box && node.has("shapes")
                   ? make_oriented_box(shape.shape.box().half_extents)
                   : shape.shape;
  if (!shape.chain.empty()) {
    if (chain == nullptr) {
      node.field("shape").field("type").fail(
          "a spawned body cannot be a chain (put the chain in \"bodies\")");
    }
    if (def.type != BodyType::Static) {
      node.field("shape").field("type").fail(
          "a chain is level geometry: its body must be \"type\": \"static\"");
    }
    *chain = shape.chain;
  }
  if (def.type == BodyType::Dynamic && body.shape.type() == ShapeType::Segment && node.has("shape")) {
    node.field("shape").field("type").fail(
        "a segment has no area and so no mass: a dynamic body cannot be only a segment (give "
        "the body \"type\": \"static\" or \"kinematic\", or use a capsule)");
  }
  const vec2 origin =
      node.field("position").vector_at_most(limits::max_coordinate, limits::coordinate_reason);
  if (auto field = node.optional_field("angle")) {
    def.angle = field->magnitude_at_most(1e4f, "rad");
    if (def.angle != 0.0f && body.shape.type() == ShapeType::Box) {
      field->fail("a \"box\" is axis-aligned and never rotates, so its angle would be lost; "
                  "use \"type\": \"oriented_box\" for a rotated box");
    }
  }
  // A compound body's origin is the given position: its shapes are placed about it.
  def.position = node.has("shapes") ? origin : origin + Rotation::from_angle(def.angle).rotate(shape.centroid);
  if (auto field = node.optional_field("velocity")) {
    def.linear_velocity = field->vector_at_most(limits::max_speed, limits::speed_reason);
  }
  if (auto field = node.optional_field("angular_velocity")) {
    def.angular_velocity = field->magnitude_at_most(limits::max_speed, limits::speed_reason);
    if (def.angular_velocity != 0.0f && body.shape.type() == ShapeType::Box) {
      field->fail("a \"box\" is axis-aligned and never rotates, so its spin would be lost; "
                  "use \"type\": \"oriented_box\" for a spinning box");
    }
  }
  if (auto field = node.optional_field("gravity_scale")) {
    def.gravity_scale = field->magnitude_at_most(limits::max_gravity_scale, "times gravity");
  }
  if (auto field = node.optional_field("linear_damping"))
    def.linear_damping = field->in_range(0.0f, limits::max_damping, "1/s");
  if (auto field = node.optional_field("angular_damping"))
    def.angular_damping = field->in_range(0.0f, limits::max_damping, "1/s");
  if (auto field = node.optional_field("fixed_rotation")) def.fixed_rotation = field->boolean();
  if (auto field = node.optional_field("bullet")) def.is_bullet = field->boolean();
  if (auto field = node.optional_field("one_way")) {
    if (field->boolean()) def.user_data = one_way_platform_tag;
  }
  if (auto field = node.optional_field("layers")) {
    def.collision_layers = static_cast<std::uint32_t>(field->integer(0, 0xFFFFFFFFll));
  }
  if (auto field = node.optional_field("sensor")) def.is_sensor = field->boolean();
  if (auto field = node.optional_field("sensor_detects_static")) {
    bool sensor_shape = false;  // a compound body's shape with "sensor": true
    if (auto list = node.optional_field("shapes")) {
      for (std::size_t i = 0; i < list->size(); ++i) {
        const JsonCursor each = list->element(i);
        sensor_shape = sensor_shape || (each.has("sensor") && each.field("sensor").boolean());
      }
    }
    if (!def.is_sensor && !sensor_shape) {
      field->fail("only a sensor detects bodies: add \"sensor\": true (to the body or one of its shapes)");
    }
    def.sensor_detects_static = field->boolean();
  }
  if (auto events = node.optional_field("events")) {
    events->expect_object();
    events->allow_only({"contact", "hit", "sensor"});
    if (auto field = events->optional_field("contact")) def.enable_contact_events = field->boolean();
    if (auto field = events->optional_field("hit")) def.enable_hit_events = field->boolean();
    if (auto field = events->optional_field("sensor")) def.enable_sensor_events = field->boolean();
  }
  def.material = table.at("Wood");
  if (auto field = node.optional_field("material"))
    def.material = read_body_material(*field, table);
  if (auto list = node.optional_field("shapes")) {
    body.shapes = read_placed_shapes(*list, def, table);
    return body;
  }
  if (def.type == BodyType::Dynamic && !(def.material.density > 0.0f)) {
    node.field("material")
        .fail("a dynamic body needs density > 0 (material " + def.material.name +
              " has density 0); make the body \"static\" or pick another material");
  }
  return body;
}

/// Body name -> creation index: the file's bodies, then spawned ones in step order.
using BodyNames = std::map<std::string, int>;

/// A body's "name": a non-empty string.
std::string read_body_name(const JsonCursor& node) {
  const std::string name = node.string();
  if (name.empty()) node.fail("a body name must not be empty (leave \"name\" out for an unnamed body)");
  return name;
}

int read_body_reference(const JsonCursor& node, const BodyNames& names) {
  if (node.value().is_string()) {
    const std::string name = read_body_name(node);
    const auto found = names.find(name);
    if (found == names.end()) node.fail("no body is named \"" + name + "\" (at this point)");
    return found->second;
  }
  return static_cast<int>(node.integer(0, 1000000));
}

CameraSpec read_camera(const JsonCursor& node, const BodyNames& names) {
  node.allow_only({"bounds", "center", "pixels_per_metre", "follow", "zoom"});
  CameraSpec camera;
  if (auto zoom = node.optional_field("zoom")) camera.zoom = zoom->in_range(0.01f, 100.0f, "a zoom factor");
  const int ways = (node.has("bounds") ? 1 : 0) + (node.has("center") ? 1 : 0) +
                   (node.has("follow") ? 1 : 0);
  if (ways > 1) {
    node.fail(
        "give one of \"bounds\", \"center\" (with \"pixels_per_metre\") or \"follow\" (with "
        "\"pixels_per_metre\")");
  }
  if (auto follow = node.optional_field("follow")) {
    camera.mode = CameraSpec::Mode::Follow;
    // "character" follows the file's character (the script's body); anything else names a body.
    const bool character = follow->value().is_string() && follow->string() == "character" &&
                           names.find("character") == names.end();
    camera.follow_body = character ? -1 : read_body_reference(*follow, names);
    camera.pixels_per_metre = node.field("pixels_per_metre")
                                  .in_range(limits::min_pixels_per_metre, limits::max_pixels_per_metre,
                                            limits::pixels_per_metre_reason);
  } else if (auto bounds = node.optional_field("bounds")) {
    if (bounds->size() != 2) bounds->fail("expected [[min x, min y], [max x, max y]]");
    camera.mode = CameraSpec::Mode::FitBounds;
    camera.bounds.lower =
        bounds->element(0).vector_at_most(limits::max_coordinate, limits::coordinate_reason);
    camera.bounds.upper =
        bounds->element(1).vector_at_most(limits::max_coordinate, limits::coordinate_reason);
    if (!(camera.bounds.upper.x > camera.bounds.lower.x &&
          camera.bounds.upper.y > camera.bounds.lower.y)) {
      bounds->fail("the second corner must be above and right of the first");
    }
    const vec2 sides = camera.bounds.upper - camera.bounds.lower;
    if (!(sides.x >= limits::min_view_side && sides.y >= limits::min_view_side)) {
      bounds->fail("the rectangle is " + compact_number(sides.x) + " x " + compact_number(sides.y) +
                   " m; each side must be at least " + compact_number(limits::min_view_side) +
                   " m (the smallest body)");
    }
  } else if (auto center = node.optional_field("center")) {
    camera.mode = CameraSpec::Mode::Centered;
    camera.center = center->vector_at_most(limits::max_coordinate, limits::coordinate_reason);
    camera.pixels_per_metre = node.field("pixels_per_metre")
                                  .in_range(limits::min_pixels_per_metre, limits::max_pixels_per_metre,
                                            limits::pixels_per_metre_reason);
  }
  return camera;
}

/// The `view` object: HUD and legend switches, overlay scales, text size, highlighted body.
void read_view(const JsonCursor& node, const BodyNames& names, std::size_t created, SceneView& view) {
  node.allow_only({"hud", "legend", "arrow_scale", "penetration_scale", "text_scale", "max_arrow_pixels",
                   "highlight", "settings", "islands", "feature_ids", "timeline"});
  if (auto field = node.optional_field("hud")) view.show_hud = field->boolean();
  if (auto field = node.optional_field("legend")) view.show_legend = field->boolean();
  if (auto field = node.optional_field("arrow_scale")) {
    const float scale = field->in_range(0.001f, 1000.0f, "a factor on the impulse and velocity arrows");
    view.draw.impulse_scale *= scale;
    view.draw.velocity_scale *= scale;
  }
  if (auto field = node.optional_field("penetration_scale")) {
    view.draw.penetration_scale = field->in_range(1.0f, 1000.0f, "a magnification of overlaps");
  }
  if (auto field = node.optional_field("text_scale")) view.text_scale = static_cast<int>(field->integer(1, 16));
  if (auto field = node.optional_field("max_arrow_pixels")) {
    view.max_arrow_pixels = field->in_range(8.0f, 4096.0f, "pixels");
  }
  if (auto field = node.optional_field("highlight")) {
    view.highlight_body = read_body_reference(*field, names);
    if (static_cast<std::size_t>(view.highlight_body) >= created) {
      field->fail("body " + std::to_string(view.highlight_body) + " does not exist (the scene creates " +
                  std::to_string(created) + " bodies)");
    }
  }
  if (auto field = node.optional_field("settings")) view.show_settings = field->boolean();
  if (auto field = node.optional_field("islands")) view.show_islands = field->boolean();
  if (auto field = node.optional_field("feature_ids")) view.show_feature_ids = field->boolean();
  if (auto field = node.optional_field("timeline")) view.show_timeline = field->boolean();
}

/// The `character` object: a platformer character played from button events.
CharacterDef read_character(const JsonCursor& node) {
  node.allow_only({"position", "half_extents", "max_speed", "jump_height", "extra_jumps",
                   "coyote_time", "jump_buffer_time", "max_slope_degrees"});
  CharacterDef def;
  def.position = node.field("position").vector();
  if (auto field = node.optional_field("half_extents")) {
    def.half_extents = field->vector();
    if (!(def.half_extents.x > 0.0f && def.half_extents.y > 0.0f)) field->fail("must be > 0");
  }
  CharacterSettings& settings = def.settings;
  if (auto field = node.optional_field("max_speed")) settings.max_speed = field->positive();
  if (auto field = node.optional_field("jump_height")) settings.jump_height = field->positive();
  if (auto field = node.optional_field("extra_jumps")) {
    settings.extra_jumps = static_cast<int>(field->integer(0, 100));
  }
  if (auto field = node.optional_field("coyote_time")) settings.coyote_time = field->non_negative();
  if (auto field = node.optional_field("jump_buffer_time")) {
    settings.jump_buffer_time = field->non_negative();
  }
  if (auto field = node.optional_field("max_slope_degrees")) {
    const float degrees = field->positive();
    if (!(degrees < 90.0f)) field->fail("must be below 90");
    settings.max_slope = degrees * 3.14159265f / 180.0f;
  }
  try {
    validate_character_settings(settings);
  } catch (const Error& error) {
    node.fail(error.what());
  }
  return def;
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& file) {
  const nlohmann::json document = parse_json_document(text, file);
  const JsonCursor root(document, file);
  // "golden" (the file's golden frames) belongs to `impulse2d golden`, which reads it itself
  // (golden/scenes/golden_block.h); a run ignores it.
  root.allow_only({"name", "description", "caption", "settings", "model", "materials", "bodies",
                   "joints", "events", "camera", "run", "overlays", "view", "character", "golden"});

  Scene scene;
  scene.source = file;
  scene.name = std::filesystem::path(file).stem().string();
  if (auto field = root.optional_field("name")) {
    scene.name = field->string();
    if (!is_file_name_prefix(scene.name)) {
      field->fail("must be a file-name prefix: letters, digits, '_', '-' and '.', not starting "
                  "with '.', at most 64 characters");
    }
  }
  if (!root.has("name") && !is_file_name_prefix(scene.name)) {
    root.fail("the file name gives the scene the name \"" + scene.name +
              "\", which cannot prefix output files; add a \"name\" field");
  }
  scene.description = "scene file " + file;
  if (auto field = root.optional_field("description")) scene.description = field->string();
  if (auto field = root.optional_field("caption")) scene.view.caption = field->string();
  std::optional<float> hit_event_speed;
  if (auto field = root.optional_field("settings")) {
    scene.settings = read_settings(*field);
    if (auto speed = field->optional_field("hit_event_speed")) {
      hit_event_speed = speed->non_negative();  // (finite: every JSON number read is)
    }
  }

  MaterialTable table;
  for (const Material& material : materials::all()) table[material.name] = material;
  if (auto field = root.optional_field("materials")) {
    field->expect_object();
    for (const auto& member : field->value().items()) {
      const std::string& name = member.key();
      if (table.count(name) != 0)
        field->field(name).fail("redefines the built-in material " + name);
      table[name] = read_material_object(field->field(name), name);
    }
  }

  std::vector<BodySpawn> bodies;
  BodyNames names;
  const JsonCursor body_list = root.field("bodies");
  for (std::size_t i = 0; i < body_list.size(); ++i) {
    const JsonCursor node = body_list.element(i);
    const int index = static_cast<int>(bodies.size());  // creation index: links count
    std::vector<ChainLink> chain;
    const BodySpawn body = read_body(node, table, &chain);
    if (chain.empty()) bodies.push_back(body);
    const Transform place{body.def.position, Rotation::from_angle(body.def.angle)};
    for (const ChainLink& link : chain) {
      BodySpawn spawn = body;
      spawn.def.position = place.apply(link.position);
      spawn.shape = link.shape;
      bodies.push_back(spawn);
    }
    if (auto name = node.optional_field("name")) {
      if (!names.emplace(read_body_name(*name), index).second) {
        name->fail("the name \"" + name->string() + "\" is used twice");
      }
    }
  }

  // Joints between the file's bodies (spawned bodies are named only by create_joint events).
  std::map<std::string, JointType> joint_names;  // name -> type, for the events
  const auto name_joint = [&joint_names](const JsonCursor& node, const JointSpec& spec) {
    if (spec.name.empty()) return;
    if (!joint_names.emplace(spec.name, spec.type).second) {
      node.field("name").fail("the joint name \"" + spec.name + "\" is used twice");
    }
  };
  if (auto list = root.optional_field("joints")) {
    JointBodies known;
    known.names = &names;
    known.count = static_cast<int>(bodies.size());
    known.spawn = [&bodies](int index) { return &bodies[static_cast<std::size_t>(index)]; };
    for (std::size_t i = 0; i < list->size(); ++i) {
      const JsonCursor node = list->element(i);
      scene.joints.push_back(read_joint(node, known, scene.warnings, file));
      name_joint(node, scene.joints.back());
    }
  }

  std::vector<BodySpawn> spawned;  // for model inference
  if (auto events = root.optional_field("events")) {
    // Spawned bodies get creation indices in step order (stable for equal steps), as the
    // run creates them.
    std::vector<std::pair<std::int64_t, std::size_t>> spawn_order;
    for (std::size_t i = 0; i < events->size(); ++i) {
      const JsonCursor node = events->element(i);
      const std::int64_t step = node.field("step").integer(0, 100000000);
      const std::string kind = node.field("type").string();
      if (kind == "spawn") spawn_order.emplace_back(step, i);
    }
    std::stable_sort(spawn_order.begin(), spawn_order.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::map<std::size_t, int> spawn_index;  // event index -> creation index
    for (std::size_t rank = 0; rank < spawn_order.size(); ++rank) {
      spawn_index[spawn_order[rank].second] = static_cast<int>(bodies.size() + rank);
    }
    for (const auto& [event_index, creation_index] : spawn_index) {
      const JsonCursor body = events->element(event_index).field("body");
      if (auto name = body.optional_field("name")) {
        if (!names.emplace(read_body_name(*name), creation_index).second) {
          name->fail("the name \"" + name->string() + "\" is used twice");
        }
      }
    }

    for (std::size_t i = 0; i < events->size(); ++i) {
      const JsonCursor node = events->element(i);
      SceneEvent event;
      event.origin = node.path();
      event.step = node.field("step").integer(0, 100000000);
      const JsonCursor type = node.field("type");
      event.kind = type.choice<SceneEventKind>({{"impulse", SceneEventKind::Impulse},
                                                {"force", SceneEventKind::Force},
                                                {"spawn", SceneEventKind::Spawn},
                                                {"remove", SceneEventKind::Remove},
                                                {"button", SceneEventKind::Button},
                                                {"create_joint", SceneEventKind::CreateJoint},
                                                {"destroy_joint", SceneEventKind::DestroyJoint},
                                                {"mouse_target", SceneEventKind::MouseTarget}});
      switch (event.kind) {
        case SceneEventKind::Impulse:
          node.allow_only({"step", "type", "body", "impulse", "point", "angular_impulse"});
          event.body = read_body_reference(node.field("body"), names);
          event.impulse =
              node.field("impulse").vector_at_most(limits::max_impulse, limits::impulse_reason);
          if (auto point = node.optional_field("point")) {
            event.point = point->vector_at_most(limits::max_coordinate, limits::coordinate_reason);
          }
          if (auto angular = node.optional_field("angular_impulse")) {
            event.angular_impulse =
                angular->magnitude_at_most(limits::max_impulse, limits::impulse_reason);
          }
          break;
        case SceneEventKind::Force:
          node.allow_only({"step", "type", "body", "force", "point", "torque", "steps"});
          event.body = read_body_reference(node.field("body"), names);
          event.force = node.field("force").vector_at_most(limits::max_force, limits::force_reason);
          if (auto point = node.optional_field("point")) {
            event.point = point->vector_at_most(limits::max_coordinate, limits::coordinate_reason);
          }
          if (auto torque = node.optional_field("torque")) {
            event.torque = torque->magnitude_at_most(limits::max_force, limits::force_reason);
          }
          event.steps = node.field("steps").integer(1, limits::max_force_steps);
          break;
        case SceneEventKind::Spawn:
          node.allow_only({"step", "type", "body"});
          event.spawn = read_body(node.field("body"), table);
          spawned.push_back(event.spawn);
          break;
        case SceneEventKind::Remove:
          node.allow_only({"step", "type", "body"});
          event.body = read_body_reference(node.field("body"), names);
          break;
        case SceneEventKind::Button:
          node.allow_only({"step", "type", "button", "pressed"});
          event.button = node.field("button").string();
          if (auto pressed = node.optional_field("pressed")) event.pressed = pressed->boolean();
          break;
        case SceneEventKind::CreateJoint: {
          node.allow_only({"step", "type", "joint"});
          JointBodies known;
          known.names = &names;
          known.count = static_cast<int>(bodies.size() + spawn_index.size());
          // Spawned bodies are not known here: no anchor warning for them.
          known.spawn = [&bodies](int index) -> const BodySpawn* {
            const auto slot = static_cast<std::size_t>(index);
            return slot < bodies.size() ? &bodies[slot] : nullptr;
          };
          event.joint = read_joint(node.field("joint"), known, scene.warnings, file);
          name_joint(node.field("joint"), event.joint);
          break;
        }
        case SceneEventKind::DestroyJoint:
        case SceneEventKind::MouseTarget:
          if (event.kind == SceneEventKind::DestroyJoint) {
            node.allow_only({"step", "type", "joint"});
          } else {
            node.allow_only({"step", "type", "joint", "target"});
            event.target = node.field("target").vector_at_most(limits::max_coordinate, limits::coordinate_reason);
          }
          event.joint_name = node.field("joint").string();
          break;
      }
      scene.events.push_back(std::move(event));
    }

    // Joint names of destroy_joint and mouse_target events: declared somewhere in the file
    // (whether the joint exists at that step is the run's check).
    for (std::size_t i = 0; i < scene.events.size(); ++i) {
      const SceneEvent& event = scene.events[i];
      if (event.kind != SceneEventKind::DestroyJoint && event.kind != SceneEventKind::MouseTarget) continue;
      const JsonCursor field = events->element(i).field("joint");
      const auto found = joint_names.find(event.joint_name);
      if (found == joint_names.end()) {
        std::string known;
        for (const auto& [name, type] : joint_names) known += (known.empty() ? "" : ", ") + name;
        field.fail("unknown joint \"" + event.joint_name + "\" (named joints: " +
                   (known.empty() ? std::string("none") : known) + ")");
      }
      if (event.kind == SceneEventKind::MouseTarget && found->second != JointType::Mouse) {
        field.fail("joint \"" + event.joint_name + "\" is a " + joint_type_name(found->second) +
                   " joint; only a mouse joint has a target");
      }
    }

    // An impulse or a force on a static or kinematic body would do nothing (the world moves
    // only dynamic bodies by them): reject it here, where every body's type is known.
    std::map<int, std::size_t> spawn_event;  // creation index -> event index
    for (const auto& [event_index, creation_index] : spawn_index) {
      spawn_event[creation_index] = event_index;
    }
    for (std::size_t i = 0; i < scene.events.size(); ++i) {
      const SceneEvent& event = scene.events[i];
      if (event.kind != SceneEventKind::Impulse && event.kind != SceneEventKind::Force) continue;
      const BodyDef* def = nullptr;
      if (event.body >= 0 && static_cast<std::size_t>(event.body) < bodies.size()) {
        def = &bodies[static_cast<std::size_t>(event.body)].def;
      } else if (const auto spawn = spawn_event.find(event.body); spawn != spawn_event.end()) {
        def = &scene.events[spawn->second].spawn.def;
      }
      if (def == nullptr || def->type == BodyType::Dynamic) continue;  // (a missing body: the run says)
      std::string label = "body " + std::to_string(event.body);
      for (const auto& [name, index] : names) {
        if (index == event.body) label += " (\"" + name + "\")";
      }
      events->element(i).field("body").fail(unmovable_body_reason(label, def->type, event.kind));
    }
  }

  if (auto field = root.optional_field("model")) {
    scene.model = read_model(*field, scene.settings);
  } else {
    // No declared model: the least one that covers the file's bodies.
    scene.model.velocity_iterations = scene.settings.velocity_iterations;
    scene.model.position_iterations = scene.settings.position_iterations;
    scene.model.rotation = false;
    scene.model.ccd = false;
    auto cover = [&scene](const BodySpawn& body) {
      auto cover_kind = [&scene](const Shape& shape) {
        scene.model.circles = scene.model.circles || shape.type() == ShapeType::Circle;
        scene.model.boxes = scene.model.boxes || shape.type() == ShapeType::Box;
        scene.model.polygons = scene.model.polygons || shape.type() == ShapeType::Polygon;
        scene.model.capsules = scene.model.capsules || shape.type() == ShapeType::Capsule;
        scene.model.segments = scene.model.segments || shape.type() == ShapeType::Segment;
      };
      cover_kind(body.shape);
      for (const ShapeDef& placed : body.shapes) {
        // A compound keeps a box as the polygon of its outline.
        cover_kind(placed.shape.type() == ShapeType::Box ? make_oriented_box(placed.shape.box().half_extents)
                                                         : placed.shape);
      }
      const bool spins = body.def.type == BodyType::Dynamic && body.shape.type() != ShapeType::Box &&
                         !body.def.fixed_rotation;
      scene.model.rotation = scene.model.rotation || spins;
      scene.model.ccd = scene.model.ccd || body.def.is_bullet;
    };
    for (const BodySpawn& body : bodies) cover(body);
    for (const BodySpawn& body : spawned) cover(body);
  }

  if (auto field = root.optional_field("camera")) {
    scene.view.camera = read_camera(*field, names);
    const std::size_t created = bodies.size() + spawned.size();
    if (scene.view.camera.mode == CameraSpec::Mode::Follow && scene.view.camera.follow_body >= 0 &&
        static_cast<std::size_t>(scene.view.camera.follow_body) >= created) {
      field->field("follow").fail("body " + std::to_string(scene.view.camera.follow_body) +
                                  " does not exist (the scene creates " + std::to_string(created) +
                                  " bodies, indices 0.." + std::to_string(created) + " - 1)");
    }
  }
  if (auto field = root.optional_field("view")) {
    read_view(*field, names, bodies.size() + spawned.size(), scene.view);
  }
  if (auto field = root.optional_field("character")) {
    const CharacterDef character = read_character(*field);
    // The character is an axis-aligned box: an inferred model grows to include it, a declared
    // one must already.
    if (root.has("model") && !scene.model.boxes) {
      field->fail("the character is a box: add \"box\" to model.shapes");
    }
    scene.model.boxes = true;
    scene.script = [character](const Params&) { return std::make_unique<CharacterScript>(character); };
  }
  if (auto run = root.optional_field("run")) {
    run->allow_only({"steps", "frames"});
    if (auto steps = run->optional_field("steps")) scene.view.steps = steps->integer(1, 10000000);
    if (auto frames = run->optional_field("frames")) {
      scene.view.frames = frames->string();
      try {
        FrameSelection::parse(scene.view.frames);
      } catch (const UsageError& error) {
        frames->fail(error.what());
      }
    }
  }
  if (auto overlays = root.optional_field("overlays")) {
    for (std::size_t i = 0; i < overlays->size(); ++i) {
      const JsonCursor entry = overlays->element(i);
      try {
        scene.view.draw.flags |= overlay_flags(entry.string());
      } catch (const UsageError& error) {
        entry.fail(error.what());
      }
    }
  }

  for (const auto& [name, index] : names) scene.body_names[index] = name;
  scene.build = [bodies, hit_event_speed](World& world, const Params&) {
    if (hit_event_speed) world.set_hit_event_threshold(*hit_event_speed);
    for (const BodySpawn& body : bodies) create_spawn(world, body);
  };
  return scene;
}

Scene load_scene_file(const std::string& path) {
  const UserFileKind scene_file{"scene file", "a plain .json file",
                                static_cast<std::uintmax_t>(limits::max_scene_file_bytes), "4 MiB"};
  Scene scene = parse_scene(read_user_file(path, scene_file), path);
  for (const std::string& warning : scene.warnings) std::cerr << "impulse2d: warning: " << warning << "\n";
  return scene;
}

}  // namespace impulse2d::demos
