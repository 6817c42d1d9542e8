/// @file noise_envelope.cpp
#include "golden/noise_envelope.h"

#include "golden/error.h"
#include "golden/json_fields.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace impulse2d::golden {

namespace {

using nlohmann::json;

/// One quantity of a `PhysicsSample`: its JSON key, its name in messages, its unit.
struct Quantity {
  const char* key;
  const char* label;
  const char* unit;
  double PhysicsSample::*field;
};

constexpr Quantity kQuantities[] = {
    {"energy", "energy", "J", &PhysicsSample::energy},
    {"momentum_x", "momentum x", "kg m/s", &PhysicsSample::momentum_x},
    {"momentum_y", "momentum y", "kg m/s", &PhysicsSample::momentum_y},
    {"angular_momentum", "angular momentum", "kg m^2/s", &PhysicsSample::angular_momentum},
};

/// How far outside its envelope an escape is, for ordering: infinite for an unmatched one
/// or from a zero envelope.
double severity(const EnvelopeEscape& escape) {
  if (escape.unmatched || escape.envelope <= 0.0) return std::numeric_limits<double>::infinity();
  return escape.measured / escape.envelope;
}

/// Adds an escape when |actual - golden| exceeds the envelope.
void compare(NoiseVerdict& verdict, const std::string& what, double golden, double actual,
             double envelope, const char* unit, bool body = false) {
  ++verdict.compared;
  const double measured = std::abs(actual - golden);
  if (!(measured <= kNoiseMargin * envelope)) {
    verdict.escapes.push_back({what, measured, envelope, unit, body});
  }
}

}  // namespace

std::vector<std::int64_t> noise_checkpoint_steps(std::int64_t frame, int count) {
  std::vector<std::int64_t> steps;
  if (frame <= 0 || count <= 0) return steps;
  const std::int64_t n = std::min<std::int64_t>(count, frame);
  for (std::int64_t i = 1; i <= n; ++i) steps.push_back(frame * i / n);
  return steps;
}

std::string EnvelopeEscape::describe() const {
  std::ostringstream text;
  if (unmatched) return what;
  const std::string suffix = unit.empty() ? "" : " " + unit;
  text << std::setprecision(3) << what << " off by " << measured << suffix << " (noise envelope "
       << envelope << suffix << ", limit " << kNoiseMargin * envelope << ")";
  return text.str();
}

std::string NoiseVerdict::describe(std::size_t count, const std::string& separator) const {
  if (escapes.empty()) {
    return "every body and quantity inside the noise envelope (" + std::to_string(compared) +
           " compared)";
  }
  std::string quantities;
  std::string bodies;
  std::size_t quantities_named = 0;
  std::size_t bodies_named = 0;
  std::size_t bodies_outside = 0;
  for (const EnvelopeEscape& escape : escapes) {
    std::string& text = escape.body ? bodies : quantities;
    std::size_t& named = escape.body ? bodies_named : quantities_named;
    if (escape.body) ++bodies_outside;
    if (named == count) continue;
    text += (named == 0 ? "" : "; ") + escape.describe();
    ++named;
  }
  std::string text;
  if (!quantities.empty()) {
    text = "quantities: " + quantities + " (" + std::to_string(escapes.size() - bodies_outside) +
           " outside)";
  }
  if (!bodies.empty()) {
    text += (text.empty() ? "bodies: " : separator + "bodies: ") + bodies + " (" +
            std::to_string(bodies_outside) + " outside)";
  }
  return text;
}

