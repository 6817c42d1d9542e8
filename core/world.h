#pragma once
/// @file world.h
/// The simulation: bodies, contacts and settings, stepped at a fixed time step.
/// The tutorial's `Scene`, with handles, methods as data and a deterministic order.

#include "core/body.h"
#include "core/contact.h"
#include "core/debug_draw.h"
#include "core/events.h"
#include "core/joint.h"
#include "core/query.h"
#include "core/settings.h"
#include "core/step_stats.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace impulse2d {

/// A ray's hit on a body.
struct RayHit {
  BodyId body;               ///< the body hit
  vec2 point{0.0f, 0.0f};    ///< world point of entry, metres
  vec2 normal{0.0f, 0.0f};   ///< outward surface normal there
  float fraction = 0.0f;     ///< 0 at the ray's origin, 1 at its end
};

/// Decides whether a new contact between two bodies is solved. Called once when the pair
/// starts touching (comes within the speculative margin); the decision is kept while they overlap and taken afresh once they are more than 1 mm apart. Return false to let them pass.
using ContactFilter =
    std::function<bool(const BodyView& a, const BodyView& b, const Manifold& manifold)>;

/// Called by queries for each body found; return false to stop the query.
using QueryCallback = std::function<bool(BodyId)>;

/// Everything a world holds: internal (core/solver/world_state.h), behind `World`'s pointer.
struct WorldState;

/// A 2D rigid-body world. Its state lives behind a pointer (internal `WorldState`): copying a
/// world copies all of it, giving an independent world that continues to the same states.
class World {
 public:
  /// A world with the given settings (validated; throws `Error` naming a bad field).
  explicit World(const WorldSettings& settings = WorldSettings{});
  /// An independent copy: bodies, contacts (with their impulses), settings and filter.
  World(const World& other);
  /// Replaces this world by an independent copy of `other`.
  World& operator=(const World& other);
  /// Takes `other`'s state; `other` may then only be assigned to or destroyed.
  World(World&& other) noexcept;
  /// Takes `other`'s state; `other` may then only be assigned to or destroyed.
  World& operator=(World&& other) noexcept;
  /// Frees the world's state.
  ~World();

  /// The current settings.
  const WorldSettings& settings() const;
  /// Replaces all settings (validated; throws `Error` naming a bad field).
  void set_settings(const WorldSettings& settings);
  /// Sets gravity, m/s^2.
  void set_gravity(vec2 gravity);
  /// Sets the fixed time step, seconds (> 0).
  void set_time_step(float time_step);

  /// Creates a body with one shape. Throws `Error` for non-finite or invalid definitions.
  BodyId create_body(const BodyDef& def, const Shape& shape);
  /// Creates a body of `count` shapes (1..`max_body_shapes`), each placed in the body's frame
  /// with its own material and layers (a compound body: an L-shaped crate, a hammer). The
  /// shapes are placed around `def.position` as the body's origin; a dynamic body is then
  /// re-centred on its centre of mass (`body(id).transform.position` is that point, and the
  /// view's `shapes` are placed relative to it). Mass and inertia are the shapes' summed
  /// (parallel axis); `def.material` is not used (each shape has its own). A `Box` is kept as
  /// the polygon of its outline (it turns with the body). Throws `Error` naming the shape
  /// (`shapes[i]`) for an invalid one, a chain link, or a dynamic body without area.
  BodyId create_body(const BodyDef& def, const ShapeDef* shapes, int count);
  /// Creates a chain (see `make_chain`): one static body per link, each at its link's midpoint
  /// moved and turned by `def.position` and `def.angle`, the rest of `def` (material, layers,
  /// events) shared; returns their handles in link order. Throws `Error` for a `def` that is
  /// not static or for bad points (naming the point), creating nothing.
  std::vector<BodyId> create_chain(const BodyDef& def, const vec2* points, int count, bool loop);
  /// Removes a body; its handle and any copy of it become stale. Throws on a stale handle.
  void remove_body(BodyId id);
  /// True when `id` names a living body.
  bool is_valid(BodyId id) const;
  /// What the body named by `id` is now (a copy; see `BodyView`). Throws `Error` on a stale
  /// or null handle.
  BodyView body(BodyId id) const;
  /// Handles of all living bodies in ascending slot order (stable across runs).
  std::vector<BodyId> body_ids() const;
  /// Number of living bodies.
  int body_count() const;

