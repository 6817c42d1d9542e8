/// @file lab_method.cpp
#include "lab/lab_method.h"

#include <cmath>
#include <sstream>

namespace impulse2d::lab {
namespace {

std::string step_label(float time_step) {
  std::ostringstream text;
  text << "dt1/" << static_cast<int>(std::lround(1.0 / time_step));
  return text.str();
}

}  // namespace

const char* engine_name(Engine engine) {
  switch (engine) {
    case Engine::Impulse2d: return "impulse2d";
    case Engine::Box2d: return "box2d";
    case Engine::Chipmunk: return "chipmunk";
  }
  return "?";
}

const char* correction_name(PositionCorrection correction) {
  switch (correction) {
    case PositionCorrection::None: return "none";
    case PositionCorrection::LinearProjection: return "linear";
    case PositionCorrection::NonlinearGaussSeidel: return "nonlinear_gauss_seidel";
  }
  return "?";
}

const char* integrator_name(Integrator integrator) {
  return integrator == Integrator::ExplicitEuler ? "explicit_euler" : "semi_implicit_euler";
}

const char* friction_mixing_name(FrictionMixing rule) {
  switch (rule) {
    case FrictionMixing::RootSumSquares: return "root_sum_squares";
    case FrictionMixing::GeometricMean: return "geometric_mean";
    case FrictionMixing::Product: return "product";
    case FrictionMixing::Average: return "average";
    case FrictionMixing::Minimum: return "min";
    case FrictionMixing::Maximum: return "max";
  }
  return "?";
}

const char* restitution_mixing_name(RestitutionMixing rule) {
  switch (rule) {
    case RestitutionMixing::Minimum: return "min";
    case RestitutionMixing::Maximum: return "max";
    case RestitutionMixing::Average: return "average";
  }
  return "?";
}

LabMethod method_for(SolverMethod solver) {
  const WorldSettings settings = settings_for(solver);
  LabMethod method;
  method.solver = settings.solver;
  method.substeps = settings.substeps;
  method.velocity_iterations = settings.velocity_iterations;
  return method;
}

std::string method_label(const LabMethod& method) {
  std::ostringstream text;
  if (method.engine == Engine::Box2d) {
    text << "box2d " << method.velocity_iterations << "/" << method.position_iterations;
  } else if (method.engine == Engine::Chipmunk) {
    text << "chipmunk " << method.velocity_iterations << "i";
  } else {
    const LabMethod base;
    text << solver_name(method.solver);
    if (method.substeps != 1) text << " " << method.substeps << "s x";
    else text << " ";
    text << method.velocity_iterations << "i";
    if (method.time_step != base.time_step) text << " " << step_label(method.time_step);
    if (method.solver != SolverMethod::SoftStep) {
      if (method.position_correction == PositionCorrection::None) text << " nopc";
      if (method.position_correction == PositionCorrection::LinearProjection) text << " linpc";
      if (method.integrator == Integrator::ExplicitEuler) text << " expl";
    }
    // Warm starting and shock propagation (whose pass uses the block solver) serve the
    // accumulated solver and the soft step; the per-iteration solver keeps no impulses.
    if (method.solver != SolverMethod::PerIteration) {
      if (!method.warm_starting) text << " nowarm";
      if (!method.block_solver) text << " noblock";
      if (!method.shock_propagation) text << " noshock";
    }
    if (!method.continuous) text << " noccd";
    if (method.speculative_margin != base.speculative_margin) {
      if (method.speculative_margin == 0.0f) text << " nospec";
      else text << " spec" << method.speculative_margin;
    }
    if (method.friction_mixing != base.friction_mixing)
      text << " f:" << friction_mixing_name(method.friction_mixing);
    if (method.restitution_mixing != base.restitution_mixing)
      text << " e:" << restitution_mixing_name(method.restitution_mixing);
  }
  return text.str();
}

std::vector<LabMethod> method_space(bool quick) {
  std::vector<LabMethod> methods;
  const std::vector<SolverMethod>& solvers = solver_methods();
  const std::vector<int> iterations =
      quick ? std::vector<int>{1, 4, 16} : std::vector<int>{1, 2, 4, 8, 16, 32};
  const std::vector<int> substeps = quick ? std::vector<int>{4} : std::vector<int>{2, 4, 8};
  const std::vector<int> substep_iterations = quick ? std::vector<int>{1} : std::vector<int>{1, 2, 4};
  for (const SolverMethod solver : solvers) {
    for (const int count : iterations) {
      LabMethod method = method_for(solver);
      method.substeps = 1;
      method.velocity_iterations = count;
      methods.push_back(method);
    }
    for (const int steps : substeps) {
      for (const int count : substep_iterations) {
        LabMethod method = method_for(solver);
        method.substeps = steps;
        method.velocity_iterations = count;
        methods.push_back(method);
      }
    }
  }
  // One setting at a time from the default (WorldSettings': the soft step at 4 sub-steps of 1
  // pass, 1/60 s, CCD, speculative margin 2 cm, warm starting, shock propagation) ...
  const auto vary = [&](auto change) {
    LabMethod method;
    change(method);
    methods.push_back(method);
  };
  const std::vector<float> steps = quick ? std::vector<float>{1.0f / 30.0f, 1.0f / 240.0f}
                                         : std::vector<float>{1.0f / 30.0f, 1.0f / 120.0f, 1.0f / 240.0f};
  for (const float step : steps) vary([step](LabMethod& m) { m.time_step = step; });
  vary([](LabMethod& m) { m.continuous = false; });
  vary([](LabMethod& m) { m.speculative_margin = 0.0f; });
  if (!quick) vary([](LabMethod& m) { m.speculative_margin = 0.1f; });
  vary([](LabMethod& m) { m.warm_starting = false; });
  if (!quick) {
    vary([](LabMethod& m) { m.shock_propagation = false; });
    for (const FrictionMixing rule :
         {FrictionMixing::RootSumSquares, FrictionMixing::Product, FrictionMixing::Average,
          FrictionMixing::Minimum, FrictionMixing::Maximum}) {
      vary([rule](LabMethod& m) { m.friction_mixing = rule; });
    }
    for (const RestitutionMixing rule : {RestitutionMixing::Minimum, RestitutionMixing::Average})
      vary([rule](LabMethod& m) { m.restitution_mixing = rule; });
  }
  // ... and the settings the soft step ignores (it has no position correction, always
  // integrates semi-implicitly, and solves its pairs through their 2x2 inverse), one at a time
  // from accumulated impulses at their own 16 iterations.
  const auto vary_accumulated = [&](auto change) {
    LabMethod method = method_for(SolverMethod::Accumulated);
    change(method);
    methods.push_back(method);
  };
  vary_accumulated([](LabMethod& m) { m.position_correction = PositionCorrection::None; });
  vary_accumulated([](LabMethod& m) { m.position_correction = PositionCorrection::LinearProjection; });
  vary_accumulated([](LabMethod& m) { m.integrator = Integrator::ExplicitEuler; });
  if (!quick) vary_accumulated([](LabMethod& m) { m.block_solver = false; });
  return methods;
}

std::vector<LabMethod> peer_methods(float time_step) {
  LabMethod box2d;
  box2d.engine = Engine::Box2d;
  box2d.velocity_iterations = 8;
  box2d.position_iterations = 3;
  box2d.time_step = time_step;
  LabMethod chipmunk;
  chipmunk.engine = Engine::Chipmunk;
  chipmunk.velocity_iterations = 10;
  chipmunk.position_iterations = 0;
  chipmunk.time_step = time_step;
  return {box2d, chipmunk};
}

demos::Scene apply_method(const LabMethod& method, const demos::Scene& scene) {
  demos::Scene result = scene;
  WorldSettings& settings = result.settings;
  settings.solver = method.solver;
  settings.substeps = method.substeps;
  settings.position_correction = method.position_correction;
  settings.integrator = method.integrator;
  settings.time_step = method.time_step;
  settings.friction_mixing = method.friction_mixing;
  settings.restitution_mixing = method.restitution_mixing;
  settings.warm_starting = method.warm_starting;
  settings.block_solver = method.block_solver;
  settings.shock_propagation = method.shock_propagation;
  settings.speculative_margin = method.speculative_margin;
  result.model.velocity_iterations = method.velocity_iterations;
  result.model.position_iterations = method.position_iterations;
  result.model.ccd = method.continuous;
  return result;
}

LabMethod scene_method(const demos::Scene& scene) {
  LabMethod method;
  const WorldSettings& settings = scene.settings;
  method.solver = settings.solver;
  method.substeps = settings.substeps;
  method.position_correction = settings.position_correction;
  method.integrator = settings.integrator;
  method.time_step = settings.time_step;
  method.friction_mixing = settings.friction_mixing;
  method.restitution_mixing = settings.restitution_mixing;
  method.warm_starting = settings.warm_starting;
  method.block_solver = settings.block_solver;
  method.shock_propagation = settings.shock_propagation;
  method.speculative_margin = settings.speculative_margin;
  method.velocity_iterations = scene.model.velocity_iterations;
  method.position_iterations = scene.model.position_iterations;
  method.continuous = scene.model.ccd;
  return method;
}

}  // namespace impulse2d::lab
