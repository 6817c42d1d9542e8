#pragma once
/// @file wide_contact_solver.h
/// The soft step's contact solve on compact arrays: a 32-byte `SolverBody` per body slot and
/// the step's contacts coloured (`contact_colouring.h`) and packed into `ContactBlock`s of 4
/// or 8 lanes, solved by the vector kernels (`wide_contact_kernels.h`). The lanes of a block
/// share no moving body, so 4 and 8 lanes give bit-identical results.
///
/// Per step: `begin_step`, then each contact prepared (`contact_prepare.h`), coloured and packed
/// into its colour's open block as the narrow phase finishes it, while it is in the cache (the
/// solver is the narrow phase's `ContactVisitor`; each colour keeps its own blocks), then
/// `finish_step` clears the lanes no contact took; the passes work on the step's
/// `SolverBodies` (`solver_bodies.h`), and `store_impulses` writes the impulses back to the
/// contacts (and `load_points` reads them in again after the bounce stages changed them).
#include "core/solver/body_state.h"
#include "core/contact.h"
#include "core/solver/contact_block.h"
#include "core/solver/contact_colouring.h"
#include "core/solver/island_batches.h"
#include "core/solver/prefetch.h"
#include "core/solver/worker_pool.h"
#include "core/solver/contact_visitor.h"
#include "core/solver/solver_body.h"
#include "core/solver/solver_context.h"

#include <array>
#include <vector>

namespace impulse2d {

/// The wide solver's arrays for one world (reused from step to step: no allocation once warm).
class WideContactSolver final : public ContactVisitor {
 public:
  /// Lanes per block this CPU runs best: 8 with AVX2 (x86-64), else 4.
  static int widest_lanes();

  /// Starts a step between `bodies` in blocks of `lanes` (4 or 8, 8 only where
  /// `widest_lanes()` is 8; 0: the widest). `bodies` and `context` are kept by reference until
  /// `finish_step`. With a `pool`, `visit` only colours each contact (from its `PairMass`), and
  /// `finish_step` gives each its lane and prepares and packs the contacts on the pool's
  /// workers (each contact is its own work: the same bits). With `allow_batches` (the step
  /// has no joints), the contacts are also grouped into island batches (`island_batches.h`);
  /// when the step has `min_island_batches()` or more and no bounce or shock stage, each
  /// batch's blocks are kept together in every colour (`batched`).
  void begin_step(const std::vector<Body>& bodies, const SolverContext& context, int lanes,
                  WorkerPool* pool = nullptr, bool allow_batches = false);
  /// Prepares the step's next contact (as `prepare_contacts` does, if enabled), colours it,
  /// records it for the island batches when they are looked for, and packs it into the next
  /// lane of its colour's blocks unless the lanes are given in `finish_step` (with a pool, or
  /// when the last step was batched); called for every contact of the list, in order, between
  /// `begin_step` and `finish_step` (by the narrow phase).
  void visit(std::size_t index, Contact& contact) override;
  /// Ends the packing of the step's `contacts`, all visited (with a pool: prepares and packs
  /// them), and clears the lanes no contact took.
  void finish_step(std::vector<Contact>& contacts);
  /// Copies each point's accumulated impulses and bounce plan (`velocity_bias`, `bouncing`,
  /// `waiting`) in, after the bounce stages changed them in the contacts.
  void load_points(const std::vector<Contact>& contacts);
  /// Copies each point's accumulated impulses and `friction_at_limit` out to the contacts.
  void store_impulses(std::vector<Contact>& contacts) const;
  /// Writes contact `index`'s impulses out (`store_impulses` for it alone) unless it was
  /// written out since the last `read_back_written`, and remembers it.
  void write_out(std::vector<Contact>& contacts, std::uint32_t index);
  /// `load_points` for the contacts written out since the last call, which it then forgets.
  void read_back_written(const std::vector<Contact>& contacts);
  /// True when some contact was written out since the last `read_back_written`.
  bool has_written_out() const { return !written_list_.empty(); }
  /// The same in one walk over the list in its order that does other work too: each contact's
  /// impulses are written back (if it was solved), then `then(contact)` is called on it.
  template <class Then>
  void store_impulses(std::vector<Contact>& contacts, Then then) const {
    if (lanes_ == 8) {
      store_impulses_in_order<8>(contacts, then);
    } else {
      store_impulses_in_order<4>(contacts, then);
    }
  }

