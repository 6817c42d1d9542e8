#pragma once
/// @file contact_colouring.h
/// Graph colouring of a step's contacts: contacts of one colour share no body the solve moves,
/// so they can be solved side by side in one vector instruction without one lane's impulse
/// changing another lane's body (Box2D v3's constraint graph). Greedy, in the contact list's
/// order, each contact taking the lowest colour neither of its moving bodies has yet: the same
/// contacts always get the same colours.

#include "core/contact.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace impulse2d {

/// Colours of a step's solvable contacts, with reusable buffers (no allocation once warm).
class ContactColouring {
 public:
  /// Colours beyond which a contact goes to the overflow (solved one at a time, last).
  static constexpr int max_colours = 64;

  /// Starts a step's colouring for contacts between `slot_count` body slots; then `add` is
  /// called for every contact in the list's order (its `PairMass` already resolved), in the
  /// walk over the list that prepares them. A contact is solvable when it is enabled and one
  /// of its bodies has a finite mass; a body moves under a contact when its inverse mass or
  /// inverse inertia in the contact's `PairMass` is nonzero.
  void begin(std::size_t slot_count);
  /// Colours the list's next contact (the first after `begin`, then one after another) and
  /// returns its colour: 0..max_colours - 1, max_colours for the overflow, -1 when it is not
  /// solved.
  int add(const Contact& contact);

  /// Colour of the list's contact `index` as `add` returned it (valid from that call on).
  int colour_of(std::size_t index) const {
    const std::uint8_t colour = colour_of_[index];
    return colour == not_solved ? -1 : colour;
  }
  /// Contacts of colour `colour` added so far (`max_colours`: the overflow).
  std::size_t count(int colour) const { return counts_[static_cast<std::size_t>(colour)]; }
  /// Number of colours used, 0..max_colours (the overflow not counted).
  int colour_count() const { return colour_count_; }

 private:
  static constexpr std::uint8_t not_solved = 0xFF;  // colour_of_ of a contact not solved
  std::vector<std::uint64_t> used_colours_;  // per body slot: colours its contacts took
  std::vector<std::uint8_t> colour_of_;      // per contact; not_solved when not solved
  std::size_t counts_[max_colours + 1] = {};  // contacts per colour, the overflow last
  int colour_count_ = 0;
};

}  // namespace impulse2d
