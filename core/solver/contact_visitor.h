#pragma once
/// @file contact_visitor.h
/// A hook into the narrow phase's walk: a solver that has per-contact work to do at the start
/// of a step (prepare, colour) does it on each contact as the narrow phase finishes it, while
/// the contact is still in the cache, instead of walking the whole list again.

#include "core/contact.h"

#include <cstddef>

namespace impulse2d {

/// Sees each contact of a step's new list once, in list order, as soon as the narrow phase has
/// written it.
class ContactVisitor {
 public:
  /// Contact `index` of the new list is final for this narrow phase; `contact` is that element.
  virtual void visit(std::size_t index, Contact& contact) = 0;

 protected:
  ~ContactVisitor() = default;
};

}  // namespace impulse2d
