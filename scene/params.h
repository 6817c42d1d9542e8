#pragma once
/// @file params.h
/// Named scene parameters (`--param rows=20`): each scene declares its parameters with a
/// default and a range; the command line and scene files override them by name.

#include <map>
#include <string>
#include <vector>

namespace impulse2d::demos {

/// One parameter a scene accepts.
struct ParamSpec {
  std::string name;            ///< as written on the command line, e.g. "rows"
  std::string description;     ///< one line, with units where physical
  double default_value = 0.0;  ///< used when not overridden
  double minimum = 0.0;        ///< smallest accepted value (inclusive)
  double maximum = 0.0;        ///< largest accepted value (inclusive)
  bool integer = false;        ///< only whole numbers are accepted
};

/// The values of a scene's parameters: defaults overridden by the user's choices.
class Params {
 public:
  /// Every parameter at its default.
  explicit Params(std::vector<ParamSpec> specs = {});

  /// Sets `name` from text such as "20" or "0.5". Throws `UsageError` naming the parameter
  /// and the reason for an unknown name, text that is not a finite number, a fraction given
  /// to an integer parameter, or a value outside the declared range.
  void set(const std::string& name, const std::string& text);
  /// Sets `name` to `value` with the same checks as the text form.
  void set(const std::string& name, double value);
  /// Parses "key=value" and sets it (throws `UsageError` for a missing '=').
  void set_assignment(const std::string& assignment);

  /// The value of `name`. Throws `UsageError` for a name the scene does not declare.
  double number(const std::string& name) const;
  /// The value of an integer parameter.
  int integer(const std::string& name) const;
  /// The declared parameters, in declaration order.
  const std::vector<ParamSpec>& specs() const { return specs_; }
  /// "rows=20 seed=1" (every parameter, declaration order), for labels and traces.
  std::string summary() const;

 private:
  const ParamSpec& spec(const std::string& name) const;
  std::vector<ParamSpec> specs_;
  std::map<std::string, double> values_;
};

/// A number as short as it can be written while reading back exactly (e.g. 20, 0.5).
std::string format_param_value(double value);

}  // namespace impulse2d::demos
