#include "core/solver/wide_contact_solver.h"

#include "core/solver/contact_prepare.h"
#include "core/solver/contact_solver_internal.h"
#include "core/solver/prefetch.h"
#include "core/solver/shock_propagation.h"
#include "core/solver/wide_contact_kernels.h"

#include <atomic>
#include <cstddef>

namespace impulse2d {

namespace {

static_assert(max_manifold_points == 2, "ContactBlock has two point slots per lane");

// Prepares `contact` (`prepare_contact`) and returns true when its touch flag changed.
bool prepare_noting_touch(Contact& contact, const Body& a, const Body& b,
                          const SolverContext& context) {
  const bool touched = contact.touching;
  prepare_contact(contact, a, b, context);
  return contact.touching != touched;
}

// The bytes of a contact that writing impulses back and reading bounce plans touch: the point
// count and its points (the rest of its ~300 bytes need not be fetched).
static_assert(offsetof(Contact, point_count) < offsetof(Contact, points),
              "the point count comes before the points");
constexpr std::size_t point_state_begin = offsetof(Contact, point_count);
constexpr std::size_t point_state_end = offsetof(Contact, points) + sizeof(Contact::points);

// Calls visit(block, its solve part, point slot index, lane, contact point) for every used
// point of every lane of the step's blocks in `packed` (a `ColourBlocks`), whose
// `contact_index` holds the blocks' contact indices, lanes per block (-1: unused lane).
template <class Blocks, class Contacts, class Visit>
void for_each_point(Blocks& packed, Contacts& contacts, Visit visit) {
  constexpr int Lanes = Blocks::lanes;
  const std::size_t block_count = packed.count;
  const std::vector<std::int32_t>& contact_index = packed.contact_index;
  // The contacts `prefetch_items_ahead` on are asked for: in colour order a contact's index is
  // not predictable from the last one's, so without the hint every ~300-byte contact is a run
  // of cache misses.
  const std::size_t ahead = prefetch_items_ahead / Lanes + 1;  // blocks
  for (std::size_t b = 0; b < block_count; ++b) {
    if (b + ahead < block_count) {
      for (int lane = 0; lane < Lanes; ++lane) {
        const std::int32_t index = contact_index[(b + ahead) * Lanes + lane];
        if (index >= 0) {
          prefetch_bytes(contacts[static_cast<std::size_t>(index)], point_state_begin, point_state_end);
        }
      }
    }
    for (int lane = 0; lane < Lanes; ++lane) {
      const std::int32_t index = contact_index[b * Lanes + lane];
      if (index < 0) continue;
      auto& contact = contacts[static_cast<std::size_t>(index)];
      for (int i = 0; i < contact.point_count; ++i) {
        visit(packed.blocks[b], packed.solves[b], i, lane, contact.points[i]);
      }
    }
  }
}

// `for_each_point` for the `count` contacts listed at `listed` (indices into `contacts`) only,
// in that order: `lane_of_contact` and `colouring` say where each is packed in `packed` (a
// `Colours`); contacts not solved are passed over.
template <int Lanes, class Packed, class Contacts, class Visit>
void for_each_listed_point(Packed& packed, const std::vector<std::int32_t>& lane_of_contact,
                           const ContactColouring& colouring, Contacts& contacts,
                           const std::uint32_t* listed, std::size_t count, Visit visit) {
  for (std::size_t n = 0; n < count; ++n) {
    const std::uint32_t index = listed[n];
    const std::int32_t slot = lane_of_contact[index];
    if (slot < 0) continue;
    auto& blocks = packed[static_cast<std::size_t>(colouring.colour_of(index))];
    const std::size_t block = static_cast<std::size_t>(slot) / Lanes;
    const int lane = static_cast<int>(static_cast<std::size_t>(slot) % Lanes);
    auto& contact = contacts[index];
    for (int i = 0; i < contact.point_count; ++i) {
      visit(blocks.blocks[block], blocks.solves[block], i, lane, contact.points[i]);
    }
  }
}


// The blocks [first, first + count) of `arrays`.
template <int Lanes>
ContactBlockArrays<Lanes> block_range(const ContactBlockArrays<Lanes>& arrays, std::size_t first,
                                      std::size_t count) {
  return {arrays.blocks + first, arrays.solves + first, arrays.sticks + first, count};
}

// Point slot `slot` of lane `lane` left without a point: nothing to solve, no impulse to apply.
template <int Lanes>
void clear_point(ContactBlock<Lanes>& block, ContactBlockSolve<Lanes>& solve, int slot, int lane) {
  solve.points[slot].rounding[lane] = 0.0f;
  solve.points[slot].normal_mass[lane] = 0.0f;
  solve.points[slot].tangent_mass[lane] = 0.0f;
  block.points[slot].normal_impulse[lane] = 0.0f;
  block.points[slot].tangent_impulse[lane] = 0.0f;
}

// No pair solve in lane `lane` (its lanes are still read, so they hold zeros).
template <int Lanes>
void clear_pair(ContactBlockSolve<Lanes>& solve, int lane) {
  solve.pair_mass_00[lane] = 0.0f;
  solve.pair_mass_01[lane] = 0.0f;
  solve.pair_mass_11[lane] = 0.0f;
}

// An unused lane: no contact, no points, body slot 0 (never written: it moves nothing).
template <int Lanes>
void clear_lane(ContactBlock<Lanes>& block, ContactBlockSolve<Lanes>& solve, int lane) {
  block.body_a[lane] = 0;
  block.body_b[lane] = 0;
  block.flags[lane] = 0;
  solve.friction_at_limit[lane] = 0;
  clear_pair(solve, lane);
  block.inverse_mass_a[lane] = 0.0f;
  block.inverse_mass_b[lane] = 0.0f;
  block.inverse_inertia_a[lane] = 0.0f;
  block.inverse_inertia_b[lane] = 0.0f;
  for (int slot = 0; slot < max_manifold_points; ++slot) clear_point(block, solve, slot, lane);
}

// The flag bits of point slot `slot` that the bounce stages may change: waiting and bouncing.
std::int32_t bounce_flags(int slot, const ContactPoint& point) {
  return (point.waiting ? block_point_waiting << slot : 0) |
         (point.bouncing ? block_point_bouncing << slot : 0);
}

// What the bounce stages may change in point slot `slot`, but for its flags: its accumulated
// impulses and speed target.
template <int Lanes>
void load_point_values(ContactBlock<Lanes>& block, ContactBlockSolve<Lanes>& solve, int slot,
                       int lane, const ContactPoint& point) {
  block.points[slot].normal_impulse[lane] = point.normal_impulse;
  block.points[slot].tangent_impulse[lane] = point.tangent_impulse;
  solve.points[slot].velocity_bias[lane] = point.velocity_bias;
}

// What the bounce stages may change in point slot `slot`: its accumulated impulses and bounce
// plan.
template <int Lanes>
void load_point_state(ContactBlock<Lanes>& block, ContactBlockSolve<Lanes>& solve, int slot,
                      int lane, const ContactPoint& point) {
  load_point_values(block, solve, slot, lane, point);
  const std::int32_t plan = (block_point_waiting | block_point_bouncing) << slot;
  block.flags[lane] = (block.flags[lane] & ~plan) | bounce_flags(slot, point);
}

// A's point `on_a` and B's point `on_b` into lane `lane` of four lane arrays (x and y of each).
void set_lane_points(float* ax, float* ay, float* bx, float* by, int lane, vec2 on_a, vec2 on_b) {
  ax[lane] = on_a.x;
  ay[lane] = on_a.y;
  bx[lane] = on_b.x;
  by[lane] = on_b.y;
}

// Largest condition number (Box2D v2's bound) of a two-point manifold's effective-mass matrix
// solved as a pair; beyond it the points are nearly one, and are solved one after the other.
constexpr float max_pair_condition = 1000.0f;

// The inverse of the two points' normal effective-mass matrix K, and whether K is
// well-conditioned enough to solve them as a pair. K's diagonal is each point's own
// 1/normal_mass; its off-diagonal couples them through the bodies' masses and inertias.
void find_pair_inverse(const Contact& contact, PairSolve& pair) {
  pair.solvable = false;
  pair.mass_00 = 0.0f;
  pair.mass_01 = 0.0f;
  pair.mass_11 = 0.0f;
  const ContactPoint& first = contact.points[0];
  const ContactPoint& second = contact.points[1];
  if (!(first.normal_mass > 0.0f && second.normal_mass > 0.0f)) return;
  const PairMass& mass = contact.mass;
  const vec2 normal = contact.normal;
  const float k00 = 1.0f / first.normal_mass;
  const float k11 = 1.0f / second.normal_mass;
  const float k01 = mass.inverse_mass_a + mass.inverse_mass_b +
                    mass.inverse_inertia_a * cross(first.anchor_a, normal) * cross(second.anchor_a, normal) +
                    mass.inverse_inertia_b * cross(first.anchor_b, normal) * cross(second.anchor_b, normal);
  const float determinant = k00 * k11 - k01 * k01;
  if (!(k00 * k00 < max_pair_condition * determinant)) return;
  const float inverse_determinant = 1.0f / determinant;
  pair.solvable = true;
  pair.mass_00 = k11 * inverse_determinant;
  pair.mass_01 = -k01 * inverse_determinant;
  pair.mass_11 = k00 * inverse_determinant;
}

// Effective mass (kg) along the tangent at the middle of a two-point contact's points, where
// the wide solver applies its friction (see solve_friction).
float middle_tangent_mass(const Contact& contact) {
  const vec2 tangent = contact_detail::tangent_of(contact.normal);
  const float arm_a = cross(0.5f * (contact.points[0].anchor_a + contact.points[1].anchor_a), tangent);
  const float arm_b = cross(0.5f * (contact.points[0].anchor_b + contact.points[1].anchor_b), tangent);
  const PairMass& mass = contact.mass;
  const float inverse = mass.inverse_mass_a + mass.inverse_mass_b +
                        mass.inverse_inertia_a * arm_a * arm_a +
                        mass.inverse_inertia_b * arm_b * arm_b;
  return inverse > 0.0f ? 1.0f / inverse : 0.0f;
}

// A two-point contact's `pair_solve`: found when prepare found its effective masses afresh,
// else kept from the step that did (it depends on nothing else).
const PairSolve& pair_solve_of(Contact& contact) {
  if (!contact.kept_pair_solve) {
    find_pair_inverse(contact, contact.pair_solve);
    contact.pair_solve.middle_tangent_mass = middle_tangent_mass(contact);
    contact.kept_pair_solve = true;
  }
  return contact.pair_solve;
}

// Point `point` into slot `slot` of lane `lane` of a block's three parts, but for its tangent
// mass (its contact's to write); returns the slot's flag bits. (Inlined: without it GCC 12
// calls it, and packing costs more than the loop over the points it replaces.)
template <int Lanes>
inline __attribute__((always_inline)) std::int32_t pack_point(const ContactPoint& point, int slot, ContactBlock<Lanes>& block,
                        ContactBlockSolve<Lanes>& solve, ContactBlockStick<Lanes>& stick, int lane) {
  BlockPointImpulse<Lanes>& impulse = block.points[slot];
  set_lane_points(impulse.anchor_ax, impulse.anchor_ay, impulse.anchor_bx, impulse.anchor_by, lane,
                  point.anchor_a, point.anchor_b);
  BlockPointSolve<Lanes>& solved = solve.points[slot];
  set_lane_points(solved.surface_ax, solved.surface_ay, solved.surface_bx, solved.surface_by, lane,
                  point.local_anchor_a, point.local_anchor_b);
  solved.rounding[lane] = point.rounding;
  solved.normal_mass[lane] = point.normal_mass;
  BlockPointStick<Lanes>& stuck = stick.points[slot];
  set_lane_points(stuck.stick_ax, stuck.stick_ay, stuck.stick_bx, stuck.stick_by, lane,
                  point.recycle_anchor_a, point.recycle_anchor_b);
  stuck.stick_offset[lane] = point.stick_offset;
  load_point_values(block, solve, slot, lane, point);
  return (block_point_present << slot) | bounce_flags(slot, point) |
         (point.caught ? block_point_caught << slot : 0);
}

// One contact into lane `lane` of a block's three parts (a contact's one or two points each
// written by its own code: no loop over the count).
template <int Lanes>
void pack_contact(Contact& contact, ContactBlock<Lanes>& block,
                  ContactBlockSolve<Lanes>& solve, ContactBlockStick<Lanes>& stick, int lane) {
  const PairMass& mass = contact.mass;
  const bool against_fixed = mass.inverse_mass_a == 0.0f || mass.inverse_mass_b == 0.0f;
  block.body_a[lane] = static_cast<std::int32_t>(contact.body_a.index);
  block.body_b[lane] = static_cast<std::int32_t>(contact.body_b.index);
  std::int32_t flags = 0;
  if (contact_detail::moves_a(mass)) flags |= block_moves_a;
  if (contact_detail::moves_b(mass)) flags |= block_moves_b;
  if (contact.sliding) flags |= block_sliding;
  if (against_fixed) flags |= block_against_fixed;
  block.normal_x[lane] = contact.normal.x;
  block.normal_y[lane] = contact.normal.y;
  block.inverse_mass_a[lane] = mass.inverse_mass_a;
  block.inverse_mass_b[lane] = mass.inverse_mass_b;
  block.inverse_inertia_a[lane] = mass.inverse_inertia_a;
  block.inverse_inertia_b[lane] = mass.inverse_inertia_b;
  solve.friction_at_limit[lane] = 0;
  solve.static_friction[lane] = contact.static_friction;
  solve.dynamic_friction[lane] = contact.dynamic_friction;
  flags |= pack_point(contact.points[0], 0, block, solve, stick, lane);
  if (contact.point_count == 2) {
    flags |= pack_point(contact.points[1], 1, block, solve, stick, lane);
    // Friction is applied once, at the middle of the two points (see solve_friction).
    const PairSolve& pair = pair_solve_of(contact);
    solve.points[0].tangent_mass[lane] = pair.middle_tangent_mass;
    solve.points[1].tangent_mass[lane] = 0.0f;
    solve.pair_mass_00[lane] = pair.mass_00;
    solve.pair_mass_01[lane] = pair.mass_01;
    solve.pair_mass_11[lane] = pair.mass_11;
    if (pair.solvable) flags |= block_point_pair;
  } else {
    solve.points[0].tangent_mass[lane] = contact.points[0].tangent_mass;
    clear_pair(solve, lane);
    clear_point(block, solve, 1, lane);
  }
  block.flags[lane] = flags;
}

}  // namespace

int WideContactSolver::widest_lanes() {
#if defined(__x86_64__)
  if (wide_contact_kernels_8_available()) return 8;
#endif
  return 4;
}

template <int Lanes>
std::size_t WideContactSolver::ColourBlocks<Lanes>::open_block() {
  if (count == blocks.size()) {
    // A quarter more room at a time, not twice: a colour's blocks hold ~200 bytes a contact,
    // and doubling would leave up to as much unused again.
    if (blocks.size() == blocks.capacity()) {
      const std::size_t room = blocks.size() + blocks.size() / 4 + 16;
      blocks.reserve(room);
      solves.reserve(room);
      sticks.reserve(room);
      contact_index.reserve(room * Lanes);
    }
    blocks.emplace_back();
    solves.emplace_back();
    sticks.emplace_back();
    contact_index.resize(contact_index.size() + Lanes);
  }
  std::fill_n(contact_index.begin() + static_cast<std::ptrdiff_t>(count * Lanes), Lanes, -1);
  return count++;
}

template <int Lanes>
void WideContactSolver::place(std::size_t index, int colour, Contact& contact) {
  // Each colour fills its blocks Lanes contacts at a time in the list's order (its last block
  // partly); the overflow goes one contact per block, as its contacts may share bodies.
  // The contacts come in the list's order: `index` is the count visited so far.
  if (lane_of_contact_.size() != index) lane_of_contact_.resize(index, -1);
  if (colour < 0) {
    lane_of_contact_.push_back(-1);
    return;
  }
  ColourBlocks<Lanes>& blocks = colours<Lanes>()[static_cast<std::size_t>(colour)];
  const std::size_t rank = colouring_.count(colour) - 1;
  const std::size_t per_block = colour == ContactColouring::max_colours ? 1 : Lanes;
  const int lane = static_cast<int>(rank % per_block);
  const std::size_t block = lane == 0 ? blocks.open_block() : blocks.count - 1;
  blocks.contact_index[block * Lanes + static_cast<std::size_t>(lane)] = static_cast<std::int32_t>(index);
  lane_of_contact_.push_back(static_cast<std::int32_t>(block * Lanes + static_cast<std::size_t>(lane)));
  pack_contact(contact, blocks.blocks[block], blocks.solves[block], blocks.sticks[block], lane);
}

template <int Lanes>
void WideContactSolver::place_in_batches(std::size_t contact_count) {
  const std::size_t batches = batched_ ? islands_.batch_count() : 1;
  placed_batches_ = batches;
  const std::size_t row = batches + 1;
  constexpr std::size_t colour_rows = ContactColouring::max_colours + 1;
  // Contacts of each colour and batch, then (a running sum over each colour's batches) the
  // first block of each batch: batch_blocks_[colour * row + batch].
  batch_blocks_.assign(colour_rows * row, 0);
  std::size_t recorded = 0;  // solvable contacts so far: the islands' record of each
  for (std::size_t i = 0; i < contact_count; ++i) {
    const int colour = colouring_.colour_of(i);
    if (colour < 0) continue;
    const std::size_t batch = batched_ ? islands_.batch_of_contact(recorded) : 0;
    ++recorded;
    ++batch_blocks_[static_cast<std::size_t>(colour) * row + batch + 1];
  }
  // Each colour's next free lane of each batch (block * Lanes + lane).
  next_lane_.resize(colour_rows * batches);
  Colours<Lanes>& packed = colours<Lanes>();
  for (std::size_t colour = 0; colour < colour_rows; ++colour) {
    const std::size_t per_block = colour == ContactColouring::max_colours ? 1 : Lanes;
    std::uint32_t* first = batch_blocks_.data() + colour * row;
    std::uint32_t blocks = 0;
    for (std::size_t batch = 0; batch < batches; ++batch) {
      next_lane_[colour * batches + batch] = blocks * Lanes;
      blocks += static_cast<std::uint32_t>((first[batch + 1] + per_block - 1) / per_block);
      first[batch + 1] = blocks;
    }
    ColourBlocks<Lanes>& colour_blocks = packed[colour];
    while (colour_blocks.count < blocks) colour_blocks.open_block();
  }
  lane_of_contact_.resize(contact_count);
  recorded = 0;
  for (std::size_t i = 0; i < contact_count; ++i) {
    const int colour = colouring_.colour_of(i);
    if (colour < 0) {
      lane_of_contact_[i] = -1;
      continue;
    }
    const std::size_t batch = batched_ ? islands_.batch_of_contact(recorded) : 0;
    ++recorded;
    std::uint32_t& next = next_lane_[static_cast<std::size_t>(colour) * batches + batch];
    const std::uint32_t lane = next;
    next += colour == ContactColouring::max_colours ? Lanes : 1;  // the overflow: a block each
    packed[static_cast<std::size_t>(colour)].contact_index[lane] = static_cast<std::int32_t>(i);
    lane_of_contact_[i] = static_cast<std::int32_t>(lane);
  }
}

template <int Lanes>
void WideContactSolver::clear_unused_lanes() {
  Colours<Lanes>& packed = colours<Lanes>();
  for (int colour = 0; colour < packed_colours_; ++colour) {
    ColourBlocks<Lanes>& blocks = packed[static_cast<std::size_t>(colour)];
    // Packed as visited, a colour is one batch: only its last block can be partly used;
    // else only a batch's last block can be. Lane 0 of every block is used.
    const std::size_t first = deferred_ || blocks.count == 0 ? 0 : blocks.count - 1;
    for (std::size_t block = first; block < blocks.count; ++block) {
      const std::int32_t* contact_index = blocks.contact_index.data() + block * Lanes;
      if (contact_index[Lanes - 1] >= 0) continue;
      for (int lane = 1; lane < Lanes; ++lane) {
        if (contact_index[lane] >= 0) continue;
        clear_lane(blocks.blocks[block], blocks.solves[block], lane);
        // Lane 0's bodies, not slot 0's: the unused lane reads (never writes) bodies that no
        // other block of the colour touches, so workers sharing the colour never read a body
        // another one is writing.
        blocks.blocks[block].body_a[lane] = blocks.blocks[block].body_a[0];
        blocks.blocks[block].body_b[lane] = blocks.blocks[block].body_b[0];
      }
    }
  }
  ColourBlocks<Lanes>& overflow = packed[ContactColouring::max_colours];
  for (std::size_t block = 0; block < overflow.count; ++block) {
    for (int lane = 1; lane < Lanes; ++lane) clear_lane(overflow.blocks[block], overflow.solves[block], lane);
  }
}

void WideContactSolver::begin_step(const std::vector<Body>& bodies, const SolverContext& context,
                                   int lanes, WorkerPool* pool, bool allow_batches) {
  pool_ = pool;
  // Islands are looked for only where the last step could have been batched: enough contacts
  // to fill the batches needed (a batch closes at target_contacts or more) and no bounce or
  // shock stage.
  const std::size_t needed = min_island_batches_;
  finds_islands_ = allow_batches && !last_step_unbatchable_ &&
                   last_contact_count_ > (needed - 1) * IslandBatches::target_contacts;
  if (!finds_islands_) last_batch_count_ = 0;
  // Lanes are given as contacts are visited (packing each while it is in the cache) unless a
  // pool packs them, or the last step had island batches to lay out (likely again).
  deferred_ = pool != nullptr || last_batch_count_ >= needed;
  batched_ = false;
  if (finds_islands_) islands_.begin(bodies.size());
  if (lanes == 0) lanes = widest_lanes();  // 4 or 8 otherwise (validate_settings)
  lanes_ = lanes;
  has_elastic_contacts_ = false;
  has_heavy_on_light_ = false;
  shock_mass_ratio_ = context.shock_propagation ? shock_mass_ratio(context.velocity_iterations) : 0.0f;
  bodies_ = &bodies;
  context_ = &context;
  touch_tally_ = TouchTally{};
  touch_tally_.valid = context.touch_velocities.linear != nullptr;
  colouring_.begin(bodies.size());
  lane_of_contact_.clear();
  for (auto& blocks : colours_4_) blocks.count = 0;
  for (auto& blocks : colours_8_) blocks.count = 0;
}

void WideContactSolver::visit(std::size_t index, Contact& contact) {
  if (contact.enabled) {
    const std::vector<Body>& bodies = *bodies_;
    const Body& a = bodies[contact.body_a.index];
    const Body& b = bodies[contact.body_b.index];
    if (pool_ != nullptr) {
      set_pair_mass(contact, pair_mass_of(a, b, *context_));  // the rest in finish_step, shared
    } else {
      touch_tally_.changed = prepare_noting_touch(contact, a, b, *context_) || touch_tally_.changed;
      touch_tally_.touching += contact.touching ? 1 : 0;
    }
    if (shock_mass_ratio_ > 0.0f && !has_heavy_on_light_) {
      has_heavy_on_light_ = is_heavy_on_light(contact, shock_mass_ratio_);
    }
  }
  const int colour = colouring_.add(contact);
  if (colour >= 0 && contact.restitution > 0.0f) has_elastic_contacts_ = true;
  if (colour >= 0 && finds_islands_) {
    const std::vector<Body>& bodies = *bodies_;
    const std::uint32_t a = contact.body_a.index;
    const std::uint32_t b = contact.body_b.index;
    islands_.add_contact(a, bodies[a].type != BodyType::Static, b, bodies[b].type != BodyType::Static);
  }
  if (deferred_) return;  // lanes given in finish_step
  if (lanes_ == 8) {
    place<8>(index, colour, contact);
  } else {
    place<4>(index, colour, contact);
  }
}

template <int Lanes>
void WideContactSolver::finish_packing(std::vector<Contact>& contacts) {
  if (deferred_) place_in_batches<Lanes>(contacts.size());
  if (deferred_ && pool_ == nullptr) {
    // Prepared as they were visited: packed here, in the list's order.
    Colours<Lanes>& packed = colours<Lanes>();
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      if (lane_of_contact_[i] < 0) continue;
      ColourBlocks<Lanes>& blocks = packed[static_cast<std::size_t>(colouring_.colour_of(i))];
      const std::size_t block = static_cast<std::size_t>(lane_of_contact_[i]) / Lanes;
      const int lane = static_cast<int>(static_cast<std::size_t>(lane_of_contact_[i]) % Lanes);
      pack_contact(contacts[i], blocks.blocks[block], blocks.solves[block], blocks.sticks[block], lane);
    }
  }
  if (pool_ != nullptr) {
    const std::vector<Body>& bodies = *bodies_;
    const SolverContext& context = *context_;
    Colours<Lanes>& packed = colours<Lanes>();
    // Each chunk tallies its touches and adds them once (the sums do not depend on the split).
    std::atomic<std::size_t> touching{0};
    std::atomic<bool> changed{false};
    parallel_for(pool_, contacts.size(), 64, [&](std::size_t begin, std::size_t end) {
      std::size_t chunk_touching = 0;
      bool chunk_changed = false;
      for (std::size_t i = begin; i < end; ++i) {
        Contact& contact = contacts[i];
        if (contact.enabled) {
          const Body& a = bodies[contact.body_a.index];
          const Body& b = bodies[contact.body_b.index];
          chunk_changed = prepare_noting_touch(contact, a, b, context) || chunk_changed;
          chunk_touching += contact.touching ? 1 : 0;
        }
        if (lane_of_contact_[i] < 0) continue;
        ColourBlocks<Lanes>& blocks = packed[static_cast<std::size_t>(colouring_.colour_of(i))];
        const std::size_t block = static_cast<std::size_t>(lane_of_contact_[i]) / Lanes;
        const int lane = static_cast<int>(static_cast<std::size_t>(lane_of_contact_[i]) % Lanes);
        pack_contact(contact, blocks.blocks[block], blocks.solves[block], blocks.sticks[block], lane);
      }
      touching.fetch_add(chunk_touching, std::memory_order_relaxed);
      if (chunk_changed) changed.store(true, std::memory_order_relaxed);
    });
    touch_tally_.touching += touching.load();
    touch_tally_.changed = touch_tally_.changed || changed.load();
  }
  clear_unused_lanes<Lanes>();
}

