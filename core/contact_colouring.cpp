#include "core/contact_colouring.h"

#include "core/contact_solver_internal.h"

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

void ContactColouring::finish() {
  // Counting sort by colour, stable: each colour keeps the contact list's order.
  starts_.assign(static_cast<std::size_t>(colour_count_) + 2, 0);
  for (int c = 0; c < colour_count_; ++c) starts_[c + 1] = starts_[c] + counts_[c];
  starts_[colour_count_ + 1] = starts_[colour_count_] + counts_[overflow_colour];
  order_.resize(starts_[colour_count_ + 1]);
  std::size_t next[max_colours + 1] = {};
  for (int c = 0; c < colour_count_; ++c) next[c] = starts_[c];
  next[overflow_colour] = starts_[colour_count_];
  for (std::size_t i = 0; i < colour_of_.size(); ++i) {
    if (colour_of_[i] == not_solved) continue;
    order_[next[colour_of_[i]]++] = static_cast<std::uint32_t>(i);
  }
}

void ContactColouring::colour(const std::vector<Contact>& contacts, std::size_t slot_count) {
  begin(slot_count);
  for (const Contact& contact : contacts) add(contact);
  finish();
}

}  // namespace impulse2d
