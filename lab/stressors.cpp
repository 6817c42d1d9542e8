/// @file stressors.cpp
#include "lab/stressors.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace impulse2d::lab {
namespace {

using nlohmann::json;

json material(double density, double restitution, double static_friction, double dynamic_friction) {
  return {{"density", density},
          {"restitution", restitution},
          {"static_friction", static_friction},
          {"dynamic_friction", dynamic_friction}};
}

json static_box(const std::string& name, double x, double y, double half_x, double half_y,
                const json& surface) {
  return {{"name", name},
          {"type", "static"},
          {"shape", {{"type", "box"}, {"half_extents", {half_x, half_y}}}},
          {"position", {x, y}},
          {"material", surface}};
}

LabScenario scenario(const std::string& name, double duration, json metric, json scene) {
  json document = {{"description", name},
                   {"answer", "see the stressor"},
                   {"duration", duration},
                   {"metric", std::move(metric)},
                   {"scene", std::move(scene)}};
  return parse_lab_scenario(document.dump(), name + ".json");
}

json rest_metric(double threshold) {
  return {{"kind", "rest"}, {"unit", "m"}, {"threshold", threshold}, {"meaning", "distance out of place"}};
}

LabScenario stack(int height, double duration) {
  const json wood = material(0.3, 0.0, 0.5, 0.3);
  json bodies = json::array({static_box("ground", 0, -0.5, 10, 0.5, wood)});
  for (int i = 0; i < height; ++i) {
    bodies.push_back({{"shape", {{"type", "oriented_box"}, {"half_extents", {0.25, 0.25}}}},
                      {"position", {0.0, 0.25 + 0.5 * i}},
                      {"material", wood}});
  }
  return scenario("stack_" + std::to_string(height), duration, rest_metric(0.01 * height + 0.01),
                  {{"model", {{"shapes", {"box", "polygon"}}, {"rotation", true}, {"friction", true},
                              {"restitution", false}}},
                   {"bodies", bodies}});
}

/// A chain of 20 discs (radius 0.1 m, 0.25 m apart) hanging at rest from a static pivot on
/// revolute joints, its last link `load` times as dense as the others; the joints' largest
/// anchor separation over the run's last second (at rest) must stay within `threshold` metres.
LabScenario hanging_chain(double load, double duration, double threshold) {
  const json link = material(1.0, 0.0, 0.5, 0.3);
  json bodies = json::array({{{"name", "pivot"}, {"type", "static"},
                              {"shape", {{"type", "circle"}, {"radius", 0.05}}},
                              {"position", {0.0, 0.0}}, {"material", material(0.0, 0.0, 0.5, 0.3)}}});
  json joints = json::array();
  for (int i = 0; i < 20; ++i) {
    bodies.push_back({{"shape", {{"type", "circle"}, {"radius", 0.1}}},
                      {"position", {0.0, -0.25 * (i + 1)}},
                      {"material", i == 19 ? material(load, 0.0, 0.5, 0.3) : link}});
    joints.push_back({{"type", "revolute"}, {"bodies", {i, i + 1}},
                      {"anchor", {0.0, i == 0 ? 0.0 : -0.25 * i - 0.125}}});
  }
  return scenario("hanging_chain", duration,
                  {{"kind", "joint_drift"}, {"unit", "m"}, {"threshold", threshold},
                   {"after", duration - 1.0},
                   {"meaning", "largest anchor separation of the chain's joints over the last second"}},
                  {{"model", {{"shapes", {"circle"}}, {"rotation", true}, {"friction", false},
                              {"restitution", false}}},
                   {"bodies", bodies},
                   {"joints", joints}});
}

}  // namespace

