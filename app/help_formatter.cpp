/// @file help_formatter.cpp
#include "app/help_formatter.h"

#include <sstream>

namespace impulse2d::demos {

namespace {

/// Width of the column of option and command names.
constexpr std::size_t name_column = 30;

/// `name` padded to the name column and `description` wrapped beside it; a name too long for
/// the column puts the description on the next line.
std::string format_entry(const std::string& name, const std::string& description) {
  std::string line = "  " + name;
  if (description.empty()) return line + "\n";
  if (line.size() >= name_column) {
    line += "\n";
    line += std::string(name_column, ' ');
  } else {
    line += std::string(name_column - line.size(), ' ');
  }
  return line + wrap_text(description, help_width - name_column, name_column) + "\n";
}

}  // namespace

std::string wrap_text(const std::string& text, std::size_t width, std::size_t indent) {
  std::string result;
  std::istringstream lines(text);
  std::string paragraph;
  bool first_paragraph = true;
  while (std::getline(lines, paragraph)) {
    const std::size_t own_indent = paragraph.find_first_not_of(' ') == std::string::npos
                                       ? 0
                                       : paragraph.find_first_not_of(' ');
    const std::size_t continuation = own_indent > 0 ? own_indent + 2 : 0;
    if (!first_paragraph) result += "\n" + std::string(indent, ' ');
    first_paragraph = false;
    std::string line(own_indent, ' ');
    std::istringstream words(paragraph);
    bool line_empty = true;
    for (std::string word; words >> word;) {
      if (!line_empty && line.size() + 1 + word.size() > width) {
        result += line + "\n" + std::string(indent, ' ');
        line = std::string(continuation, ' ');
        line_empty = true;
      }
      line += (line_empty ? "" : " ") + word;
      line_empty = false;
    }
    result += line;
  }
  return result;
}

HelpFormatter::HelpFormatter() { column_width(name_column); }

std::string HelpFormatter::make_option(const CLI::Option* option, bool is_positional) const {
  const std::string name =
      make_option_name(option, is_positional) + (is_positional ? "" : make_option_opts(option));
  return format_entry(name, make_option_desc(option));
}

std::string HelpFormatter::make_subcommand(const CLI::App* command) const {
  return format_entry(command->get_display_name(true), command->get_description());
}

std::string HelpFormatter::make_description(const CLI::App* app) const {
  const std::string description = CLI::Formatter::make_description(app);
  return description.empty() ? description : wrap_text(description, help_width, 0) + "\n";
}

std::string HelpFormatter::make_footer(const CLI::App* app) const {
  const std::string footer = CLI::Formatter::make_footer(app);
  return footer.empty() ? footer : wrap_text(footer, help_width, 0) + "\n";
}

}  // namespace impulse2d::demos
