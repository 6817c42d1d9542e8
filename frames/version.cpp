/// @file version.cpp
#include "frames/version.h"

namespace impulse2d::demos {

std::string program_version() { return IMPULSE2D_VERSION; }

}  // namespace impulse2d::demos
