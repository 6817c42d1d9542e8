#pragma once
/// @file contact_prepare.h
/// Readies a step's contacts for the velocity solvers: anchors, masses, effective masses and
/// the closing acceleration, then (optionally) last step's impulses applied as a warm start.

#include "core/solver/body_state.h"
#include "core/contact.h"
#include "core/solver/solver_context.h"

#include <vector>

namespace impulse2d {

/// Prepares one enabled contact between bodies `a` and `b` as `prepare_contacts` does (for
/// solvers that prepare while they walk the list for something else).
void prepare_contact(Contact& contact, const Body& a, const Body& b, const SolverContext& context);

/// The `PairMass` `prepare_contact` gives a contact between `a` and `b` (all the colouring
/// reads of a prepared contact).
PairMass pair_mass_of(const Body& a, const Body& b, const SolverContext& context);

/// Sets `contact.mass` to `mass`, forgetting the effective masses kept with the old one
/// (`Contact::kept_masses`) when it differs: every write of a prepared contact's mass goes
/// through here.
void set_pair_mass(Contact& contact, const PairMass& mass);

/// Computes every enabled contact's pair masses, each point's anchors (world and local),
/// effective masses along the normal and tangent, and the contact's closing acceleration from
/// gravity and applied forces, and the slip it carries into the step. Call it before this
/// step's velocities are integrated. Without warm starting the carried-over impulses are
/// zeroed.
void prepare_contacts(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                      const SolverContext& context);

/// Applies the carried-over accumulated impulses (warm starting).
void warm_start_contacts(const std::vector<Contact>& contacts, std::vector<Body>& bodies);

}  // namespace impulse2d