  /// Applies the accumulated impulses to `bodies` (one state per body slot: warm starting).
  /// With a `pool`, the blocks of each colour are shared among its workers (they move
  /// disjoint bodies), colour after colour, the overflow last on this thread: the same bits.
  void warm_start(SolverBody* bodies, WorkerPool* pool = nullptr);
  /// One soft (`use_bias`) or relax pass over every block, colour by colour, on `bodies`
  /// (with a `pool`, as `warm_start`).
  void solve(const SolverContext& context, bool use_bias, SolverBody* bodies,
             WorkerPool* pool = nullptr);

  /// True when some contact of this step has restitution > 0: without one (and so in any
  /// resting pile) the bounce stages change nothing and are skipped.
  bool has_elastic_contacts() const { return has_elastic_contacts_; }
  /// True when the context asks for shock propagation and some contact of this step joins a
  /// heavy body to a light one (`is_heavy_on_light`): only then can the shock pass act.
  bool has_heavy_on_light() const { return has_heavy_on_light_; }
  /// Lanes per block of this step (4 or 8).
  int lanes() const { return lanes_; }
  /// True when this step's blocks are laid out batch by batch (see `begin_step`): the soft
  /// step may then run all sub-steps of one batch (`warm_start_batch`, `solve_batch`) before
  /// the next.
  bool batched() const { return batched_; }
  /// The fewest island batches a step is batched from. Batching saves memory traffic against
  /// finding the batches and packing after the narrow phase (~4 % more instructions); measured
  /// on a 2 MB-L2 Xeon against pass by pass: 400 pyramids (22 batches, 9 MB of blocks) 0.98x
  /// the time at 8 lanes, 1.07x at 4 lanes and 1.02-1.09x with two workers (whose colours
  /// share out as well as the batches do); 1820 pyramids (122 batches) 0.91x, 0.99x and
  /// 0.98-1.05x (medians of 3-4 alternated pairs).
  static constexpr std::size_t default_min_island_batches = 32;
  /// See `default_min_island_batches`.
  std::size_t min_island_batches() const { return min_island_batches_; }
  /// Sets `min_island_batches()` (>= 2): the results are the same bits either way, so tests
  /// lower it to solve a small world batch by batch.
  void set_min_island_batches(std::size_t batches) { min_island_batches_ = batches; }
  /// The step's island batches (valid when `batched`).
  const IslandBatches& islands() const { return islands_; }

  /// What this step's prepare found of the contacts' touch (`Contact::touching`, judged when
  /// the context has touch velocities), for the events after the step.
  struct TouchTally {
    /// True when this step visited and judged every contact of the list (a soft step with
    /// contact events on): only then do the other two describe it.
    bool valid = false;
    /// True when some contact's `enabled && touching` differs from what its flag held before
    /// the step (a contact new to the list holds false, or its predecessor's value).
    bool changed = false;
    std::size_t touching = 0;  ///< contacts enabled and touching
  };
  /// The tally of the last step that judged the touches since `forget_touch_tally`.
  const TouchTally& touch_tally() const { return touch_tally_; }
  /// Marks the tally invalid (a step whose solver does not visit leaves it so).
  void forget_touch_tally() { touch_tally_ = TouchTally{}; }
  /// `warm_start` for the blocks of island batch `batch` only (when `batched`).
  void warm_start_batch(std::size_t batch, SolverBody* bodies);
  /// `solve` for the blocks of island batch `batch` only (when `batched`), on this thread.
  void solve_batch(std::size_t batch, const SolverContext& context, bool use_bias,
                   SolverBody* bodies);
  /// Colours of this step's contacts (the overflow not counted).
  int colour_count() const { return colouring_.colour_count(); }

