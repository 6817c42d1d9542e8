#pragma once
/// @file shock_propagation.h
/// Shock propagation (Guendelman, Bridson and Fedkiw 2003), where Gauss-Seidel cannot
/// converge: a heavy body resting on a light one. One pass of the velocity iterations closes
/// the error of such a contact by only about m / (m + M) (M above, m below), so 16 passes
/// leave a 1:1000 pair almost unsolved and the light body is squeezed out. After the
/// iterations, one more pass visits those contacts from the ground up with the lower body
/// held fixed, so the heavy body stops on the light one, which in turn rests on what is
/// below it.
///
/// The pass is kept to where it is needed, because holding the lower body fixed breaks
/// momentum conservation (and, applied to every contact of a 100-row pyramid, feeds the lower
/// rows' jitter into the upper ones until the top comes apart): a contact takes part only when
/// its upper body is heavier than its lower one by more than the ratio the iterations can
/// handle, N / ln 2 for N iterations (the ratio at which N passes no longer halve the error,
/// (M / (M + m))^N = 1/2), and so do the contacts that carry that pair down to the ground
/// (after the iterations the unsolved error sits there: the light body pressed into what is
/// below it). Equal-mass stacks and pyramids never take part. Its impulses change velocities only and are not
/// added to the accumulated impulses, so the warm start of the next step is the iterations'
/// own estimate of the load (a one-sided impulse stored there would be applied to both bodies
/// next step as if it were load).

#include "core/solver/body_state.h"
#include "core/contact.h"

#include <cstdint>
#include <vector>

namespace impulse2d {

/// The support order of one step: each body's distance (in contacts) to the nearest fixed
/// body through supporting contacts, and the contacts that carry a heavy body on a light one
/// sorted from the ground up. Kept by the world and reused, so building it allocates nothing once warm.
struct SupportOrder {
  /// Per body slot: supporting contacts to the nearest fixed body, or -1 when none reaches one.
  std::vector<int> level;
  /// Indices of the contacts the shock pass solves, by ascending level of their lower body.
  std::vector<int> contacts_upward;
  /// Per body slot: 1 when a heavy body rests on it, directly or through other bodies.
  std::vector<std::uint8_t> under_heavy;
  /// Per contact of the last build, 1 when it was part of the support graph.
  std::vector<std::uint8_t> supporting;
  /// Scratch: the same for the build under way (compared with `supporting`).
  std::vector<std::uint8_t> next_supporting;
  /// Scratch: per-slot offsets into `edge_body` (size slots + 1).
  std::vector<int> edge_start;
  /// Scratch: the other body of each supporting contact, grouped by body.
  std::vector<int> edge_body;
  /// Scratch: the breadth-first queue, then the contacts between levels in ascending order.
  std::vector<int> queue;
  /// Scratch: contacts per level, then each level's first place in the sorted order.
  std::vector<int> level_count;
};

/// The mass ratio (upper / lower) above which `velocity_iterations` passes of Gauss-Seidel no
/// longer halve a resting contact's error in one step: N / ln 2.
float shock_mass_ratio(int velocity_iterations);

/// True when the contact is solvable and joins two dynamic bodies whose masses differ by more
/// than `mass_ratio` (`shock_mass_ratio`, either way up): only when some contact is can the
/// shock pass act, so a solver that must gather its state to run the pass asks this of each
/// contact as it prepares it. Reads the contact's pair masses (`Contact::mass`), not the bodies.
bool is_heavy_on_light(const Contact& contact, float mass_ratio);

/// Builds `order` after the velocity iterations. A contact supports when it is solvable, its
/// normal is within 45 degrees of `gravity` (m/s^2; none: no order), one of its points pushes
/// (positive normal impulse) and none bounces or waits (collisions keep their momentum
/// exchange). Fixed bodies (zero inverse mass) are level 0. `contacts_upward` holds, from the
/// ground up, the supporting contacts whose lower-level body lies below the other and either
/// is lighter than it by more than `shock_mass_ratio(velocity_iterations)` or carries such a
/// pair above it: the whole chain that carries the heavy body down to the ground. When no
/// supporting contact is heavy-on-light (most steps), it returns at once with
/// `contacts_upward` empty and the rest of `order` left as it was. With `same_contacts` (the
/// contacts, their normals and the bodies' masses are those of the last build: a later
/// sub-step of one step), an order whose contacts support as they did is kept as it is: it
/// would be built again the same.
void build_support_order(const std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                         vec2 gravity, int velocity_iterations, bool same_contacts,
                         SupportOrder& order);

/// One pass over `order.contacts_upward`: the normal impulses (the 2x2 block for two-point
/// manifolds when `block_solver`, else point by point, toward each point's `velocity_bias`)
/// and then, when `friction`, Coulomb friction, with the lower body's inverse mass and inertia
/// taken as zero so that only the upper body's velocity changes. The accumulated impulses are
/// left as the iterations left them.
void solve_shock_pass(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                      const SupportOrder& order, bool block_solver, bool friction);

}  // namespace impulse2d