std::vector<Stressor> stressors(bool quick) {
  const double long_run = quick ? 5.0 : 30.0;
  const double short_run = quick ? 3.0 : 10.0;
  std::vector<Stressor> list;

  Stressor height;
  height.name = "stack_height";
  height.question = "a stack of n 0.5 m boxes stands " + std::to_string(static_cast<int>(long_run)) +
                    " s (every box within the slop per contact + 1 cm of its start)";
  height.unit = "boxes";
  height.ladder = quick ? std::vector<double>{2, 5, 10, 20, 30}
                        : std::vector<double>{2, 4, 6, 8, 10, 12, 15, 20, 25, 30, 40};
  height.integer = true;
  height.scenarios = [long_run](double value) {
    return std::vector<LabScenario>{stack(static_cast<int>(value), long_run)};
  };
  list.push_back(height);

  Stressor ratio;
  ratio.name = "mass_ratio";
  ratio.question = "a box r times heavier rests on a light one (both within 3 cm of their start)";
  ratio.unit = "x";
  ratio.ladder = {1, 3, 10, 30, 100, 300, 1000, 3000, 10000};
  ratio.scenarios = [short_run](double value) {
    const json wood = material(0.3, 0.0, 0.5, 0.3);
    json bodies = json::array(
        {static_box("ground", 0, -0.5, 10, 0.5, wood),
         {{"shape", {{"type", "oriented_box"}, {"half_extents", {0.5, 0.25}}}},
          {"position", {0.0, 0.25}}, {"material", wood}},
         {{"shape", {{"type", "oriented_box"}, {"half_extents", {0.5, 0.25}}}},
          {"position", {0.0, 0.75}}, {"material", material(0.3 * value, 0.0, 0.5, 0.3)}}});
    return std::vector<LabScenario>{scenario(
        "mass_ratio", short_run, rest_metric(0.03),
        {{"model", {{"shapes", {"box", "polygon"}}, {"rotation", true}, {"friction", true},
                    {"restitution", false}}},
         {"bodies", bodies}})};
  };
  list.push_back(ratio);

  Stressor bullet;
  bullet.name = "bullet_speed";
  bullet.question = "a 0.1 m ball (marked bullet) flying at a 0.1 m thick wall stays on its side";
  bullet.unit = "m/s";
  bullet.ladder = {1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048};
  bullet.scenarios = [](double value) {
    const json hard = material(1.0, 0.0, 0.0, 0.0);
    json bodies = json::array(
        {static_box("wall", 0, 0, 0.05, 2, hard),
         {{"name", "ball"}, {"shape", {{"type", "circle"}, {"radius", 0.1}}},
          {"position", {-3.0, 0.0}}, {"velocity", {value, 0.0}}, {"bullet", true},
          {"material", hard}}});
    return std::vector<LabScenario>{scenario(
        "bullet", 0.5,
        {{"kind", "tunnel"}, {"body", "ball"}, {"surface", "wall"}, {"unit", "m"},
         {"threshold", 0.05}, {"meaning", "how far the ball's centre ended beyond the wall's centre"}},
        {{"settings", {{"gravity", {0, 0}}, {"max_linear_speed", 10000}}},
         {"model", {{"shapes", {"circle", "box"}}, {"rotation", false}, {"friction", false},
                    {"restitution", false}, {"ccd", true}}},
         {"bodies", bodies}})};
  };
  list.push_back(bullet);

  Stressor step;
  step.name = "time_step";
  step.question = "a stack of 10 boxes stands " + std::to_string(static_cast<int>(short_run)) +
                  " s at this time step";
  step.unit = "ms";
  step.ladder = {1000.0 / 240, 1000.0 / 120, 1000.0 / 60, 1000.0 / 30, 1000.0 / 20, 1000.0 / 15,
                 1000.0 / 10};
  step.sets_time_step = true;
  step.scenarios = [short_run](double) { return std::vector<LabScenario>{stack(10, short_run)}; };
  list.push_back(step);

  Stressor overlap;
  overlap.name = "initial_overlap";
  overlap.question = "two 1 m boxes built overlapping by d (no gravity) separate without either "
                     "exceeding 1 m/s";
  overlap.unit = "m";
  overlap.ladder = {0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.45};
  overlap.scenarios = [](double value) {
    const json wood = material(0.3, 0.0, 0.5, 0.3);
    json bodies = json::array(
        {{{"shape", {{"type", "box"}, {"half_extents", {0.5, 0.5}}}},
          {"position", {-0.5 + value / 2, 0.0}}, {"material", wood}},
         {{"shape", {{"type", "box"}, {"half_extents", {0.5, 0.5}}}},
          {"position", {0.5 - value / 2, 0.0}}, {"material", wood}}});
    return std::vector<LabScenario>{scenario(
        "overlap", 2.0,
        {{"kind", "peak_speed"}, {"unit", "m/s"}, {"threshold", 1.0},
         {"meaning", "largest speed reached while separating"}},
        {{"settings", {{"gravity", {0, 0}}}},
         {"model", {{"shapes", {"box"}}, {"rotation", false}, {"friction", true},
                    {"restitution", false}}},
         {"bodies", bodies}})};
  };
  list.push_back(overlap);

  Stressor pile;
  pile.name = "elastic_pile";
  pile.question = "n elastic discs (e = 1) bouncing in a closed box under gravity keep their "
                  "energy within 5 % for " + std::to_string(static_cast<int>(short_run)) + " s";
  pile.unit = "discs";
  pile.ladder = {1, 2, 4, 8, 16, 32};
  pile.integer = true;
  pile.scenarios = [short_run](double value) {
    const json elastic = material(1.0, 1.0, 0.0, 0.0);
    json bodies = json::array({static_box("floor", 0, -0.5, 5, 0.5, elastic),
                               static_box("roof", 0, 10.5, 5, 0.5, elastic),
                               static_box("left", -5.5, 5, 0.5, 5.5, elastic),
                               static_box("right", 5.5, 5, 0.5, 5.5, elastic)});
    const int count = static_cast<int>(value);
    for (int i = 0; i < count; ++i) {
      const double x = -3.5 + (i % 8);
      const double y = 2.0 + 1.0 * (i / 8) + 0.3 * (i % 3);
      bodies.push_back({{"shape", {{"type", "circle"}, {"radius", 0.3}}},
                        {"position", {x, y}},
                        {"velocity", {1.5 * std::cos(i * 1.7), 2.0 * std::sin(i * 2.3)}},
                        {"material", elastic}});
    }
    return std::vector<LabScenario>{scenario(
        "elastic_pile", short_run,
        {{"kind", "energy"}, {"unit", "%"}, {"threshold", 5.0},
         {"meaning", "largest change of mechanical energy, percent"}},
        {{"settings", {{"restitution_threshold", 0}}},
         {"model", {{"shapes", {"circle", "box"}}, {"rotation", false}, {"friction", false},
                    {"restitution", true}}},
         {"bodies", bodies}})};
  };
  list.push_back(pile);

  Stressor angle;
  angle.name = "friction_angle";
  angle.question = "a box (mu_s 0.5, mu_d 0.3) built 1 mm into a ramp holds at atan(mu_s) - d "
                   "(within 1 cm over 2 s) and slides as predicted at atan(mu_s) + d (within 15 cm)";
  angle.unit = "degrees";
  angle.ladder = {8, 4, 2, 1, 0.5, 0.25, 0.1};
  angle.scenarios = [](double value) {
    std::vector<LabScenario> pair;
    const double critical = std::atan(0.5) * 180.0 / 3.14159265358979323846;
    for (const double degrees : {critical - value, critical + value}) {
      const double theta = degrees * 3.14159265358979323846 / 180.0;
      const double c = std::cos(theta), s = std::sin(theta);
      // Built 1 mm into the ramp, so the box does not land (impacts are another stressor).
      const double local_x = 2.0, local_y = 0.749;
      const json grip = material(1.0, 0.0, 0.5, 0.3);
      json bodies = json::array(
          {{{"name", "ramp"}, {"type", "static"},
            {"shape", {{"type", "oriented_box"}, {"half_extents", {10, 0.5}}}},
            {"position", {0, 0}}, {"angle", theta}, {"material", material(0.0, 0.0, 0.5, 0.3)}},
           {{"name", "block"}, {"shape", {{"type", "oriented_box"}, {"half_extents", {0.25, 0.25}}}},
            {"position", {local_x * c - local_y * s, local_x * s + local_y * c}},
            {"angle", theta}, {"material", grip}}});
      // Holding: within 1 cm. Sliding: semi-implicit Euler at 1/60 s already errs by a T dt / 2
      // (5 cm here) and a contact found one step late by a T dt more; 15 cm allows both and is
      // still far below the metres a held (or wrongly sliding) box is off by.
      const double threshold = degrees < critical ? 0.01 : 0.15;
      pair.push_back(scenario(
          "friction_angle", 2.0,
          {{"kind", "slope_motion"}, {"body", "block"}, {"surface", "ramp"}, {"unit", "m"},
           {"threshold", threshold}, {"meaning", "distance along the ramp from the exact position"}},
          {{"model", {{"shapes", {"polygon"}}, {"rotation", true}, {"friction", true},
                      {"restitution", false}}},
           {"bodies", bodies}}));
    }
    return pair;
  };
  list.push_back(angle);

  // Joints: how heavy a load, and how coarse a step, a hanging chain's joints carry without
  // coming apart by more than 1 cm (the drift of soft or iterated point constraints grows with
  // the weight below a joint and with the time step).
  Stressor load;
  load.name = "chain_load";
  load.question = "a hanging chain of 20 links whose last link is r times heavier keeps every "
                  "joint within 1 cm (over the last of " + std::to_string(static_cast<int>(short_run)) + " s)";
  load.unit = "x";
  load.ladder = {1, 3, 10, 30, 100, 300, 1000, 3000, 10000};
  load.scenarios = [short_run](double value) {
    return std::vector<LabScenario>{hanging_chain(value, short_run, 0.01)};
  };
  list.push_back(load);

  Stressor chain_step;
  chain_step.name = "chain_time_step";
  chain_step.question = "the hanging chain of 20 equal links keeps every joint within 1 cm (over "
                        "the last of " + std::to_string(static_cast<int>(short_run)) +
                        " s) at this time step";
  chain_step.unit = "ms";
  chain_step.ladder = {1000.0 / 240, 1000.0 / 120, 1000.0 / 60, 1000.0 / 30, 1000.0 / 20,
                       1000.0 / 15, 1000.0 / 10};
  chain_step.sets_time_step = true;
  chain_step.scenarios = [short_run](double) {
    return std::vector<LabScenario>{hanging_chain(1.0, short_run, 0.01)};
  };
  list.push_back(chain_step);
  return list;
}

}  // namespace impulse2d::lab