NoiseVerdict judge_against_envelope(const NoiseEnvelope& envelope,
                                    const std::vector<BodyPose>& golden_bodies,
                                    const std::vector<BodyPose>& actual_bodies,
                                    const std::vector<PhysicsSample>& actual_samples) {
  NoiseVerdict verdict;
  std::map<std::string, const BodyNoise*> noise_by_name;
  for (const BodyNoise& noise : envelope.bodies) noise_by_name[noise.name] = &noise;
  std::map<std::string, const BodyPose*> actual_by_name;
  for (const BodyPose& pose : actual_bodies) actual_by_name[pose.name] = &pose;

  for (const BodyPose& golden : golden_bodies) {
    const auto actual = actual_by_name.find(golden.name);
    const auto noise = noise_by_name.find(golden.name);
    if (actual == actual_by_name.end()) {
      verdict.escapes.push_back({golden.name + " (missing in this run)", 0.0, 0.0, "", true, true});
      continue;
    }
    const double distance_noise = noise != noise_by_name.end() ? noise->second->distance : 0.0;
    const double rotation_noise = noise != noise_by_name.end() ? noise->second->rotation : 0.0;
    ++verdict.compared;
    const double distance =
        std::hypot(actual->second->x - golden.x, actual->second->y - golden.y);
    if (!(distance <= kNoiseMargin * distance_noise)) {
      verdict.escapes.push_back({golden.name + " position", distance, distance_noise, "m", true});
    }
    compare(verdict, golden.name + " angle", golden.angle, actual->second->angle, rotation_noise,
            "rad", true);
    actual_by_name.erase(actual);
  }
  for (const auto& extra : actual_by_name) {
    verdict.escapes.push_back({extra.first + " (not in the golden run)", 0.0, 0.0, "", true, true});
  }

  std::map<std::int64_t, const PhysicsSample*> actual_by_step;
  for (const PhysicsSample& sample : actual_samples) actual_by_step[sample.step] = &sample;
  for (const NoiseCheckpoint& checkpoint : envelope.checkpoints) {
    const std::string at = " at step " + std::to_string(checkpoint.golden.step);
    const auto found = actual_by_step.find(checkpoint.golden.step);
    if (found == actual_by_step.end()) {
      verdict.escapes.push_back({"physics sample" + at + " (not taken in this run)", 0.0, 0.0,
                                 "", false, true});
      continue;
    }
    for (const Quantity& quantity : kQuantities) {
      compare(verdict, quantity.label + at, checkpoint.golden.*quantity.field,
              found->second->*quantity.field, checkpoint.spread.*quantity.field, quantity.unit);
    }
    compare(verdict, "contact count" + at, checkpoint.golden.contacts, found->second->contacts,
            checkpoint.spread.contacts, "");
  }
  std::stable_sort(verdict.escapes.begin(), verdict.escapes.end(),
                   [](const EnvelopeEscape& a, const EnvelopeEscape& b) {
                     const double sa = severity(a);
                     const double sb = severity(b);
                     if (sa != sb) return sa > sb;
                     return a.measured > b.measured;
                   });
  return verdict;
}

json noise_envelope_to_json(const NoiseEnvelope& envelope) {
  json checkpoints = json::array();
  for (const NoiseCheckpoint& checkpoint : envelope.checkpoints) {
    json item = {{"step", checkpoint.golden.step}};
    for (const Quantity& quantity : kQuantities) {
      item[quantity.key] = checkpoint.golden.*quantity.field;
      item[std::string(quantity.key) + "_noise"] = checkpoint.spread.*quantity.field;
    }
    item["contacts"] = checkpoint.golden.contacts;
    item["contacts_noise"] = checkpoint.spread.contacts;
    checkpoints.push_back(std::move(item));
  }
  json bodies = json::array();
  for (const BodyNoise& body : envelope.bodies) {
    bodies.push_back(
        {{"name", body.name}, {"distance", body.distance}, {"rotation", body.rotation}});
  }
  return {{"perturbations", envelope.perturbations},
          {"checkpoints", std::move(checkpoints)},
          {"bodies", std::move(bodies)}};
}

NoiseEnvelope noise_envelope_from_json(const json& object, const std::string& origin) {
  const FieldReader top(object, origin, "noise.");
  top.reject_unknown({"perturbations", "checkpoints", "bodies"});
  NoiseEnvelope envelope;
  const json& perturbations = top.array("perturbations");
  if (perturbations.empty()) top.fail("perturbations", "must name at least one perturbation");
  for (const json& item : perturbations) {
    if (!item.is_string() || item.get<std::string>().empty()) {
      top.fail("perturbations", "expected non-empty strings, got " + item.dump());
    }
    envelope.perturbations.push_back(item.get<std::string>());
  }
  const json& checkpoints = top.array("checkpoints");
  std::set<std::string> checkpoint_keys = {"step", "contacts", "contacts_noise"};
  for (const Quantity& quantity : kQuantities) {
    checkpoint_keys.insert(quantity.key);
    checkpoint_keys.insert(std::string(quantity.key) + "_noise");
  }
  for (std::size_t i = 0; i < checkpoints.size(); ++i) {
    const FieldReader item(checkpoints[i], origin,
                           "noise.checkpoints[" + std::to_string(i) + "].");
    item.reject_unknown(checkpoint_keys);
    NoiseCheckpoint checkpoint;
    checkpoint.golden.step = item.integer("step", 1);
    if (!envelope.checkpoints.empty() &&
        checkpoint.golden.step <= envelope.checkpoints.back().golden.step) {
      item.fail("step", "checkpoints must be in ascending step order");
    }
    checkpoint.spread.step = checkpoint.golden.step;
    for (const Quantity& quantity : kQuantities) {
      checkpoint.golden.*quantity.field = item.number(quantity.key);
      checkpoint.spread.*quantity.field = item.non_negative(std::string(quantity.key) + "_noise");
    }
    checkpoint.golden.contacts = item.integer("contacts", 0);
    checkpoint.spread.contacts = item.integer("contacts_noise", 0);
    envelope.checkpoints.push_back(checkpoint);
  }
  const json& bodies = top.array("bodies");
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const FieldReader body(bodies[i], origin, "noise.bodies[" + std::to_string(i) + "].");
    body.reject_unknown({"name", "distance", "rotation"});
    envelope.bodies.push_back(
        {body.string("name", false), body.non_negative("distance"), body.non_negative("rotation")});
  }
  return envelope;
}

}  // namespace impulse2d::golden
