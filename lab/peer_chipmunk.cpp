/// @file peer_chipmunk.cpp
/// Chipmunk 7 as a lab peer (compiled only when libchipmunk-dev is installed). Debian's
/// libchipmunk is a debug build: it prints a banner on the first space it creates, which is
/// kept off stdout here.
#include <chipmunk/chipmunk.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fcntl.h>

#include "lab/lab_peers.h"
#include "core/world.h"

namespace impulse2d::lab {
namespace {

/// cpSpaceNew with stdout pointed at /dev/null (the debug build's banner).
cpSpace* new_quiet_space() {
  std::fflush(stdout);
  const int saved = dup(STDOUT_FILENO);
  const int null_device = open("/dev/null", O_WRONLY);
  if (saved >= 0 && null_device >= 0) dup2(null_device, STDOUT_FILENO);
  cpSpace* space = cpSpaceNew();
  std::fflush(stdout);
  if (saved >= 0 && null_device >= 0) dup2(saved, STDOUT_FILENO);
  if (null_device >= 0) close(null_device);
  if (saved >= 0) close(saved);
  return space;
}

class ChipmunkSimulation : public LabSimulation {
 public:
  ChipmunkSimulation(const World& initial, const LabMethod& method)
      : space_(new_quiet_space()), method_(method), gravity_(initial.settings().gravity) {
    const WorldSettings& settings = initial.settings();
    cpSpaceSetGravity(space_, cpv(gravity_.x, gravity_.y));
    cpSpaceSetIterations(space_, method.velocity_iterations);
    cpSpaceSetCollisionSlop(space_, settings.slop);
    friction_on_ = settings.enable_friction;
    restitution_on_ = settings.enable_restitution;
    for (const BodyId id : initial.body_ids()) {
      const BodyView source = initial.body(id);
      cpBody* body = nullptr;
      if (source.type == BodyType::Static) {
        body = cpBodyNewStatic();
      } else if (source.type == BodyType::Kinematic) {
        body = cpBodyNewKinematic();
      } else {
        const double moment = source.inverse_inertia > 0.0f ? source.inertia : INFINITY;
        body = cpBodyNew(source.mass, moment);
      }
      cpSpaceAddBody(space_, body);
      cpBodySetPosition(body, cpv(source.transform.position.x, source.transform.position.y));
      cpBodySetAngle(body, source.angle);
      cpBodySetVelocity(body, cpv(source.linear_velocity.x, source.linear_velocity.y));
      cpBodySetAngularVelocity(body, source.angular_velocity);
      cpShape* shape = nullptr;
      switch (source.shape->type()) {
        case ShapeType::Circle:
          shape = cpCircleShapeNew(body, source.shape->circle().radius, cpvzero);
          break;
        case ShapeType::Box:
          shape = cpBoxShapeNew(body, 2.0 * source.shape->box().half_extents.x,
                                2.0 * source.shape->box().half_extents.y, 0.0);
          break;
        case ShapeType::Polygon: {
          cpVect vertices[max_polygon_vertices];
          for (int i = 0; i < source.shape->polygon().count; ++i) {
            const vec2 v = source.shape->polygon().vertices[static_cast<std::size_t>(i)];
            vertices[i] = cpv(v.x, v.y);
          }
          shape = cpPolyShapeNewRaw(body, source.shape->polygon().count, vertices, 0.0);
          break;
        }
      }
      cpShapeSetFriction(shape, friction_on_ ? source.material->static_friction : 0.0);
      cpShapeSetElasticity(shape, restitution_on_ ? source.material->restitution : 0.0);
      cpSpaceAddShape(space_, shape);
      bodies_.push_back(body);
      shapes_.push_back(shape);
      materials_.push_back(*source.material);
      dynamic_.push_back(source.type == BodyType::Dynamic);
      rotates_.push_back(source.inverse_inertia > 0.0f);
    }
  }
  ~ChipmunkSimulation() override {
    // The space goes first (its teardown only wakes its bodies): removing shapes one at a time
    // filters every cached arbiter for each, quadratic in the body count (5 s for 10,000 boxes).
    cpSpaceFree(space_);
    for (cpShape* shape : shapes_) cpShapeFree(shape);
    for (cpBody* body : bodies_) cpBodyFree(body);
  }
  ChipmunkSimulation(const ChipmunkSimulation&) = delete;
  ChipmunkSimulation& operator=(const ChipmunkSimulation&) = delete;

  void step() override { cpSpaceStep(space_, method_.time_step); }
  float time_step() const override { return method_.time_step; }
  vec2 gravity() const override { return gravity_; }
  int body_count() const override { return static_cast<int>(bodies_.size()); }
  void read_states(std::vector<BodyState>& states) const override {
    states.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      cpBody* body = bodies_[i];
      BodyState& state = states[i];
      const cpVect position = cpBodyGetPosition(body);
      const cpVect velocity = cpBodyGetVelocity(body);
      state.position = {static_cast<float>(position.x), static_cast<float>(position.y)};
      state.angle = static_cast<float>(cpBodyGetAngle(body));
      state.velocity = {static_cast<float>(velocity.x), static_cast<float>(velocity.y)};
      state.angular_velocity = static_cast<float>(cpBodyGetAngularVelocity(body));
      state.dynamic = dynamic_[i];
      state.mass = dynamic_[i] ? static_cast<float>(cpBodyGetMass(body)) : 0.0f;
      state.inertia = dynamic_[i] && rotates_[i] ? static_cast<float>(cpBodyGetMoment(body)) : 0.0f;
    }
  }
  ContactCoefficients coefficients(int a, int b) const override {
    const Material& first = materials_.at(static_cast<std::size_t>(a));
    const Material& second = materials_.at(static_cast<std::size_t>(b));
    ContactCoefficients result;
    const float friction = friction_on_ ? first.static_friction * second.static_friction : 0.0f;
    result.static_friction = friction;
    result.dynamic_friction = friction;
    result.restitution = restitution_on_ ? first.restitution * second.restitution : 0.0f;
    return result;
  }
  unsigned long long state_hash() const override {
    std::vector<BodyState> states;
    read_states(states);
    return hash_states(states);
  }
  void place_body(int index, vec2 position, vec2 velocity) override {
    cpBody* body = bodies_.at(static_cast<std::size_t>(index));
    cpBodySetPosition(body, cpv(position.x, position.y));
    cpBodySetAngle(body, 0.0);
    cpBodySetVelocity(body, cpv(velocity.x, velocity.y));
    cpBodySetAngularVelocity(body, 0.0);
  }

 private:
  cpSpace* space_;
  LabMethod method_;
  vec2 gravity_;
  std::vector<cpBody*> bodies_;
  std::vector<cpShape*> shapes_;
  std::vector<Material> materials_;
  std::vector<bool> dynamic_;
  std::vector<bool> rotates_;
  bool friction_on_ = true;
  bool restitution_on_ = true;
};

}  // namespace

std::unique_ptr<LabSimulation> make_chipmunk_simulation(const World& initial,
                                                        const LabMethod& method) {
  return std::make_unique<ChipmunkSimulation>(initial, method);
}

}  // namespace impulse2d::lab
