#pragma once
/// @file scene_limits.h
/// The ranges a scene file's physical values must lie in, and why. Values outside them are
/// not wrong JSON but physically meaningless for a float engine: they are accepted by the
/// arithmetic and then freeze, explode or vanish without a word, so the loader rejects them
/// with the JSON path, the range and the reason (README, "Limits").

#include <cstddef>
#include <cstdint>

namespace impulse2d::demos::limits {

/// Smallest size (radius, half extent, polygon extent), m: the solver's slop is 1 cm and
/// its position tolerance about 1 mm; a smaller body sinks through contacts or jitters.
constexpr float min_size = 1e-3f;
/// Largest size and largest polygon vertex coordinate, m.
constexpr float max_size = 1e3f;
/// Why sizes have their range.
constexpr const char* size_reason =
    "m; below 1 mm the solver's 1 cm slop swallows the body, above 1 km float positions lose "
    "millimetres";

/// Largest |coordinate| of a position or a camera point, m: a float resolves 1 mm up to
/// about 16 km; beyond 10 km contacts lose their sub-millimetre precision.
constexpr float max_coordinate = 1e4f;
/// Why positions have their range.
constexpr const char* coordinate_reason = "m; float positions resolve 1 mm only up to ~16 km";

/// Most points of one chain (`make_chain`'s limit): each link is a static body.
constexpr std::size_t max_chain_points = 100000;

/// Smallest side of a camera's view rectangle, m (the smallest body fills it).
constexpr float min_view_side = 1e-3f;
/// Camera scale range, pixels per metre, after any zoom: beyond it a metre of world is less
/// than 1/10000 pixel or more than 10 million pixels, and screen coordinates lose float
/// precision or overflow.
constexpr float min_pixels_per_metre = 1e-4f;
/// Largest camera scale, pixels per metre.
constexpr float max_pixels_per_metre = 1e7f;
/// Why camera scales have their range.
constexpr const char* pixels_per_metre_reason =
    "pixels per metre; beyond it screen coordinates lose float precision or overflow";

/// Density range for a body that has mass, kg/m^2 (0 is allowed for static bodies only).
/// 1e-3..1e5 keeps masses and inertias finite as floats for every allowed size; the solver
/// converges for mass ratios up to about 1e3 between touching bodies.
constexpr float min_density = 1e-3f;
/// Largest density, kg/m^2.
constexpr float max_density = 1e5f;
/// Why densities have their range.
constexpr const char* density_reason =
    "kg/m^2; outside it masses and inertias leave float range for some sizes, and touching "
    "bodies beyond a 1e3 mass ratio do not converge";

/// Time step range, s: below 1e-5 s a step's velocity change g dt is lost in float rounding
/// of typical speeds; above 0.1 s contacts and continuous collision are meaningless.
constexpr float min_time_step = 1e-5f;
/// Largest time step, s.
constexpr float max_time_step = 0.1f;
/// Why the time step has its range.
constexpr const char* time_step_reason =
    "s; below it g dt vanishes in float rounding, above it contacts are missed";

/// Largest |gravity| component, m/s^2 (100 g).
constexpr float max_gravity = 1e3f;
/// Why gravity has its range.
constexpr const char* gravity_reason = "m/s^2 per component, 100 g; beyond it a step of "
                                       "free fall outruns the contact solver";

/// Largest |velocity| component, m/s, and |angular velocity|, rad/s.
constexpr float max_speed = 1e4f;
/// Why speeds have their range.
constexpr const char* speed_reason = "m/s or rad/s; beyond it one step moves a body kilometres";

/// Largest |impulse| component of an event, N s.
constexpr float max_impulse = 1e7f;
/// Why impulses have their range.
constexpr const char* impulse_reason = "N s; beyond it the body leaves float range";

/// Largest |force| component and |torque| of a force event, N and N m: one step's push F dt
/// (dt up to 0.1 s) then stays within the impulse limit.
constexpr float max_force = 1e8f;
/// Why forces have their range.
constexpr const char* force_reason =
    "N or N m; beyond it one step's push F dt exceeds the 1e7 N s impulse limit";
/// Most steps a force event may last (the longest run).
constexpr std::int64_t max_force_steps = 100000000;

/// Largest |gravity_scale|.
constexpr float max_gravity_scale = 100.0f;
/// Largest damping, 1/s.
constexpr float max_damping = 1e3f;

/// Largest scene file, bytes (4 MiB): the largest built-in scene file is under 4 KiB.
constexpr long long max_scene_file_bytes = 4ll * 1024 * 1024;

}  // namespace impulse2d::demos::limits