void WideContactSolver::finish_step(std::vector<Contact>& contacts) {
  if (!deferred_) lane_of_contact_.resize(contacts.size(), -1);  // all visited: no change
  packed_colours_ = colouring_.colour_count();
  // The bounce and shock stages work on the whole world between the passes.
  last_step_unbatchable_ = (context_->restitution && has_elastic_contacts_) || has_heavy_on_light_;
  last_contact_count_ = contacts.size();
  if (finds_islands_) {
    islands_.make_batches();
    last_batch_count_ = islands_.batch_count();
    batched_ = deferred_ && islands_.batch_count() >= min_island_batches_ && !last_step_unbatchable_;
    if (batched_) {
      const std::vector<Body>& bodies = *bodies_;
      islands_.gather_bodies([&bodies](std::size_t slot) { return bodies[slot].type != BodyType::Static; });
    }
  }
  if (lanes_ == 8) {
    finish_packing<8>(contacts);
  } else {
    finish_packing<4>(contacts);
  }
  bodies_ = nullptr;
  context_ = nullptr;
  pool_ = nullptr;
}

void WideContactSolver::load_points(const std::vector<Contact>& contacts) {
  auto load = [](auto& block, auto& solve, int slot, int lane, const ContactPoint& point) {
    load_point_state(block, solve, slot, lane, point);
  };
  if (lanes_ == 8) {
    for (auto& blocks : colours_8_) for_each_point(blocks, contacts, load);
  } else {
    for (auto& blocks : colours_4_) for_each_point(blocks, contacts, load);
  }
}

