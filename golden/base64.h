#pragma once
/// @file base64.h
/// Standard base64 (RFC 4648, with padding), for images embedded in the HTML report.

#include <cstdint>
#include <string>
#include <vector>

namespace impulse2d::golden {

/// The base64 text of `bytes`, padded with '=' to a multiple of 4 characters.
std::string base64_encode(const std::vector<std::uint8_t>& bytes);

}  // namespace impulse2d::golden
