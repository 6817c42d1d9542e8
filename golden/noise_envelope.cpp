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
double severity(const EnvelopeEscape& escape) { return escape.severity(); }

/// Adds an escape when |actual - golden| exceeds the envelope.
void compare(NoiseVerdict& verdict, const std::string& what, double golden, double actual,
             double envelope, const char* unit, bool body = false) {
  ++verdict.compared;
  const double measured = std::abs(actual - golden);
  if (!(measured <= kNoiseMargin * envelope)) {
    EnvelopeEscape escape{what, measured, envelope, unit, body};
    escape.reference = body ? 0.0 : golden;
    verdict.escapes.push_back(std::move(escape));
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

double EnvelopeEscape::severity() const {
  if (unmatched) return std::numeric_limits<double>::infinity();
  const double floor = 1e-6 * (1.0 + std::abs(reference));
  return measured / std::max(envelope, floor);
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
  std::string text;
  for (std::size_t i = 0; i < escapes.size() && i < count; ++i) {
    text += (i == 0 ? "" : separator) + std::to_string(i + 1) + ". " + escapes[i].describe();
  }
  if (escapes.size() > count) {
    std::size_t bodies = 0;
    for (std::size_t i = count; i < escapes.size(); ++i) bodies += escapes[i].body ? 1 : 0;
    const std::size_t more = escapes.size() - count;
    text += separator + "(" + std::to_string(more) + " more outside the envelope: " +
            std::to_string(bodies) + (bodies == 1 ? " body, " : " bodies, ") +
            std::to_string(more - bodies) + (more - bodies == 1 ? " quantity)" : " quantities)");
  }
  return text;
}

std::string NoiseVerdict::describe_cannot_tell() const {
  std::ostringstream text;
  const double spread = envelope_reach / kNoiseMargin;
  text << std::setprecision(3) << "cannot tell at this frame: the run stayed inside the noise "
       << "envelope, but ";
  if (spread * kNoiseMargin > bound) {
    text << "rounding alone (the perturbed runs) already moves bodies up to " << spread
         << " m here (limit " << envelope_reach << " m), ";
  }
  text << "and this run moved " << (largest_move_body.empty() ? "no body" : largest_move_body)
       << " " << largest_move << " m; the bound within which a change is called noise is "
       << bound << " m (1 % of the scene's size, " << scene_scale << " m)";
  if (!unsampled_living_set.empty()) {
    text << "; which bodies are alive differs (" << unsampled_living_set.front();
    if (unsampled_living_set.size() > 1) text << " and " << unsampled_living_set.size() - 1 << " more";
    text << "), and rounding alone already changes which bodies this scene has removed by this "
            "frame, in ways its eight perturbed runs do not all show";
  }
  if (stops_telling_step >= 0) {
    text << "; the scene amplifies rounding beyond that bound from step " << stops_telling_step;
    if (last_telling_step >= 0) {
      text << ", and a frame at step " << last_telling_step << " or earlier still tells";
    } else {
      text << " on, so no earlier checkpoint tells either";
    }
  } else if (!spread_recorded) {
    text << "; this sidecar does not record from which step the scene stops telling "
            "(re-promote it to record that)";
  }
  return text.str();
}

NoiseVerdict judge_against_envelope(const NoiseEnvelope& envelope,
                                    const std::vector<BodyPose>& golden_bodies,
                                    const std::vector<BodyPose>& actual_bodies,
                                    const std::vector<PhysicsSample>& actual_samples) {
  NoiseVerdict verdict;
  std::map<std::string, const BodyNoise*> noise_by_name;
  for (const BodyNoise& noise : envelope.bodies) noise_by_name[noise.name] = &noise;
  const std::set<std::string> extra_bodies(envelope.extra_bodies.begin(),
                                           envelope.extra_bodies.end());
  // Does rounding alone already change which bodies are alive at the frame?
  bool living_set_varies = !extra_bodies.empty();
  for (const BodyNoise& noise : envelope.bodies) living_set_varies |= noise.may_be_missing;
  std::map<std::string, const BodyPose*> actual_by_name;
  for (const BodyPose& pose : actual_bodies) actual_by_name[pose.name] = &pose;

  // The scene's size: the box around the golden's bodies.
  if (!golden_bodies.empty()) {
    double min_x = golden_bodies[0].x, max_x = min_x, min_y = golden_bodies[0].y, max_y = min_y;
    for (const BodyPose& pose : golden_bodies) {
      min_x = std::min(min_x, pose.x);
      max_x = std::max(max_x, pose.x);
      min_y = std::min(min_y, pose.y);
      max_y = std::max(max_y, pose.y);
    }
    verdict.scene_scale = std::max(1.0, std::hypot(max_x - min_x, max_y - min_y));
  }
  verdict.bound = kNoiseBoundFraction * verdict.scene_scale;

  for (const BodyPose& golden : golden_bodies) {
    const auto actual = actual_by_name.find(golden.name);
    const auto noise = noise_by_name.find(golden.name);
    const double distance_noise = noise != noise_by_name.end() ? noise->second->distance : 0.0;
    verdict.envelope_reach = std::max(verdict.envelope_reach, kNoiseMargin * distance_noise);
    if (actual == actual_by_name.end()) {
      // Removed earlier in this run: noise when some perturbed run removed it too.
      if (noise == noise_by_name.end() || !noise->second->may_be_missing) {
        if (living_set_varies) {
          verdict.unsampled_living_set.push_back(golden.name + " (removed in this run only)");
        } else {
          verdict.escapes.push_back(
              {golden.name + " (missing in this run)", 0.0, 0.0, "", true, true});
        }
      }
      ++verdict.compared;
      continue;
    }
    const double rotation_noise = noise != noise_by_name.end() ? noise->second->rotation : 0.0;
    ++verdict.compared;
    const double distance =
        std::hypot(actual->second->x - golden.x, actual->second->y - golden.y);
    if (distance > verdict.largest_move) {
      verdict.largest_move = distance;
      verdict.largest_move_body = golden.name;
    }
    if (!(distance <= kNoiseMargin * distance_noise)) {
      verdict.escapes.push_back({golden.name + " position", distance, distance_noise, "m", true});
    }
    compare(verdict, golden.name + " angle", golden.angle, actual->second->angle, rotation_noise,
            "rad", true);
    actual_by_name.erase(actual);
  }
  for (const auto& extra : actual_by_name) {
    ++verdict.compared;
    if (extra_bodies.count(extra.first) != 0) continue;  // some perturbed run had it too
    if (living_set_varies) {
      verdict.unsampled_living_set.push_back(extra.first + " (alive in this run only)");
      continue;
    }
    verdict.escapes.push_back({extra.first + " (not in the golden run)", 0.0, 0.0, "", true, true});
  }

  std::map<std::int64_t, const PhysicsSample*> actual_by_step;
  for (const PhysicsSample& sample : actual_samples) actual_by_step[sample.step] = &sample;
  std::int64_t previous_step = -1;
  for (const NoiseCheckpoint& checkpoint : envelope.checkpoints) {
    if (checkpoint.body_spread >= 0.0) {
      verdict.spread_recorded = true;
      if (verdict.stops_telling_step < 0 &&
          kNoiseMargin * checkpoint.body_spread > verdict.bound) {
        verdict.stops_telling_step = checkpoint.golden.step;
        verdict.last_telling_step = previous_step;
      }
    }
    previous_step = checkpoint.golden.step;
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
    if (checkpoint.golden.bodies >= 0 && found->second->bodies >= 0) {
      compare(verdict, "living bodies" + at, checkpoint.golden.bodies, found->second->bodies,
              checkpoint.spread.bodies, "");
    }
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
    if (checkpoint.golden.bodies >= 0) {
      item["bodies"] = checkpoint.golden.bodies;
      item["bodies_noise"] = std::max(checkpoint.spread.bodies, 0);
    }
    if (checkpoint.body_spread >= 0.0) item["body_spread"] = checkpoint.body_spread;
    checkpoints.push_back(std::move(item));
  }
  json bodies = json::array();
  for (const BodyNoise& body : envelope.bodies) {
    json item = {{"name", body.name}, {"distance", body.distance}, {"rotation", body.rotation}};
    if (body.may_be_missing) item["may_be_missing"] = true;
    bodies.push_back(std::move(item));
  }
  json object = {{"perturbations", envelope.perturbations},
                 {"checkpoints", std::move(checkpoints)},
                 {"bodies", std::move(bodies)}};
  if (!envelope.extra_bodies.empty()) object["extra_bodies"] = envelope.extra_bodies;
  return object;
}

NoiseEnvelope noise_envelope_from_json(const json& object, const std::string& origin) {
  const FieldReader top(object, origin, "noise.");
  top.reject_unknown({"perturbations", "checkpoints", "bodies", "extra_bodies"});
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
  std::set<std::string> checkpoint_keys = {"step",   "contacts",     "contacts_noise",
                                           "bodies", "bodies_noise", "body_spread"};
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
    if (item.has("bodies")) {
      checkpoint.golden.bodies = item.integer("bodies", 0);
      checkpoint.spread.bodies = item.integer("bodies_noise", 0);
    }
    if (item.has("body_spread")) checkpoint.body_spread = item.non_negative("body_spread");
    envelope.checkpoints.push_back(checkpoint);
  }
  const json& bodies = top.array("bodies");
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const FieldReader body(bodies[i], origin, "noise.bodies[" + std::to_string(i) + "].");
    body.reject_unknown({"name", "distance", "rotation", "may_be_missing"});
    BodyNoise noise{body.string("name", false), body.non_negative("distance"),
                    body.non_negative("rotation")};
    if (body.has("may_be_missing")) {
      const json& flag = body.get("may_be_missing");
      if (!flag.is_boolean()) body.fail("may_be_missing", "expected true or false, got " + flag.dump());
      noise.may_be_missing = flag.get<bool>();
    }
    envelope.bodies.push_back(std::move(noise));
  }
  if (top.has("extra_bodies")) {
    for (const json& item : top.array("extra_bodies")) {
      if (!item.is_string() || item.get<std::string>().empty()) {
        top.fail("extra_bodies", "expected non-empty strings, got " + item.dump());
      }
      envelope.extra_bodies.push_back(item.get<std::string>());
    }
  }
  return envelope;
}

}  // namespace impulse2d::golden