void WideContactSolver::store_impulses(std::vector<Contact>& contacts) const {
  auto store = [](const auto& block, const auto& solve, int slot, int lane, ContactPoint& point) {
    point.normal_impulse = block.points[slot].normal_impulse[lane];
    point.tangent_impulse = block.points[slot].tangent_impulse[lane];
    point.friction_at_limit = (solve.friction_at_limit[lane] & (1 << slot)) != 0;
  };
  if (lanes_ == 8) {
    for (const auto& blocks : colours_8_) for_each_point(blocks, contacts, store);
  } else {
    for (const auto& blocks : colours_4_) for_each_point(blocks, contacts, store);
  }
}

void WideContactSolver::load_points_listed(const std::vector<Contact>& contacts,
                                           const std::uint32_t* listed, std::size_t count) {
  auto load = [](auto& block, auto& solve, int slot, int lane, const ContactPoint& point) {
    load_point_state(block, solve, slot, lane, point);
  };
  if (lanes_ == 8) {
    for_each_listed_point<8>(colours_8_, lane_of_contact_, colouring_, contacts, listed, count, load);
  } else {
    for_each_listed_point<4>(colours_4_, lane_of_contact_, colouring_, contacts, listed, count, load);
  }
}

void WideContactSolver::write_out(std::vector<Contact>& contacts, std::uint32_t index) {
  if (written_out_.size() < contacts.size()) written_out_.resize(contacts.size(), 0);
  if (written_out_[index] != 0) return;
  written_out_[index] = 1;
  written_list_.push_back(index);
  store_impulses_listed(contacts, &index, 1);
}