 private:
  /// One colour's blocks of `Lanes` lanes (the overflow's: one contact per block), in their
  /// three parts (`contact_block.h`). The arrays only grow: the first `count` blocks are this
  /// step's, and every lane of them is packed or cleared.
  template <int Lanes>
  struct ColourBlocks {
    static constexpr int lanes = Lanes;  ///< contacts side by side
    std::vector<ContactBlock<Lanes>> blocks;       ///< read by every pass
    std::vector<ContactBlockSolve<Lanes>> solves;  ///< read by both solve passes
    std::vector<ContactBlockStick<Lanes>> sticks;  ///< read by the biased pass
    /// Per lane of the blocks: the index of its contact in the list, -1 when unused.
    std::vector<std::int32_t> contact_index;
    std::size_t count = 0;  ///< blocks of this step
    /// The step's blocks as the kernels take them.
    ContactBlockArrays<Lanes> arrays() {
      return {blocks.data(), solves.data(), sticks.data(), count};
    }
    /// Opens the next block, every lane unused; returns its index.
    std::size_t open_block();
  };
  /// A `ColourBlocks` per colour, the overflow last.
  template <int Lanes>
  using Colours = std::array<ColourBlocks<Lanes>, ContactColouring::max_colours + 1>;

  template <int Lanes>
  Colours<Lanes>& colours() {
    if constexpr (Lanes == 8) {
      return colours_8_;
    } else {
      return colours_4_;
    }
  }
  template <int Lanes>
  const Colours<Lanes>& colours() const {
    if constexpr (Lanes == 8) {
      return colours_8_;
    } else {
      return colours_4_;
    }
  }
  /// Gives the list's contact `index` (of colour `colour`, -1: not solved) the next lane of its
  /// colour and packs it there (when the lanes are given as contacts are visited).
  template <int Lanes>
  void place(std::size_t index, int colour, Contact& contact);
  /// Gives every solvable contact of the list its lane, colour by colour and within a colour
  /// batch by batch (one batch unless `batched_`), each batch's contacts in the list's order,
  /// and records each batch's blocks in `batch_blocks_`.
  template <int Lanes>
  void place_in_batches(std::size_t contact_count);
  /// Clears the lanes no contact took: in each colour the lanes after a batch's last contact,
  /// and every overflow block's but the first.
  template <int Lanes>
  void clear_unused_lanes();
  /// The blocks of island batch `batch` in colour `colour` (as `batch_blocks_` holds them).
  template <int Lanes>
  ContactBlockArrays<Lanes> batch_arrays(int colour, std::size_t batch);
  /// `finish_step` at `Lanes` lanes.
  template <int Lanes>
  void finish_packing(std::vector<Contact>& contacts);
  template <int Lanes, class Then>
  void store_impulses_in_order(std::vector<Contact>& contacts, Then then) const;
  /// `store_impulses` and `load_points` for the `count` contacts listed at `listed` only.
  void store_impulses_listed(std::vector<Contact>& contacts, const std::uint32_t* listed,
                             std::size_t count) const;
  void load_points_listed(const std::vector<Contact>& contacts, const std::uint32_t* listed,
                          std::size_t count);

  /// Runs `pass(arrays)` over each colour's blocks in turn (`arrays` a range of them), shared
  /// among `pool`'s workers, then over the overflow blocks on this thread.
  template <int Lanes, class Pass>
  void for_each_colour(WorkerPool* pool, Pass pass);
  /// Runs `pass(arrays)` over island batch `batch`'s blocks of each colour in turn, the
  /// overflow last, on this thread.
  template <int Lanes, class Pass>
  void for_each_colour_of_batch(std::size_t batch, Pass pass);
  /// Runs `kernel(arrays)` at this step's lane count over every colour's blocks (shared among
  /// `pool`'s workers, as `for_each_colour`) or, with a `batch`, over that island batch's only
  /// (`for_each_colour_of_batch`); `kernel` takes the blocks of either width.
  template <class Kernel>
  void run_pass(WorkerPool* pool, const std::size_t* batch, Kernel kernel);

