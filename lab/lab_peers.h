#pragma once
/// @file lab_peers.h
/// Making a `LabSimulation` for any method: impulse2d itself, or a peer engine (Box2D 2.4.1,
/// Chipmunk 7.0.3) built from the same scene. Peers are compiled in when their Debian packages
/// (libbox2d-dev, libchipmunk-dev) were found at configure time.
///
/// A peer gets the scene's bodies as impulse2d built them (shapes, poses, velocities, masses,
/// one friction coefficient mu = mu_s per body, restitution), the scene's gravity and time step,
/// and its own mixing rules: Box2D sqrt(a b) friction and max restitution, Chipmunk a*b for
/// both. Chipmunk's collision slop is set to the scene's slop; everything else is the peer's
/// default. The scene's joints are built in the peer with the same anchors, axes, reference
/// angles, lengths, limits, motors and springs (a spring of f Hz and damping ratio z becomes
/// the stiffness m (2 pi f)^2 and damping 2 m z (2 pi f) of the bodies' reduced mass m, as
/// Box2D's b2LinearStiffness computes them); a joint the peer lacks fails that scenario's run
/// with "... not supported by <peer>", it is never dropped. A chain link (a one-sided segment
/// with ghost vertices) is a one-sided b2EdgeShape in Box2D (its points reversed: Box2D's edge
/// faces the right of v1 -> v2, impulse2d's link the left of point1 -> point2) and a two-sided
/// segment with cpSegmentShapeSetNeighbors in Chipmunk, which has no one-sided segment.

#include <memory>
#include <string>
#include <vector>

#include "lab/lab_method.h"
#include "lab/lab_simulation.h"

namespace impulse2d {
class World;
}

namespace impulse2d::lab {

/// True when `engine` was compiled in (impulse2d always is).
bool engine_available(Engine engine);

/// Why a peer is missing ("libbox2d-dev was not found when the project was configured; run
/// scripts/setup.sh"), or a note about it (Chipmunk: Debian's build is a debug build), or "".
std::string engine_note(Engine engine);

/// A run of `scene` by `method`'s engine. Throws `demos::UsageError` when the scene cannot be
/// built, `std::runtime_error` when the engine is not compiled in.
std::unique_ptr<LabSimulation> make_simulation(const demos::Scene& scene, const LabMethod& method);

/// Box2D 2.4.1 stepping a copy of `initial` and `joints` (defined only when Box2D is compiled
/// in). A joint Box2D 2.4.1 cannot model (a revolute or prismatic spring, a distance motor, a
/// weld's linear spring) throws `std::runtime_error` "... not supported by Box2D 2.4.1".
std::unique_ptr<LabSimulation> make_box2d_simulation(const World& initial,
                                                     const std::vector<LabJoint>& joints,
                                                     const LabMethod& method);

/// Chipmunk 7 stepping a copy of `initial` and `joints` (defined only when Chipmunk is compiled
/// in). A joint Chipmunk cannot model (wheel, motor, mouse; a prismatic motor or spring, a
/// distance motor, a weld spring) throws `std::runtime_error` "... not supported by Chipmunk
/// 7.0.3".
std::unique_ptr<LabSimulation> make_chipmunk_simulation(const World& initial,
                                                        const std::vector<LabJoint>& joints,
                                                        const LabMethod& method);

/// A 64-bit FNV-1a hash over positions, angles and velocities of `states`, for peers.
unsigned long long hash_states(const std::vector<BodyState>& states);

}  // namespace impulse2d::lab
