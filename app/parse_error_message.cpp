/// @file parse_error_message.cpp
#include "app/parse_error_message.h"

#include <optional>
#include <sstream>

#include "app/spelling.h"

namespace impulse2d::demos {
namespace {

/// The subcommands of `command`, in declaration order.
std::vector<CLI::App*> subcommands_of(CLI::App& command) {
  return command.get_subcommands([](CLI::App*) { return true; });
}

/// The subcommand of `command` called `name`, or nullptr.
CLI::App* find_subcommand(CLI::App& command, const std::string& name) {
  for (CLI::App* sub : subcommands_of(command)) {
    if (sub->check_name(name)) return sub;
  }
  return nullptr;
}

/// The arguments an `ExtrasError` lists ("... not expected: c b a", CLI11 lists them last
/// first), in command-line order.
std::vector<std::string> unexpected_arguments(const CLI::ParseError& error) {
  const std::string message = error.what();
  const std::string marker = "expected: ";
  const std::size_t at = message.find(marker);
  std::vector<std::string> tokens;
  if (at == std::string::npos) return tokens;
  std::istringstream words(message.substr(at + marker.size()));
  for (std::string word; words >> word;) tokens.insert(tokens.begin(), word);
  return tokens;
}

/// `--name` of `--name=value`.
std::string option_name(const std::string& token) { return token.substr(0, token.find('=')); }

/// True when `name` is an option of `command` or of a command it falls through to.
bool is_known_option(CLI::App* command, const std::string& name) {
  for (CLI::App* each = command; each != nullptr; each = each->get_parent()) {
    if (each->get_option_no_throw(name) != nullptr) return true;
    if (!each->get_fallthrough()) break;
  }
  return false;
}

/// Every option spelling ("--out", "-o") `command` accepts, its parents' included.
std::vector<std::string> option_spellings(CLI::App* command) {
  std::vector<std::string> names;
  for (CLI::App* each = command; each != nullptr; each = each->get_parent()) {
    for (const CLI::Option* option : each->get_options()) {
      for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
      for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
    if (!each->get_fallthrough()) break;
  }
  return names;
}

/// " (did you mean 'render'?)" when `word` looks like a misspelling of one of `known`.
std::string suggestion(const std::string& word, const std::vector<std::string>& known) {
  const std::optional<std::string> closest = closest_spelling(word, known);
  return closest ? " (did you mean '" + *closest + "'?)" : "";
}

}  // namespace

std::string parse_error_message(CLI::App& app, const CLI::ParseError& error,
                                const std::vector<std::string>& arguments) {
  // The command the error happened in: the deepest subcommand named on the command line.
  CLI::App* command = &app;
  std::string path;
  std::vector<std::string> after_command;  // the arguments after the command's name
  for (const std::string& token : arguments) {
    CLI::App* sub = token.empty() || token[0] == '-' ? nullptr : find_subcommand(*command, token);
    if (sub != nullptr) {
      command = sub;
      path += (path.empty() ? "" : " ") + sub->get_name();
      after_command.clear();
    } else {
      after_command.push_back(token);
    }
  }
  const std::string where = path.empty() ? "" : path + ": ";
  const std::string help =
      "Run 'impulse2d " + (path.empty() ? "" : path + " ") + "--help' for the usage.\n";

  const bool missing_subcommand = dynamic_cast<const CLI::RequiredError*>(&error) != nullptr &&
                                  std::string(error.what()).find("subcommand") != std::string::npos;
  if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr || missing_subcommand) {
    const std::vector<std::string> rest =
        missing_subcommand ? after_command : unexpected_arguments(error);
    for (const std::string& token : rest) {
      if (token.size() < 2 || token[0] != '-') continue;
      const std::string name = option_name(token);
      if (is_known_option(command, name)) continue;
      return "impulse2d: " + where + "unknown option '" + name + "'" +
             suggestion(name, option_spellings(command)) + "\n" + help;
    }
    for (const std::string& token : rest) {
      if (token.empty() || token[0] == '-') continue;
      const std::vector<CLI::App*> subs = subcommands_of(*command);
      if (subs.empty()) {
        return "impulse2d: " + where + "unexpected argument '" + token + "'\n" + help;
      }
      std::vector<std::string> names;
      for (const CLI::App* sub : subs) names.push_back(sub->get_name());
      return "impulse2d: " + where + "unknown command '" + token + "'" +
             suggestion(token, names) + "\n" + help;
    }
  }
  if (missing_subcommand) {
    std::string names;
    for (const CLI::App* sub : subcommands_of(*command)) {
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    return "impulse2d: " + where + "a command is required: " + names + "\n" + help;
  }
  return "impulse2d: " + where + error.what() + "\n" + help;
}

}  // namespace impulse2d::demos