void WideContactSolver::read_back_written(const std::vector<Contact>& contacts) {
  load_points_listed(contacts, written_list_.data(), written_list_.size());
  for (const std::uint32_t index : written_list_) written_out_[index] = 0;
  written_list_.clear();
}

void WideContactSolver::store_impulses_listed(std::vector<Contact>& contacts,
                                              const std::uint32_t* listed, std::size_t count) const {
  auto store = [](const auto& block, const auto& solve, int slot, int lane, ContactPoint& point) {
    point.normal_impulse = block.points[slot].normal_impulse[lane];
    point.tangent_impulse = block.points[slot].tangent_impulse[lane];
    point.friction_at_limit = (solve.friction_at_limit[lane] & (1 << slot)) != 0;
  };
  if (lanes_ == 8) {
    for_each_listed_point<8>(colours_8_, lane_of_contact_, colouring_, contacts, listed, count, store);
  } else {
    for_each_listed_point<4>(colours_4_, lane_of_contact_, colouring_, contacts, listed, count, store);
  }
}

namespace {

// Blocks a worker takes at least at a time (a block is a few dozen nanoseconds of work).
constexpr std::size_t min_blocks_per_chunk = 16;

// The kernels' settings of a soft (`use_bias`) or relax pass.
WidePassSettings pass_settings(const SolverContext& context, bool use_bias) {
  WidePassSettings pass;
  pass.inverse_substep = 1.0f / context.substep;
  pass.static_softness = context.static_softness;
  pass.dynamic_softness = context.dynamic_softness;
  pass.push_max_speed = context.push_max_speed;
  pass.use_bias = use_bias;
  pass.friction = context.friction;
  return pass;
}

}  // namespace

