// Snapshots (snapshot.h): one list of fields per struct, walked by a writer and a reader alike,
// so the two directions cannot disagree.
#include "core/error.h"
#include "core/snapshot.h"
#include "core/solver/world_state.h"
#include "core/world.h"

#include <cstring>
#include <string>

namespace impulse2d {

namespace {

std::uint64_t fnv1a(const std::uint8_t* data, std::size_t size) {
  std::uint64_t hash = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= data[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

constexpr std::uint32_t tag(const char (&name)[5]) {
  return static_cast<std::uint32_t>(static_cast<std::uint8_t>(name[0])) |
         static_cast<std::uint32_t>(static_cast<std::uint8_t>(name[1])) << 8 |
         static_cast<std::uint32_t>(static_cast<std::uint8_t>(name[2])) << 16 |
         static_cast<std::uint32_t>(static_cast<std::uint8_t>(name[3])) << 24;
}

struct Writer {
  std::vector<std::uint8_t>& out;
  void bytes_le(std::uint64_t value, int count) {
    for (int i = 0; i < count; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
  }
  void u8(std::uint8_t& v) { bytes_le(v, 1); }
  void u32(std::uint32_t& v) { bytes_le(v, 4); }
  void u64(std::uint64_t& v) { bytes_le(v, 8); }
  void i32(std::int32_t& v) { bytes_le(static_cast<std::uint32_t>(v), 4); }
  void i64(std::int64_t& v) { bytes_le(static_cast<std::uint64_t>(v), 8); }
  void f32(float& v) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    bytes_le(bits, 4);
  }
  void f64(double& v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    bytes_le(bits, 8);
  }
  void boolean(bool& v) { bytes_le(v ? 1 : 0, 1); }
  template <class E>
  void enumeration(E& v) { bytes_le(static_cast<std::uint32_t>(v), 4); }
  void string(std::string& v) {
    std::uint32_t size = static_cast<std::uint32_t>(v.size());
    u32(size);
    out.insert(out.end(), v.begin(), v.end());
  }
  std::uint32_t count(std::size_t size) {
    std::uint32_t value = static_cast<std::uint32_t>(size);
    u32(value);
    return value;
  }
  void section(std::uint32_t name) { bytes_le(name, 4); }
  static constexpr bool reading = false;
};

struct Reader {
  const std::uint8_t* data;
  std::size_t size;
  std::size_t at = 0;
  std::uint64_t bytes_le(int count, const char* what) {
    if (size - at < static_cast<std::size_t>(count)) {
      throw Error(std::string("World::restore_snapshot: truncated buffer (reading ") + what + " at byte " +
                  std::to_string(at) + ")");
    }
    std::uint64_t value = 0;
    for (int i = 0; i < count; ++i) value |= static_cast<std::uint64_t>(data[at + i]) << (8 * i);
    at += static_cast<std::size_t>(count);
    return value;
  }
  void u8(std::uint8_t& v) { v = static_cast<std::uint8_t>(bytes_le(1, "u8")); }
  void u32(std::uint32_t& v) { v = static_cast<std::uint32_t>(bytes_le(4, "u32")); }
  void u64(std::uint64_t& v) { v = bytes_le(8, "u64"); }
  void i32(std::int32_t& v) { v = static_cast<std::int32_t>(static_cast<std::uint32_t>(bytes_le(4, "i32"))); }
  void i64(std::int64_t& v) { v = static_cast<std::int64_t>(bytes_le(8, "i64")); }
  void f32(float& v) {
    const std::uint32_t bits = static_cast<std::uint32_t>(bytes_le(4, "f32"));
    std::memcpy(&v, &bits, 4);
  }
  void f64(double& v) {
    const std::uint64_t bits = bytes_le(8, "f64");
    std::memcpy(&v, &bits, 8);
  }
  void boolean(bool& v) {
    const std::uint64_t b = bytes_le(1, "bool");
    if (b > 1) throw Error("World::restore_snapshot: corrupt bool at byte " + std::to_string(at - 1));
    v = b != 0;
  }
  template <class E>
  void enumeration(E& v, std::uint32_t count) {
    const std::uint32_t raw = static_cast<std::uint32_t>(bytes_le(4, "enum"));
    if (raw >= count) throw Error("World::restore_snapshot: corrupt enum value at byte " + std::to_string(at - 4));
    v = static_cast<E>(raw);
  }
  void string(std::string& v) {
    std::uint32_t length;
    u32(length);
    if (size - at < length) throw Error("World::restore_snapshot: truncated buffer (reading a name)");
    v.assign(reinterpret_cast<const char*>(data + at), length);
    at += length;
  }
  std::uint32_t count(std::size_t) {
    std::uint32_t value;
    u32(value);
    // Every element takes at least a byte: a count past the end is corrupt, not a huge allocation.
    if (value > size - at) throw Error("World::restore_snapshot: corrupt count " + std::to_string(value));
    return value;
  }
  void section(std::uint32_t name) {
    const std::uint32_t found = static_cast<std::uint32_t>(bytes_le(4, "section tag"));
    if (found != name) throw Error("World::restore_snapshot: corrupt buffer: section tag mismatch at byte " + std::to_string(at - 4));
  }
  static constexpr bool reading = true;
};

// Enumerations with their number of values (checked on reading).
template <class IO, class E>
void enum_field(IO& io, E& value, std::uint32_t count) {
  if constexpr (IO::reading) {
    io.enumeration(value, count);
  } else {
    io.enumeration(value);
  }
}

template <class IO> void io_vec2(IO& io, vec2& v) { io.f32(v.x); io.f32(v.y); }
template <class IO> void io_rotation(IO& io, Rotation& r) { io.f32(r.cosine); io.f32(r.sine); }
template <class IO> void io_transform(IO& io, Transform& t) { io_vec2(io, t.position); io_rotation(io, t.rotation); }
template <class IO> void io_aabb(IO& io, Aabb& a) { io_vec2(io, a.lower); io_vec2(io, a.upper); }
template <class IO> void io_body_id(IO& io, BodyId& id) { io.u32(id.index); io.u32(id.generation); }
template <class IO> void io_bool(IO& io, bool& b) { io.boolean(b); }

template <class IO>
void io_settings(IO& io, WorldSettings& s) {
  io_vec2(io, s.gravity);
  io.f32(s.time_step);
  io.i32(s.substeps);
  enum_field(io, s.solver, 3);
  io.i32(s.velocity_iterations);
  io.i32(s.solver_lanes);
  io_bool(io, s.warm_starting);
  io_bool(io, s.block_solver);
  io_bool(io, s.shock_propagation);
  io.f32(s.speculative_margin);
  io.f32(s.contact_recycle_distance);
  enum_field(io, s.position_correction, 3);
  io.i32(s.position_iterations);
  io.f32(s.correction_percent);
  io.f32(s.slop);
  io.f32(s.max_correction);
  io.f32(s.contact_hertz);
  io.f32(s.contact_damping_ratio);
  io.f32(s.contact_push_max_speed);
  io.f32(s.restitution_threshold);
  enum_field(io, s.friction_mixing, 8);
  enum_field(io, s.restitution_mixing, 8);
  enum_field(io, s.integrator, 2);
  enum_field(io, s.broad_phase, 3);
  io_bool(io, s.enable_friction);
  io_bool(io, s.enable_restitution);
  io_bool(io, s.enable_rotation);
  io_bool(io, s.enable_sleeping);
  io_bool(io, s.enable_continuous);
  io.f32(s.sleep_linear_speed);
  io.f32(s.sleep_angular_speed);
  io.f32(s.time_to_sleep);
  io.f32(s.max_linear_speed);
}

template <class IO>
void io_shape(IO& io, Shape& shape) {
  std::uint8_t kind = static_cast<std::uint8_t>(shape.type());
  io.u8(kind);
  if (kind == static_cast<std::uint8_t>(ShapeType::Circle)) {
    Circle circle = IO::reading ? Circle{} : shape.circle();
    io.f32(circle.radius);
    if (IO::reading) shape = circle;
  } else if (kind == static_cast<std::uint8_t>(ShapeType::Box)) {
    Box box = IO::reading ? Box{} : shape.box();
    io_vec2(io, box.half_extents);
    if (IO::reading) shape = box;
  } else if (kind == static_cast<std::uint8_t>(ShapeType::Polygon)) {
    Polygon polygon = IO::reading ? Polygon{} : shape.polygon();
    io.i32(polygon.count);
    if (polygon.count < 3 || polygon.count > max_polygon_vertices) {
      throw Error("World::restore_snapshot: corrupt polygon vertex count " + std::to_string(polygon.count));
    }
    for (vec2& v : polygon.vertices) io_vec2(io, v);
    for (vec2& n : polygon.normals) io_vec2(io, n);
    io.f32(polygon.radius);
    io.f32(polygon.rounding);
    if (IO::reading) shape = polygon;
  } else if (kind == static_cast<std::uint8_t>(ShapeType::Capsule)) {
    Capsule capsule = IO::reading ? Capsule{} : shape.capsule();
    io_vec2(io, capsule.center1);
    io_vec2(io, capsule.center2);
    io.f32(capsule.radius);
    if (IO::reading) shape = capsule;
  } else if (kind == static_cast<std::uint8_t>(ShapeType::Segment)) {
    Segment segment = IO::reading ? Segment{} : shape.segment();
    io_vec2(io, segment.point1);
    io_vec2(io, segment.point2);
    io_bool(io, segment.one_sided);
    io_vec2(io, segment.ghost1);
    io_vec2(io, segment.ghost2);
    if (IO::reading) shape = segment;
  } else {
    throw Error("World::restore_snapshot: corrupt shape kind " + std::to_string(kind));
  }
}

template <class IO>
void io_material(IO& io, Material& material) {
  io.string(material.name);
  io.f32(material.density);
  io.f32(material.restitution);
  io.f32(material.static_friction);
  io.f32(material.dynamic_friction);
}

template <class IO>
void io_body(IO& io, Body& b) {
  io_body_id(io, b.id);
  enum_field(io, b.type, 3);
  io_bool(io, b.awake);
  io_bool(io, b.fixed_rotation);
  io_bool(io, b.is_bullet);
  io_transform(io, b.transform);
  io.f32(b.angle);
  io_vec2(io, b.linear_velocity);
  io.f32(b.angular_velocity);
  io.f32(b.inverse_mass);
  io.f32(b.inverse_inertia);
  io_vec2(io, b.force);
  io.f32(b.torque);
  io.f32(b.gravity_scale);
  io.f32(b.linear_damping);
  io.f32(b.angular_damping);
  io.f32(b.mass);
  io.f32(b.inertia);
  io_vec2(io, b.previous_position);
  io.f32(b.previous_angle);
  io.f32(b.sleep_time);
  io.f32(b.extent);
  io.f32(b.rounding);
  io_bool(io, b.speculative);
  io.u32(b.collision_layers);
  io_aabb(io, b.aabb);
  io.u64(b.user_data);
  io_bool(io, b.enable_contact_events);
  io_bool(io, b.enable_hit_events);
  io_bool(io, b.is_sensor);
  io_bool(io, b.sensor_detects_static);
  io_bool(io, b.enable_sensor_events);
  io_material(io, b.material);
  io_shape(io, b.shape);
  io_bool(io, b.compound);
  const std::uint32_t children = io.count(b.children.size());
  if (IO::reading) {
    if (children > static_cast<std::uint32_t>(max_body_shapes) || b.compound != (children > 0)) {
      throw Error("World::restore_snapshot: corrupt compound body shape count " + std::to_string(children));
    }
    b.children.assign(children, BodyShape{});
  }
  for (BodyShape& part : b.children) {
    io_shape(io, part.shape);
    io_transform(io, part.local);
    io_material(io, part.material);
    io.u32(part.collision_layers);
    io_bool(io, part.is_sensor);
  }
  io_bool(io, b.has_sensor_shapes);
}

// A shape index (0..max_body_shapes - 1) of a contact or event pair.
template <class IO>
void io_child(IO& io, std::uint16_t& child) {
  std::uint32_t value = child;
  io.u32(value);
  if (IO::reading) {
    if (value >= static_cast<std::uint32_t>(max_body_shapes)) {
      throw Error("World::restore_snapshot: corrupt shape index " + std::to_string(value));
    }
    child = static_cast<std::uint16_t>(value);
  }
}

template <class IO>
void io_softness(IO& io, Softness& s) { io.f32(s.bias_rate); io.f32(s.mass_scale); io.f32(s.impulse_scale); }

template <class IO>
void io_joint(IO& io, Joint& j) {
  io.u32(j.id.index);
  io.u32(j.id.generation);
  enum_field(io, j.type, 7);
  io_body_id(io, j.body_a);
  io_body_id(io, j.body_b);
  io_vec2(io, j.local_anchor_a);
  io_vec2(io, j.local_anchor_b);
  io_vec2(io, j.local_axis_a);
  io.f32(j.reference_angle);
  io_bool(io, j.collide_connected);
  io_bool(io, j.enable_spring);
  io_bool(io, j.enable_limit);
  io_bool(io, j.enable_motor);
  for (float* f : {&j.hertz, &j.damping_ratio, &j.lower, &j.upper, &j.motor_speed, &j.max_motor, &j.length,
                   &j.min_length, &j.max_length, &j.linear_hertz, &j.angular_hertz, &j.linear_damping_ratio,
                   &j.angular_damping_ratio}) {
    io.f32(*f);
  }
  io_vec2(io, j.linear_offset);
  io.f32(j.angular_offset);
  io.f32(j.max_force);
  io.f32(j.max_torque);
  io.f32(j.correction_factor);
  io_vec2(io, j.target);
  io.u64(j.user_data);
  io_vec2(io, j.linear_impulse);
  for (float* f : {&j.angular_impulse, &j.axial_impulse, &j.spring_impulse, &j.motor_impulse, &j.lower_impulse,
                   &j.upper_impulse, &j.inverse_mass_a, &j.inverse_mass_b, &j.inverse_inertia_a,
                   &j.inverse_inertia_b}) {
    io.f32(*f);
  }
  io_softness(io, j.spring_softness);
  io_softness(io, j.angular_softness);
  io.f32(j.impulse_interval);
  io_bool(io, j.active);
}

template <class IO>
void io_contact(IO& io, Contact& c) {
  io_body_id(io, c.body_a);
  io_body_id(io, c.body_b);
  io_child(io, c.child_a);
  io_child(io, c.child_b);
  io_vec2(io, c.normal);
  io.i32(c.point_count);
  // A contact has one point or more (the narrow phase keeps no other, and the solvers read the
  // first point of every contact they are given).
  if (c.point_count < 1 || c.point_count > max_manifold_points) {
    throw Error("World::restore_snapshot: corrupt contact point count " + std::to_string(c.point_count));
  }
  for (ContactPoint& p : c.points) {
    for (vec2* v : {&p.point, &p.anchor_a, &p.anchor_b, &p.local_anchor_a, &p.local_anchor_b}) io_vec2(io, *v);
    io.f32(p.depth);
    io.f32(p.rounding);
    io.u32(p.feature_id);
    for (float* f : {&p.normal_impulse, &p.tangent_impulse, &p.normal_mass, &p.tangent_mass, &p.velocity_bias}) {
      io.f32(*f);
    }
    io_bool(io, p.bouncing);
    io.f32(p.bounce_speed);
    io_bool(io, p.bounced);
    io_bool(io, p.caught);
    io_bool(io, p.waiting);
    io_bool(io, p.friction_at_limit);
    io_vec2(io, p.recycle_anchor_a);
    io_vec2(io, p.recycle_anchor_b);
    io.f32(p.base_separation);
    io.f32(p.stick_offset);
  }
  for (float* f : {&c.static_friction, &c.dynamic_friction, &c.restitution}) io.f32(*f);
  io_bool(io, c.sliding);
  for (float* f : {&c.approach_acceleration, &c.start_slip, &c.start_load}) io.f32(*f);
  io.u8(c.steps_at_static_limit);
  io.f32(c.limit_slip);
  for (float* f : {&c.mass.inverse_mass_a, &c.mass.inverse_mass_b, &c.mass.inverse_inertia_a,
                   &c.mass.inverse_inertia_b}) {
    io.f32(*f);
  }
  io_vec2(io, c.manifold_pose.relative_position);
  io_rotation(io, c.manifold_pose.rotation_a);
  io_rotation(io, c.manifold_pose.rotation_b);
  io_bool(io, c.recycled);
  io_bool(io, c.enabled);
}

template <class IO, class T, class Each>
void io_vector(IO& io, std::vector<T>& items, Each each) {
  const std::uint32_t count = io.count(items.size());
  if (IO::reading) items.assign(count, T{});
  for (T& item : items) each(io, item);
}

template <class IO>
void io_u32_vector(IO& io, std::vector<std::uint32_t>& items) {
  io_vector(io, items, [](IO& inner, std::uint32_t& v) { inner.u32(v); });
}

template <class IO>
void io_pairs(IO& io, std::vector<EventPair>& pairs) {
  io_vector(io, pairs, [](IO& inner, EventPair& p) {
    io_body_id(inner, p.a);
    io_body_id(inner, p.b);
    io_child(inner, p.shape_a);
    io_child(inner, p.shape_b);
  });
}

template <class IO>
void io_world(IO& io, WorldState& w) {
  io.section(tag("SETT"));
  io_settings(io, w.settings);
  io.section(tag("TIME"));
  io.f64(w.time);
  io.i64(w.step_count);
  io.f32(w.accumulator);
  io_bool(io, w.bounds_current);
  io.section(tag("BODY"));
  const std::uint32_t slots = io.count(w.bodies.size());
  if (IO::reading) {
    w.bodies.assign(slots, Body{});
    w.alive.assign(slots, 0);
  }
  for (std::uint32_t i = 0; i < slots; ++i) {
    io.u8(w.alive[i]);
    io_body(io, w.bodies[i]);
  }
  io_u32_vector(io, w.free_slots);
  io.i32(w.living_body_count);
  io.section(tag("JOIN"));
  const std::uint32_t joint_slots = io.count(w.joints.size());
  if (IO::reading) {
    w.joints.assign(joint_slots, Joint{});
    w.joint_alive.assign(joint_slots, 0);
  }
  for (std::uint32_t i = 0; i < joint_slots; ++i) {
    io.u8(w.joint_alive[i]);
    io_joint(io, w.joints[i]);
  }
  io_u32_vector(io, w.free_joint_slots);
  io.i32(w.living_joint_count);
  io.section(tag("CONT"));
  io_vector(io, w.contacts, [](IO& inner, Contact& c) { io_contact(inner, c); });
  io.section(tag("SLEE"));
  io_vector(io, w.sleeping_contacts, [](IO& inner, Contact& c) { io_contact(inner, c); });
  io.section(tag("EVNT"));
  io.f32(w.events.hit_event_threshold);
  io.i32(w.events.contact_event_bodies);
  io.i32(w.events.hit_event_bodies);
  io.i32(w.events.sensor_bodies);
  io_pairs(io, w.events.touching);
  io_pairs(io, w.events.sensor_overlaps);
  io_pairs(io, w.events.removed_touches);
  io_pairs(io, w.events.removed_overlaps);
}

}  // namespace

std::vector<std::uint8_t> World::save_snapshot() const {
  std::vector<std::uint8_t> payload;
  Writer payload_writer{payload};
  io_world(payload_writer, *state_);
  std::vector<std::uint8_t> bytes;
  bytes.reserve(payload.size() + 24);
  Writer header{bytes};
  std::uint32_t magic = snapshot_magic;
  std::uint32_t version = snapshot_version;
  std::uint64_t size = payload.size();
  std::uint64_t hash = fnv1a(payload.data(), payload.size());
  header.u32(magic);
  header.u32(version);
  header.u64(size);
  header.u64(hash);
  bytes.insert(bytes.end(), payload.begin(), payload.end());
  return bytes;
}

void World::restore_snapshot(const std::uint8_t* data, std::size_t size) {
  if (data == nullptr && size > 0) throw Error("World::restore_snapshot: null buffer");
  Reader header{data, size};
  std::uint32_t magic, version;
  std::uint64_t payload_size, hash;
  if (size < 24) throw Error("World::restore_snapshot: truncated buffer (" + std::to_string(size) + " bytes, the header alone is 24)");
  header.u32(magic);
  if (magic != snapshot_magic) throw Error("World::restore_snapshot: not an impulse2d snapshot (bad magic number)");
  header.u32(version);
  if (version != snapshot_version) {
    throw Error("World::restore_snapshot: snapshot version " + std::to_string(version) + ", this build reads version " +
                std::to_string(snapshot_version));
  }
  header.u64(payload_size);
  header.u64(hash);
  if (payload_size != size - 24) {
    throw Error("World::restore_snapshot: truncated or padded buffer (payload " + std::to_string(size - 24) +
                " bytes, header says " + std::to_string(payload_size) + ")");
  }
  if (fnv1a(data + 24, size - 24) != hash) {
    throw Error("World::restore_snapshot: corrupt buffer (payload hash mismatch)");
  }
  // Read into a fresh state: a failure leaves this world as it was.
  auto restored = std::make_unique<WorldState>();
  Reader reader{data + 24, size - 24};
  io_world(reader, *restored);
  if (reader.at != reader.size) throw Error("World::restore_snapshot: corrupt buffer (trailing bytes)");
  validate_settings(restored->settings);
  WorldState& w = *restored;
  // Consistency: handles inside the buffer must name living slots.
  auto living = [&w](BodyId id) {
    return id.index < w.bodies.size() && w.alive[id.index] && w.bodies[id.index].id == id;
  };
  for (std::size_t i = 0; i < w.joints.size(); ++i) {
    if (w.joint_alive[i] && !(living(w.joints[i].body_a) && living(w.joints[i].body_b))) {
      throw Error("World::restore_snapshot: corrupt buffer (joint " + std::to_string(i) + " names a dead body)");
    }
  }
  for (const std::vector<Contact>* list : {&w.contacts, &w.sleeping_contacts}) {
    for (const Contact& c : *list) {
      if (!living(c.body_a) || !living(c.body_b)) throw Error("World::restore_snapshot: corrupt buffer (contact names a dead body)");
    }
  }
  for (const std::uint32_t slot : w.free_slots) {
    if (slot >= w.bodies.size() || w.alive[slot]) throw Error("World::restore_snapshot: corrupt buffer (free slot list)");
  }
  for (const std::uint32_t slot : w.free_joint_slots) {
    if (slot >= w.joints.size() || w.joint_alive[slot]) throw Error("World::restore_snapshot: corrupt buffer (free joint slot list)");
  }
  // The broad phase, rebuilt in slot order from the saved bounds; the joints' pair list.
  for (std::uint32_t i = 0; i < w.bodies.size(); ++i) {
    if (w.alive[i]) w.broad_phase.add_body(i, w.bodies[i].type, w.bodies[i].aabb);
  }
  w.rebuild_unconnected_pairs();
  w.contact_filter = state_->contact_filter;  // the restoring world's own
  w.settings.worker_count = state_->settings.worker_count;  // how to run: the restoring world's
  w.settings.task_system = state_->settings.task_system;
  state_ = std::move(restored);
}

void World::restore_snapshot(const std::vector<std::uint8_t>& bytes) { restore_snapshot(bytes.data(), bytes.size()); }

}  // namespace impulse2d
