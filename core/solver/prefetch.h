#pragma once
/// @file prefetch.h
/// Hints that ask the cache for an object's bytes before a walk reaches it. The walks over the
/// step's lists (pairs, contacts, bodies) read objects of 300-400 bytes that are too far apart
/// for the hardware to guess the next, and the lists together outgrow the L2 cache from a few
/// thousand bodies on: without the hint each object read is a run of cache misses. A hint
/// changes no result.

#include <cstddef>

namespace impulse2d {

/// How many objects ahead of the one being read a walk asks the cache for: far enough for a
/// miss to the L3 cache to land in time, near enough for what it brings to stay in L1.
constexpr std::size_t prefetch_items_ahead = 8;

/// Asks the cache for bytes [begin, end) of `object` (every 64-byte line they touch).
template <class Object>
inline void prefetch_bytes(const Object& object, std::size_t begin = 0,
                           std::size_t end = sizeof(Object)) {
  const char* bytes = reinterpret_cast<const char*>(&object);
  for (std::size_t offset = begin; offset < end; offset += 64) __builtin_prefetch(bytes + offset);
  __builtin_prefetch(bytes + end - 1);
}

}  // namespace impulse2d