  int lanes_ = 4;
  int packed_colours_ = 0;  ///< colours of this step (the overflow not counted)
  bool has_elastic_contacts_ = false;
  bool has_heavy_on_light_ = false;
  std::size_t min_island_batches_ = default_min_island_batches;
  bool finds_islands_ = false;     // this step records its contacts' islands
  bool deferred_ = false;          // lanes given in finish_step, not as each contact is visited
  bool batched_ = false;           // see batched()
  bool last_step_unbatchable_ = false;  // the last step had a bounce or shock stage
  std::size_t last_contact_count_ = 0;  // contacts of the last step
  std::size_t last_batch_count_ = 0;    // island batches of the last step (0: not looked for)
  float shock_mass_ratio_ = 0.0f;  // of this step's context, when it asks for shock propagation
  TouchTally touch_tally_;
  const std::vector<Body>* bodies_ = nullptr;  // between begin_step and finish_step
  const SolverContext* context_ = nullptr;     // between begin_step and finish_step
  WorkerPool* pool_ = nullptr;                 // between begin_step and finish_step
  ContactColouring colouring_;
  IslandBatches islands_;
  /// Per colour (the overflow last) and batch: the index of the batch's first block among the
  /// colour's blocks, entry colour * (batches + 1) + batch; the next entry ends the range.
  std::vector<std::uint32_t> batch_blocks_;
  std::size_t placed_batches_ = 1;  // batches of the layout in batch_blocks_
  std::vector<std::uint32_t> next_lane_;  // place_in_batches' next lane of each colour and batch
  Colours<4> colours_4_;
  Colours<8> colours_8_;
  /// Per contact of the list: its lane among its colour's blocks' lanes (block * lanes +
  /// lane; the colour is `colouring_.colour_of`), -1 when it is not solved.
  std::vector<std::int32_t> lane_of_contact_;
  /// Per contact of the list: 1 when written out since the last `read_back_written` (grown on
  /// demand; all 0 between read-backs).
  std::vector<std::uint8_t> written_out_;
  std::vector<std::uint32_t> written_list_;  ///< those contacts, in the order written out
};

template <int Lanes, class Then>
void WideContactSolver::store_impulses_in_order(std::vector<Contact>& contacts, Then then) const {
  // The blocks are in colour order, not the list's: each contact's lanes (and the contact) are
  // asked for `prefetch_items_ahead` contacts before they are read.
  const Colours<Lanes>& packed = colours<Lanes>();
  const std::size_t count = contacts.size();
  for (std::size_t i = 0; i < count; ++i) {
    if (i + prefetch_items_ahead < count && lane_of_contact_[i + prefetch_items_ahead] >= 0) {
      const auto next = static_cast<std::size_t>(lane_of_contact_[i + prefetch_items_ahead]);
      const ColourBlocks<Lanes>& colour = packed[static_cast<std::size_t>(colouring_.colour_of(i + prefetch_items_ahead))];
      for (const BlockPointImpulse<Lanes>& point : colour.blocks[next / Lanes].points) {
        __builtin_prefetch(&point.normal_impulse[next % Lanes]);
        __builtin_prefetch(&point.tangent_impulse[next % Lanes]);
      }
      __builtin_prefetch(&colour.solves[next / Lanes].friction_at_limit[next % Lanes]);
    }
    if (i + prefetch_items_ahead < count) prefetch_bytes(contacts[i + prefetch_items_ahead]);
    Contact& contact = contacts[i];
    if (lane_of_contact_[i] >= 0) {
      const ColourBlocks<Lanes>& colour = packed[static_cast<std::size_t>(colouring_.colour_of(i))];
      const auto block = static_cast<std::size_t>(lane_of_contact_[i]) / Lanes;
      const auto lane = static_cast<std::size_t>(lane_of_contact_[i]) % Lanes;
      const std::int32_t at_limit = colour.solves[block].friction_at_limit[lane];
      for (int p = 0; p < contact.point_count; ++p) {
        ContactPoint& point = contact.points[p];
        point.normal_impulse = colour.blocks[block].points[p].normal_impulse[lane];
        point.tangent_impulse = colour.blocks[block].points[p].tangent_impulse[lane];
        point.friction_at_limit = (at_limit & (1 << p)) != 0;
      }
    }
    then(contact);
  }
}

}  // namespace impulse2d
