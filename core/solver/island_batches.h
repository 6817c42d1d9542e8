#pragma once
/// @file island_batches.h
/// A step's solvable contacts and moving bodies grouped into batches of whole islands (sets of
/// bodies that the step's contacts join, static bodies joining nothing), each batch about
/// `target_contacts` contacts or one larger island. No contact of one batch touches a body of
/// another that the step moves, so the soft step can run every sub-step of a batch before the
/// next batch (while its blocks and bodies are in the cache) instead of streaming every
/// contact of the world through each pass: every body sees the same operations in the same
/// order, so the results are bit-identical to solving the whole world pass by pass.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace impulse2d {

/// Union-find over a step's body slots and the batches made from it (buffers reused from step
/// to step: no allocation once warm).
class IslandBatches {
 public:
  /// Contacts a batch collects before the next one starts: about 0.4 MB of contact blocks
  /// (`contact_block.h`, ~210 bytes a contact) and their bodies, so that a batch's sub-steps
  /// run in a core's L2 cache.
  static constexpr std::size_t target_contacts = 2048;

  /// Starts a step over `slot_count` body slots, no slot joined to another.
  void begin(std::size_t slot_count);
  /// Records the step's next solvable contact, between slots `a` and `b`; a slot whose flag
  /// (`a_joins`, `b_joins`) is false (a static body) joins nothing. One of the flags is true.
  void add_contact(std::uint32_t a, bool a_joins, std::uint32_t b, bool b_joins);
  /// Makes the batches of the recorded contacts: islands in the order of their first contact,
  /// gathered until a batch reaches `target_contacts`.
  void make_batches();
  /// After `make_batches`, lists each batch's body slots: the slots for which `moves(slot)` is
  /// true (those the sub-steps integrate), each in its island's batch; those of no contact go
  /// to one more batch after the others, the rest batch (no contacts).
  template <class Moves>
  void gather_bodies(Moves moves);

  /// Batches with contacts (the rest batch not counted).
  std::size_t batch_count() const { return batch_count_; }
  /// Batch of the `k`-th contact recorded by `add_contact`.
  std::uint32_t batch_of_contact(std::size_t k) const { return contact_batch_[k]; }
  /// Body slots of batch `batch` (0..batch_count(); batch_count() is the rest batch).
  const std::uint32_t* bodies_of(std::size_t batch) const {
    return body_slots_.data() + body_begin_[batch];
  }
  /// Number of body slots of batch `batch` (see `bodies_of`).
  std::size_t body_count(std::size_t batch) const {
    return body_begin_[batch + 1] - body_begin_[batch];
  }

 private:
  static constexpr std::uint32_t no_batch = 0xFFFFFFFFu;
  std::uint32_t root_of(std::uint32_t slot);
  void sort_bodies_by_batch();

  std::vector<std::uint32_t> parent_;         // per slot: union-find parent
  std::vector<std::uint32_t> root_contacts_;  // per root slot: its island's contacts
  std::vector<std::uint32_t> root_batch_;     // per root slot: its island's batch, or no_batch
  std::vector<std::uint32_t> contact_slot_;   // per recorded contact: a slot it joins
  std::vector<std::uint32_t> contact_batch_;  // per recorded contact: its batch
  std::vector<std::uint32_t> slot_batch_;     // per slot: its batch (rest: batch_count_), or no_batch
  std::vector<std::uint32_t> body_begin_;     // per batch and the rest: first of body_slots_
  std::vector<std::uint32_t> body_slots_;     // the slots, batch after batch
  std::vector<std::uint32_t> next_slot_;      // per batch: the next free place in body_slots_
  std::size_t batch_count_ = 0;
};

template <class Moves>
void IslandBatches::gather_bodies(Moves moves) {
  const std::size_t slots = parent_.size();
  slot_batch_.resize(slots);
  for (std::size_t slot = 0; slot < slots; ++slot) {
    std::uint32_t batch = no_batch;
    if (moves(slot)) {
      batch = root_batch_[root_of(static_cast<std::uint32_t>(slot))];
      if (batch == no_batch) batch = static_cast<std::uint32_t>(batch_count_);
    }
    slot_batch_[slot] = batch;
  }
  sort_bodies_by_batch();
}

}  // namespace impulse2d