  /// Sets position (metres) and angle (radians) directly; also resets the interpolation state.
  void set_transform(BodyId id, vec2 position, float angle);
  /// Sets the linear velocity, m/s.
  void set_linear_velocity(BodyId id, vec2 velocity);
  /// Sets the angular velocity, rad/s.
  void set_angular_velocity(BodyId id, float angular_velocity);
  /// Sets the gravity scale of a body.
  void set_gravity_scale(BodyId id, float scale);
  /// Replaces a body's material (validated; throws `Error` naming the field). A dynamic body's
  /// mass and inertia follow the new density (which must stay > 0); contacts mix the new
  /// coefficients from the next step on. A compound body's shapes all get `material`.
  void set_material(BodyId id, const Material& material);
  /// Adds a force (N) at a world point (metres) for the next step; it also makes a torque.
  void apply_force(BodyId id, vec2 force, vec2 world_point);
  /// Adds a force (N) at the centre of mass for the next step.
  void apply_force_to_center(BodyId id, vec2 force);
  /// Adds a torque (N m) for the next step.
  void apply_torque(BodyId id, float torque);
  /// Changes velocity at once by an impulse (N s) at a world point (metres).
  void apply_linear_impulse(BodyId id, vec2 impulse, vec2 world_point);
  /// Changes angular velocity at once by an angular impulse (N m s).
  void apply_angular_impulse(BodyId id, float impulse);
  /// Wakes a sleeping body (or puts an awake one to sleep).
  void set_awake(BodyId id, bool awake);

  /// Creates a hinge between two distinct living bodies (wakes both). Throws `Error` on a
  /// stale handle, equal bodies or a non-finite or out-of-range field (lower > upper, a
  /// negative hertz, damping ratio, max torque).
  JointId create_joint(const RevoluteJointDef& def);
  /// Creates a slider (wakes both bodies); throws as the revolute overload (the axis must
  /// not be zero).
  JointId create_joint(const PrismaticJointDef& def);
  /// Creates a distance joint, rope or spring (wakes both bodies); throws as the revolute
  /// overload (min_length <= max_length, lengths >= 0).
  JointId create_joint(const DistanceJointDef& def);
  /// Creates a weld (wakes both bodies); throws as the revolute overload.
  JointId create_joint(const WeldJointDef& def);
  /// Creates a wheel joint (wakes both bodies); throws as the prismatic overload.
  JointId create_joint(const WheelJointDef& def);
  /// Creates a motor joint (wakes both bodies); throws as the revolute overload
  /// (correction_factor in [0, 1]).
  JointId create_joint(const MotorJointDef& def);
  /// Creates a mouse joint (wakes body B); throws as the revolute overload (hertz > 0).
  JointId create_joint(const MouseJointDef& def);
  /// Destroys a joint and wakes its bodies; its handle becomes stale. Throws `Error` on a
  /// stale or null handle. Removing a body destroys its joints the same way.
  void destroy_joint(JointId id);
  /// True when `id` names a living joint.
  bool is_valid(JointId id) const;
  /// The joint's type. Throws `Error` on a stale or null handle.
  JointType joint_type(JointId id) const;
  /// The joint's first body. Throws `Error` on a stale or null handle.
  BodyId joint_body_a(JointId id) const;
  /// The joint's second body. Throws `Error` on a stale or null handle.
  BodyId joint_body_b(JointId id) const;
  /// Handles of all living joints in ascending slot order (stable across runs).
  std::vector<JointId> joint_ids() const;
  /// Number of living joints.
  int joint_count() const;
  /// The force (N, world axes) the joint applied to body B over the last step's last
  /// (sub-)step (its accumulated impulse / that step); A received the opposite. 0 for a
  /// joint that was not solved (both bodies asleep or not dynamic). Throws on a stale handle.
  vec2 joint_reaction_force(JointId id) const;
  /// The torque (N m) the joint applied to body B about its anchor over the last step's last
  /// (sub-)step, as `joint_reaction_force`. Throws on a stale handle.
  float joint_reaction_torque(JointId id) const;
  /// Moves a mouse joint's target (world metres) and wakes its body. Throws `Error` on a
  /// stale handle or a joint of another type.
  void set_mouse_target(JointId id, vec2 target);
  /// Sets the motor speed of a revolute (rad/s), prismatic (m/s), wheel (rad/s) or distance
  /// (m/s) joint and wakes its bodies. Throws `Error` on a stale handle or another type.
  void set_joint_motor_speed(JointId id, float speed);

  /// Advances the simulation by one fixed step of `settings().time_step` seconds.
  void step();
  /// Fixed-step accumulator: adds `frame_time` seconds (clamped to 0.25 s against the spiral
  /// of death), takes as many whole steps as fit and returns how many it took. Afterwards
  /// `interpolation_alpha()` is the fraction of a step left over, for drawing.
  int advance(float frame_time);
  /// Left-over fraction of a step after `advance`, in [0, 1).
  float interpolation_alpha() const;
  /// Simulated time, seconds (steps taken times the time step).
  double time() const;
  /// Number of steps taken.
  std::int64_t step_count() const;

  /// Calls `callback` for each body whose bounds overlap `box`, in ascending slot order.
  void query_aabb(const Aabb& box, const QueryCallback& callback) const;
  /// Calls `callback` for each body whose shape contains `point`, in ascending slot order.
  void query_point(vec2 point, const QueryCallback& callback) const;
  /// The first body hit along `origin` -> `origin + translation` among bodies sharing a bit
  /// with `layers`; ties broken by slot order.
  std::optional<RayHit> raycast_closest(vec2 origin, vec2 translation,
                                        std::uint32_t layers = 0xFFFFFFFFu) const;
  /// Every body hit along the ray, sorted by fraction (then slot order).
  std::vector<RayHit> raycast_all(vec2 origin, vec2 translation,
                                  std::uint32_t layers = 0xFFFFFFFFu) const;