template <int Lanes, class Pass>
void WideContactSolver::for_each_colour(WorkerPool* pool, Pass pass) {
  Colours<Lanes>& packed = colours<Lanes>();
  for (int colour = 0; colour < packed_colours_; ++colour) {
    const ContactBlockArrays<Lanes> arrays = packed[static_cast<std::size_t>(colour)].arrays();
    parallel_for(pool, arrays.count, min_blocks_per_chunk, [&](std::size_t begin, std::size_t end) {
      pass(block_range(arrays, begin, end - begin));
    });
  }
  // The overflow's contacts may share bodies: one after another.
  pass(packed[ContactColouring::max_colours].arrays());
}

template <int Lanes>
ContactBlockArrays<Lanes> WideContactSolver::batch_arrays(int colour, std::size_t batch) {
  const std::uint32_t* first = batch_blocks_.data() + static_cast<std::size_t>(colour) * (placed_batches_ + 1);
  return block_range(colours<Lanes>()[static_cast<std::size_t>(colour)].arrays(), first[batch],
                     first[batch + 1] - first[batch]);
}

template <int Lanes, class Pass>
void WideContactSolver::for_each_colour_of_batch(std::size_t batch, Pass pass) {
  for (int colour = 0; colour < packed_colours_; ++colour) {
    const ContactBlockArrays<Lanes> arrays = batch_arrays<Lanes>(colour, batch);
    if (arrays.count > 0) pass(arrays);
  }
  pass(batch_arrays<Lanes>(ContactColouring::max_colours, batch));
}

