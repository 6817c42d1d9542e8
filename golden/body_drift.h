#pragma once
/// @file body_drift.h
/// Which bodies moved most between the golden's physics state and this run's, so a
/// *simulation diverged* failure can point at them.

#include <cstddef>
#include <string>
#include <vector>

namespace impulse2d::golden {

/// A body's pose at a golden frame, as recorded in the sidecar.
struct BodyPose {
  std::string name;    ///< stable label, e.g. "body 3" or "box left"
  double x = 0.0;      ///< centre of mass x, metres
  double y = 0.0;      ///< centre of mass y, metres
  double angle = 0.0;  ///< rotation, radians
};

/// How far one body is from where the golden run had it.
struct BodyDrift {
  std::string name;       ///< the body's label
  double distance = 0.0;  ///< |actual - golden| centre of mass, metres
  double rotation = 0.0;  ///< |actual - golden| angle, radians
  std::string note;       ///< "only in golden" / "only in actual" when unmatched, else empty
};

/// True when the poses are named by world slot ("body 7", "body 7 (generation 2)"), as
/// sidecars before issue 29 name them, rather than by creation order ("body #7", "ball (#3)").
bool is_slot_named(const std::vector<BodyPose>& poses);

/// The `count` bodies that drifted most, bodies matched by name. Unmatched bodies come
/// first, then by distance, then by rotation, descending; bodies that did not move at all
/// are left out.
std::vector<BodyDrift> largest_drifts(const std::vector<BodyPose>& golden,
                                      const std::vector<BodyPose>& actual, std::size_t count);

/// "box 3 moved 0.42 m, turned 0.1 rad; ..." (3 significant digits) for failure messages;
/// "no body moved" when the list is empty.
std::string describe_drifts(const std::vector<BodyDrift>& drifts);

}  // namespace impulse2d::golden
