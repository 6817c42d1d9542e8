/// @file body_drift.cpp
#include "golden/body_drift.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace impulse2d::golden {

bool is_slot_named(const std::vector<BodyPose>& poses) {
  for (const BodyPose& pose : poses) {
    if (pose.name.rfind("body ", 0) == 0 && pose.name.size() > 5 &&
        pose.name[5] >= '0' && pose.name[5] <= '9') {
      return true;
    }
  }
  return false;
}

std::vector<BodyDrift> largest_drifts(const std::vector<BodyPose>& golden,
                                      const std::vector<BodyPose>& actual, std::size_t count) {
  std::map<std::string, const BodyPose*> actual_by_name;
  for (const BodyPose& pose : actual) actual_by_name[pose.name] = &pose;

  std::vector<BodyDrift> drifts;
  for (const BodyPose& expected : golden) {
    auto found = actual_by_name.find(expected.name);
    if (found == actual_by_name.end()) {
      drifts.push_back({expected.name, 0.0, 0.0, "only in golden"});
      continue;
    }
    const BodyPose& now = *found->second;
    actual_by_name.erase(found);
    const double distance = std::hypot(now.x - expected.x, now.y - expected.y);
    const double rotation = std::abs(now.angle - expected.angle);
    if (distance > 0.0 || rotation > 0.0) {
      drifts.push_back({expected.name, distance, rotation, ""});
    }
  }
  for (const auto& unmatched : actual_by_name) {
    drifts.push_back({unmatched.first, 0.0, 0.0, "only in actual"});
  }

  std::stable_sort(drifts.begin(), drifts.end(), [](const BodyDrift& a, const BodyDrift& b) {
    if (a.note.empty() != b.note.empty()) return !a.note.empty();
    if (a.distance != b.distance) return a.distance > b.distance;
    return a.rotation > b.rotation;
  });
  if (drifts.size() > count) drifts.resize(count);
  return drifts;
}

std::string describe_drifts(const std::vector<BodyDrift>& drifts) {
  if (drifts.empty()) return "no body moved";
  std::ostringstream text;
  text << std::setprecision(3);  // "0.000678 m", "24.2 m": enough to tell drifts apart
  for (std::size_t i = 0; i < drifts.size(); ++i) {
    const BodyDrift& drift = drifts[i];
    if (i > 0) text << "; ";
    text << drift.name;
    if (!drift.note.empty()) {
      text << " " << drift.note;
    } else {
      text << " moved " << drift.distance << " m, turned " << drift.rotation << " rad";
    }
  }
  return text.str();
}

}  // namespace impulse2d::golden