template <class Kernel>
void WideContactSolver::run_pass(WorkerPool* pool, const std::size_t* batch, Kernel kernel) {
#if defined(__x86_64__)
  if (lanes_ == 8) {
    if (batch != nullptr) {
      for_each_colour_of_batch<8>(*batch, kernel);
    } else {
      for_each_colour<8>(pool, kernel);
    }
    return;
  }
#endif
  if (batch != nullptr) {
    for_each_colour_of_batch<4>(*batch, kernel);
  } else {
    for_each_colour<4>(pool, kernel);
  }
}

namespace {

// The kernels of each lane count, chosen by the blocks' type.
void warm_start_kernel(const ContactBlockArrays<4>& arrays, SolverBody* bodies) {
  warm_start_contact_blocks_4(arrays.blocks, arrays.count, bodies);
}
void solve_kernel(const ContactBlockArrays<4>& arrays, SolverBody* bodies, const WidePassSettings& pass) {
  solve_contact_blocks_4(arrays, bodies, pass);
}
#if defined(__x86_64__)
void warm_start_kernel(const ContactBlockArrays<8>& arrays, SolverBody* bodies) {
  warm_start_contact_blocks_8(arrays.blocks, arrays.count, bodies);
}
void solve_kernel(const ContactBlockArrays<8>& arrays, SolverBody* bodies, const WidePassSettings& pass) {
  solve_contact_blocks_8(arrays, bodies, pass);
}
#endif

}  // namespace

void WideContactSolver::warm_start_batch(std::size_t batch, SolverBody* bodies) {
  run_pass(nullptr, &batch, [&](const auto& arrays) { warm_start_kernel(arrays, bodies); });
}

void WideContactSolver::solve_batch(std::size_t batch, const SolverContext& context,
                                    bool use_bias, SolverBody* bodies) {
  const WidePassSettings pass = pass_settings(context, use_bias);
  run_pass(nullptr, &batch, [&](const auto& arrays) { solve_kernel(arrays, bodies, pass); });
}

void WideContactSolver::warm_start(SolverBody* bodies, WorkerPool* pool) {
  run_pass(pool, nullptr, [&](const auto& arrays) { warm_start_kernel(arrays, bodies); });
}

void WideContactSolver::solve(const SolverContext& context, bool use_bias, SolverBody* bodies,
                              WorkerPool* pool) {
  const WidePassSettings pass = pass_settings(context, use_bias);
  run_pass(pool, nullptr, [&](const auto& arrays) { solve_kernel(arrays, bodies, pass); });
}

}  // namespace impulse2d
