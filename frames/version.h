#pragma once
/// @file version.h
/// The program's version, as `impulse2d --version` prints it and every frame's PNG metadata
/// records it.

#include <string>

namespace impulse2d::demos {

/// "0.1.0": the project version CMake was configured with.
std::string program_version();

}  // namespace impulse2d::demos
