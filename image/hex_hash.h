#pragma once
/// @file hex_hash.h
/// 64-bit hashes as text: 16 lower-case hex digits, the form sidecars and messages use.

#include <cstdint>
#include <optional>
#include <string>

namespace impulse2d::image {

/// 16 lower-case hex digits, zero-padded, no prefix.
std::string to_hex_hash(std::uint64_t hash);

/// The hash spelled by exactly 16 hex digits (either case, no prefix); nullopt otherwise.
std::optional<std::uint64_t> parse_hex_hash(const std::string& text);

}  // namespace impulse2d::image