  /// Bodies whose shapes overlap `shape` placed at `transform` (a Box turns with the
  /// rotation), by the narrow phase's own test (touching at zero depth is no overlap), that pass
  /// `filter`. Writes the `capacity` smallest slots, ascending, into `out` and returns how many
  /// bodies overlap in all (may exceed `capacity`). Allocates nothing (keep `filter.accept`'s
  /// captures small); throws `Error` on an invalid shape, a non-finite transform or
  /// capacity > 0 without a buffer.
  int overlap_shape(const Shape& shape, const Transform& transform, BodyId* out, int capacity,
                    const QueryFilter& filter = QueryFilter{}) const;
  /// Moves `shape` from `transform` along `translation` (metres; rotation kept) and returns the
  /// first body it meets among those passing `filter`: fraction of the translation (to about
  /// 1e-6 m along it), point on that body and its surface normal; ties by smallest slot. A body
  /// overlapping at the start is met at fraction 0. Allocates nothing.
  std::optional<ShapeCastHit> cast_shape(const Shape& shape, const Transform& transform,
                                         vec2 translation,
                                         const QueryFilter& filter = QueryFilter{}) const;
  /// The first body hit along `origin` -> `origin + translation` among those passing `filter`
  /// (layer mask, sensors, static bodies, callback); ties by smallest slot. Allocates nothing.
  std::optional<RayHit> raycast_closest(vec2 origin, vec2 translation, const QueryFilter& filter) const;

  /// Touching pairs after the last step, sorted by (A's slot, B's slot).
  const std::vector<Contact>& contacts() const;
  /// Touching pairs set aside because none of their bodies moves (each asleep or static), as
  /// found when the last step began, sorted by (A's slot, B's slot); read-only (for drawing
  /// and counting: the solvers never see them). When a body of the pair wakes, the contact
  /// goes back to the narrow phase with its impulses (warm start); when one is moved by
  /// `set_transform` or removed, the contact is dropped.
  const std::vector<Contact>& sleeping_contacts() const;
  /// Installs a filter consulted when a pair starts touching (pass nullptr to remove it).
  void set_contact_filter(ContactFilter filter);
  /// Overrides the kept decision of the touching pair (a, b), in either order (also of a
  /// sleeping pair): false lets them pass through each other until they separate (e.g.
  /// dropping through a one-way platform). Returns false when the pair is not touching. Throws `Error` on a stale handle.
  bool set_contact_enabled(BodyId a, BodyId b, bool enabled);

  /// The last step's contact events: begin and end of touch, hits (see events.h). Valid
  /// until the next step; reading allocates nothing.
  const ContactEvents& contact_events() const;
  /// The last step's sensor events: shapes that began or stopped overlapping a sensor.
  const SensorEvents& sensor_events() const;
  /// Sets the approach speed (m/s, >= 0) above which a touching pair with hit events on makes
  /// a `ContactHitEvent` (default 1 m/s, Box2D v3's). Throws `Error` when negative or not finite.
  void set_hit_event_threshold(float speed);
  /// The approach speed (m/s) above which hits are reported.
  float hit_event_threshold() const;

  /// Counts and timings of the last step.
  const StepStats& stats() const;
  /// 64-bit FNV-1a hash over every living body's slot, position, angle and velocities, in slot
  /// order. Equal hashes mean bit-identical states.
  std::uint64_t state_hash() const;
  /// Bodies whose state became non-finite during a step: they were restored to their previous
  /// position, stopped and put to sleep instead of spreading NaN. Cleared by the next step.
  const std::vector<BodyId>& diverged_bodies() const;

  /// The whole state of the world as bytes (layout in snapshot.h): bodies, shapes, joints,
  /// contacts with their warm-start impulses and friction state, settings, time and event
  /// state. A world restored from it continues bit for bit as this one.
  std::vector<std::uint8_t> save_snapshot() const;
  /// Replaces this world's state by the one saved in `bytes` (the broad phase is rebuilt;
  /// this world's contact filter is kept). Throws `Error` saying what is wrong for a buffer of
  /// another version, a truncated one or one with changed bytes, leaving this world unchanged.
  void restore_snapshot(const std::vector<std::uint8_t>& bytes);
  /// As above, from `size` bytes at `data`.
  void restore_snapshot(const std::uint8_t* data, std::size_t size);

  /// Emits the world to `draw`: shapes (interpolated by `options.interpolation_alpha`), then
  /// overlays in the order of `DebugDrawFlag`.
  void draw(DebugDraw& draw, const DebugDrawOptions& options) const;

 private:
  friend struct WorldState;
  std::unique_ptr<WorldState> state_;
};

}  // namespace impulse2d
