#pragma once
/// @file lab_method.h
/// A method of the lab: an engine and every setting the lab sweeps. impulse2d's methods come
/// from `WorldSettings` (core/settings.h); a peer (Box2D, Chipmunk) is a method too, with its
/// own fixed iteration counts.

#include <string>
#include <vector>

#include "core/settings.h"
#include "scene/scene.h"

namespace impulse2d::lab {

/// The engines the lab can run a scenario in.
enum class Engine {
  Impulse2d,  ///< this engine, with every setting below
  Box2d,      ///< Box2D 2.4.1 (Debian's libbox2d-dev): velocity/position iterations
  Chipmunk,   ///< Chipmunk 7.0.3 (Debian's libchipmunk-dev, a debug build): iterations
};

/// One configuration of the sweep. The defaults are `WorldSettings`' own, so the lab's
/// "default" follows core/settings.h (the soft step, 4 sub-steps of 1 pass). A method that
/// means another solver starts from `method_for(solver)`, which gives it the sub-steps and
/// passes `settings_for` (core/settings.h) measures it at.
struct LabMethod {
  Engine engine = Engine::Impulse2d;  ///< which engine runs it
  SolverMethod solver = WorldSettings{}.solver;  ///< impulse scheme
  int velocity_iterations = WorldSettings{}.velocity_iterations;  ///< passes per (sub)step
  int position_iterations = WorldSettings{}.position_iterations;  ///< NGS (Box2D: position) passes
  int substeps = WorldSettings{}.substeps;  ///< sub-steps per step
  PositionCorrection position_correction = WorldSettings{}.position_correction;  ///< method
  Integrator integrator = WorldSettings{}.integrator;  ///< motion integration
  float time_step = WorldSettings{}.time_step;  ///< seconds per step
  bool continuous = WorldSettings{}.enable_continuous;  ///< CCD for bodies marked bullet
  /// Speculative contact margin, metres (0: contacts only between overlapping shapes).
  float speculative_margin = WorldSettings{}.speculative_margin;
  FrictionMixing friction_mixing = WorldSettings{}.friction_mixing;  ///< friction rule
  RestitutionMixing restitution_mixing = WorldSettings{}.restitution_mixing;  ///< restitution rule
  bool warm_starting = WorldSettings{}.warm_starting;  ///< accumulated impulses carried over
  bool block_solver = WorldSettings{}.block_solver;  ///< 2-point block solver
  bool shock_propagation = WorldSettings{}.shock_propagation;  ///< ground-up heavy-on-light pass
};

/// The default method with `solver` at its own sub-steps and passes (`settings_for`): the soft
/// step 4 sub-steps x 1 pass (= `LabMethod{}`), accumulated and per-iteration impulses 1 step x
/// 16 iterations.
LabMethod method_for(SolverMethod solver);

/// A short label: the solver and its budget, always ("soft_step 4s x1i" is the default, "accumulated 16i"
/// accumulated impulses at 1 step of 16 iterations, "per_iteration 2s x4i"), then only the settings that
/// differ from the default and that the solver uses, e.g. "soft_step 4s x1i dt1/120",
/// "soft_step 4s x1i nospec", "accumulated 16i linpc", "box2d 8/3".
std::string method_label(const LabMethod& method);

/// The configurations swept by `impulse2d lab`: every solver at one step of 1, 2, 4, 8, 16, 32
/// velocity iterations and at 2, 4, 8 substeps of 1, 2, 4 iterations; one at a time from the
/// default (the soft step), time step 1/30..1/240, CCD off, speculative contacts off and at a
/// wider margin, warm starting and shock propagation off, every friction and restitution mixing
/// rule; one at a time from accumulated impulses at 16 iterations (the settings only it uses),
/// each position correction, explicit Euler and the block solver off. `quick` keeps a subset
/// (for CI). In a fixed order.
std::vector<LabMethod> method_space(bool quick);

/// The peers' own configurations: Box2D at 8/3 iterations and Chipmunk at 10 iterations, at
/// `time_step` seconds per step.
std::vector<LabMethod> peer_methods(float time_step);

/// `scene` with the method's settings applied (its settings and its model's iteration counts
/// and CCD switch). The scene's model switches (rotation, friction, restitution, sleeping) stay.
demos::Scene apply_method(const LabMethod& method, const demos::Scene& scene);

/// The method the scene itself declares (its settings with its model applied).
LabMethod scene_method(const demos::Scene& scene);

/// Names as in scene files: "accumulated", "nonlinear_gauss_seidel", "geometric_mean", ...
const char* engine_name(Engine engine);
const char* correction_name(PositionCorrection correction);          ///< see engine_name
const char* integrator_name(Integrator integrator);                  ///< see engine_name
const char* friction_mixing_name(FrictionMixing rule);               ///< see engine_name
const char* restitution_mixing_name(RestitutionMixing rule);         ///< see engine_name

}  // namespace impulse2d::lab
