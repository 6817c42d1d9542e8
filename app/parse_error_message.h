#pragma once
/// @file parse_error_message.h
/// The one-line explanation of a command-line error CLI11 found, in the program's own words:
/// prefixed `impulse2d:`, naming the command it happened in, "unknown command" or "unknown
/// option" with a "did you mean ...?" for a misspelling, and where to find the usage.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace impulse2d::demos {

/// The message (ending in a newline) for `error`, thrown while `app` parsed `arguments` (the
/// command line without the program name).
std::string parse_error_message(CLI::App& app, const CLI::ParseError& error,
                                const std::vector<std::string>& arguments);

}  // namespace impulse2d::demos
