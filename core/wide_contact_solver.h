#pragma once
/// @file wide_contact_solver.h
/// The soft step's contact solve on compact arrays: a 32-byte `SolverBody` per body slot and
/// the step's contacts coloured (`contact_colouring.h`) and packed into `ContactBlock`s of 4
/// or 8 lanes, solved by the vector kernels (`wide_contact_kernels.h`). The lanes of a block
/// share no moving body, so 4 and 8 lanes give bit-identical results.
///
/// Per step: `begin_step` prepares (`contact_prepare.h`), colours and packs the contacts; the
/// passes work on the step's `SolverBodies` (`solver_bodies.h`), and `store_impulses` writes
/// the impulses back to the contacts (and `load_points` reads them in again after the bounce
/// stages changed them).
#include "core/body.h"
#include "core/contact.h"
#include "core/contact_block.h"
#include "core/contact_colouring.h"
#include "core/solver_body.h"
#include "core/solver_context.h"

#include <vector>

namespace impulse2d {

/// The wide solver's arrays for one world (reused from step to step: no allocation once warm).
class WideContactSolver {
 public:
  /// Lanes per block this CPU runs best: 8 with AVX2 (x86-64), else 4.
  static int widest_lanes();

  /// Prepares the step's `contacts` between `bodies` (as `prepare_contacts` does), colours
  /// them and packs them into blocks of `lanes` (4 or 8, 8 only where `widest_lanes()` is 8;
  /// 0: the widest).
  void begin_step(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                  const SolverContext& context, int lanes);
  /// Copies each point's accumulated impulses and bounce plan (`velocity_bias`, `bouncing`,
  /// `waiting`) in, after the bounce stages changed them in the contacts.
  void load_points(const std::vector<Contact>& contacts);
  /// Copies each point's accumulated impulses and `friction_at_limit` out to the contacts.
  void store_impulses(std::vector<Contact>& contacts) const;

  /// Applies the accumulated impulses to `bodies` (one state per body slot: warm starting).
  void warm_start(SolverBody* bodies);
  /// One soft (`use_bias`) or relax pass over every block, colour by colour, on `bodies`.
  void solve(const SolverContext& context, bool use_bias, SolverBody* bodies);

  /// True when some contact of this step has restitution > 0: without one (and so in any
  /// resting pile) the bounce stages change nothing and are skipped.
  bool has_elastic_contacts() const { return has_elastic_contacts_; }
  /// Lanes per block of this step (4 or 8).
  int lanes() const { return lanes_; }
  /// Colours of this step's contacts (the overflow not counted).
  int colour_count() const { return colouring_.colour_count(); }

 private:
  /// A step's blocks of `Lanes` lanes, in their three parts (`contact_block.h`).
  template <int Lanes>
  struct BlockStorage {
    static constexpr int lanes = Lanes;  ///< contacts side by side
    std::vector<ContactBlock<Lanes>> blocks;       ///< read by every pass
    std::vector<ContactBlockSolve<Lanes>> solves;  ///< read by both solve passes
    std::vector<ContactBlockStick<Lanes>> sticks;  ///< read by the biased pass
    /// The three arrays as the kernels take them.
    ContactBlockArrays<Lanes> arrays() {
      return {blocks.data(), solves.data(), sticks.data(), blocks.size()};
    }
  };

  template <int Lanes>
  BlockStorage<Lanes>& storage();
  template <int Lanes>
  void pack(const std::vector<Contact>& contacts);

  int lanes_ = 4;
  bool has_elastic_contacts_ = false;
  ContactColouring colouring_;
  BlockStorage<4> storage_4_;
  BlockStorage<8> storage_8_;
  /// Per lane of the blocks, in order: the index of its contact in the list, -1 when unused.
  std::vector<std::int32_t> contact_index_;
};

}  // namespace impulse2d
