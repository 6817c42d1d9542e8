#include "core/solver/contact_colouring.h"

#include "core/solver/contact_solver_internal.h"

#include <algorithm>

namespace impulse2d {

namespace {

constexpr std::uint8_t overflow_colour = ContactColouring::max_colours;

// Index of the lowest clear bit of `used` (which has one).
int lowest_free_colour(std::uint64_t used) {
  const std::uint64_t free_bits = ~used;
  return __builtin_ctzll(free_bits);
}

}  // namespace

void ContactColouring::begin(std::size_t slot_count) {
  used_colours_.assign(slot_count, 0);
  colour_of_.clear();
  std::fill(std::begin(counts_), std::end(counts_), std::size_t{0});
  colour_count_ = 0;
}

int ContactColouring::add(const Contact& contact) {
  if (!contact_detail::is_solvable(contact)) {
    colour_of_.push_back(not_solved);
    return -1;
  }
  const bool moves_a = contact_detail::moves_a(contact.mass);
  const bool moves_b = contact_detail::moves_b(contact.mass);
  std::uint64_t& used_a = used_colours_[contact.body_a.index];
  std::uint64_t& used_b = used_colours_[contact.body_b.index];
  const std::uint64_t used = (moves_a ? used_a : 0) | (moves_b ? used_b : 0);
  std::uint8_t colour = overflow_colour;
  if (used != ~std::uint64_t{0}) {
    const int free = lowest_free_colour(used);
    colour = static_cast<std::uint8_t>(free);
    const std::uint64_t bit = std::uint64_t{1} << free;
    if (moves_a) used_a |= bit;
    if (moves_b) used_b |= bit;
    colour_count_ = std::max(colour_count_, free + 1);
  }
  colour_of_.push_back(colour);
  ++counts_[colour];
  return colour;
}

}  // namespace impulse2d
