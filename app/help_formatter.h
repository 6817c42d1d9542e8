#pragma once
/// @file help_formatter.h
/// The help's layout: CLI11's, with every line wrapped to `help_width` columns (CLI11 2.1
/// writes each description on one line, however long).

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>

namespace impulse2d::demos {

/// The widest line of any help text, in columns.
inline constexpr std::size_t help_width = 100;

/// CLI11's formatter with option names in a column of 30 and descriptions, the program's and
/// commands' descriptions and footers wrapped at word boundaries to `help_width` columns.
class HelpFormatter : public CLI::Formatter {
 public:
  HelpFormatter();
  /// One option: its name column, then its description wrapped beside it.
  std::string make_option(const CLI::Option* option, bool is_positional) const override;
  /// One command of a list: its name, then its description wrapped beside it.
  std::string make_subcommand(const CLI::App* command) const override;
  /// The description over the usage line, wrapped.
  std::string make_description(const CLI::App* app) const override;
  /// The footer, wrapped.
  std::string make_footer(const CLI::App* app) const override;
};

/// `text` wrapped at spaces into lines of at most `width` columns, each line after the first
/// starting with `indent` spaces; a line of `text` that starts with spaces keeps them (and its
/// continuation lines are indented two more). Words longer than a line stay whole.
std::string wrap_text(const std::string& text, std::size_t width, std::size_t indent);

}  // namespace impulse2d::demos
