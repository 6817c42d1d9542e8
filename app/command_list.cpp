/// @file command_list.cpp
/// `impulse2d list`: every built-in scene with its description, model, run and parameters.
#include <CLI/CLI.hpp>

#include "app/command.h"
#include "demos/scene_registry.h"
#include "scene/params.h"
#include "scene/scene_model.h"

namespace impulse2d::demos {
namespace {

void list_scenes(std::ostream& out) {
  for (const Scene& scene : builtin_scenes()) {
    out << scene.name << "\n  " << scene.description << "\n  model: " << describe_model(scene.model)
        << "\n  run: " << scene.view.steps << " steps, frames " << scene.view.frames << "\n";
    for (const ParamSpec& param : scene.params) {
      out << "  --param " << param.name << "=" << format_param_value(param.default_value) << "  ("
          << format_param_value(param.minimum) << ".." << format_param_value(param.maximum) << ") "
          << param.description << "\n";
    }
  }
  out << "\nA scene file (.json) can be given wherever a scene name is accepted.\n";
}

}  // namespace

Command add_list_command(CLI::App& program, const ProgramOptions&) {
  Command command;
  command.parser =
      program.add_subcommand("list", "list the built-in scenes with their parameters and models");
  command.dry_run = [](std::ostream& out) {
    out << "dry run: list: the " << builtin_scenes().size()
        << " built-in scenes with their models and parameters, to standard output\n"
        << "nothing was run or written\n";
  };
  command.run = [](std::ostream& out) {
    list_scenes(out);
    return 0;
  };
  return command;
}

}  // namespace impulse2d::demos
