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

  /// Sets `name` from text such as "20", "-1" or "0.5", read strictly (no '+', space or hex,
  /// see strict_number.h), with the checks of the number form.
  void set(const std::string& name, const std::string& text);
  /// Sets `name` to `value`. Throws `UsageError` naming the parameter and the reason for an
  /// unknown name, a value that is not finite, a fraction given to an integer parameter, or a
  /// value outside the declared range.
  void set(const std::string& name, double value);
  /// Parses "key=value" (the value strict: digits, one '.', an exponent, a leading '-'; no
  /// '+', space or hex, see strict_number.h) and sets it with the checks of `set`; messages
  /// start with "--param key=value: ". Throws `UsageError` for a missing '=' too.
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
  const ParamSpec* find(const std::string& name) const;
  const ParamSpec& spec(const std::string& name) const;
  std::string unknown_reason(const std::string& name) const;
  static std::string value_reason(const ParamSpec& declared, double value);
  std::vector<ParamSpec> specs_;
  std::map<std::string, double> values_;
};

/// A number as short as it can be written while reading back exactly (e.g. 20, 0.5).
std::string format_param_value(double value);

}  // namespace impulse2d::demos
