/// @file lab_result.cpp
#include "lab/lab_result.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

#include "scene/usage_error.h"

namespace impulse2d::lab {
namespace {

const char* const header_fields[] = {
    "job", "scenario", "engine", "method", "solver", "velocity_iterations",
    "position_iterations", "substeps", "position_correction", "integrator", "time_step",
    "continuous", "speculative_margin", "friction_mixing", "restitution_mixing", "warm_starting", "block_solver",
    "shock_propagation", "steps", "bodies", "repeats", "ns_per_step", "ns_per_step_body", "us_per_simulated_second",
    "instructions_per_step", "error", "unit", "threshold", "pass", "pareto", "recommended",
    "failure_reason"};
constexpr std::size_t field_count = sizeof(header_fields) / sizeof(header_fields[0]);

std::string number(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[64];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

std::string quoted(const std::string& text) {
  std::string result = "\"";
  for (const char c : text) result += c == '"' ? std::string("\"\"") : std::string(1, c);
  return result + "\"";
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

template <typename Values, typename Namer>
typename Values::value_type parse_name(const std::string& text, const Values& values, Namer name,
                                       const std::string& where) {
  for (const typename Values::value_type value : values) {
    if (text == name(value)) return value;
  }
  throw demos::UsageError(where + ": unknown value \"" + text + "\"");
}

}  // namespace

void mark_fronts(std::vector<LabResult>& results) {
  std::map<std::string, std::vector<LabResult*>> by_scenario;
  for (LabResult& result : results) {
    result.pareto = false;
    result.recommended = false;
    by_scenario[result.scenario].push_back(&result);
  }
  for (auto& [scenario, rows] : by_scenario) {
    std::sort(rows.begin(), rows.end(), [](const LabResult* a, const LabResult* b) {
      if (a->us_per_simulated_second != b->us_per_simulated_second)
        return a->us_per_simulated_second < b->us_per_simulated_second;
      if (a->error != b->error) return a->error < b->error;
      return a->job < b->job;
    });
    double best_error = std::numeric_limits<double>::infinity();
    LabResult* recommended = nullptr;
    for (LabResult* row : rows) {
      if (row->error < best_error) {
        row->pareto = true;
        best_error = row->error;
      }
      // Mixing rules change the physics (and with it the exact answer), so a method that
      // passes by mixing differently is not a cheaper way to the same answer.
      const LabMethod defaults;
      const bool same_model = row->method.friction_mixing == defaults.friction_mixing &&
                              row->method.restitution_mixing == defaults.restitution_mixing;
      if (!recommended && row->pass && same_model && row->method.engine == Engine::Impulse2d)
        recommended = row;
    }
    if (recommended) recommended->recommended = true;
  }
}

std::string csv_header() {
  std::string line;
  for (std::size_t i = 0; i < field_count; ++i) line += (i ? "," : "") + std::string(header_fields[i]);
  return line;
}

std::string csv_line(const LabResult& r) {
  const LabMethod& m = r.method;
  std::ostringstream line;
  line << r.job << ',' << r.scenario << ',' << engine_name(m.engine) << ',' << method_label(m)
       << ',' << solver_name(m.solver) << ',' << m.velocity_iterations << ','
       << m.position_iterations << ',' << m.substeps << ','
       << correction_name(m.position_correction) << ',' << integrator_name(m.integrator) << ','
       << number(m.time_step) << ',' << (m.continuous ? 1 : 0) << ','
       << number(m.speculative_margin) << ','
       << friction_mixing_name(m.friction_mixing) << ','
       << restitution_mixing_name(m.restitution_mixing) << ',' << (m.warm_starting ? 1 : 0)
       << ',' << (m.block_solver ? 1 : 0) << ',' << (m.shock_propagation ? 1 : 0) << ',' << r.steps << ',' << r.bodies << ','
       << r.repeats << ',' << number(r.ns_per_step) << ',' << number(r.ns_per_step_body) << ','
       << number(r.us_per_simulated_second) << ',' << number(r.instructions_per_step) << ','
       << number(r.error) << ',' << r.unit << ',' << number(r.threshold) << ','
       << (r.pass ? 1 : 0) << ',' << (r.pareto ? 1 : 0) << ',' << (r.recommended ? 1 : 0) << ','
       << quoted(r.failure);
  return line.str();
}

std::vector<LabResult> parse_csv(const std::string& text, const std::string& file) {
  std::istringstream lines(text);
  std::string line;
  std::vector<LabResult> results;
  int line_number = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string where = file + ":" + std::to_string(line_number);
    if (line_number == 1) {
      if (line != csv_header()) throw demos::UsageError(where + ": not a lab CSV (header differs)");
      continue;
    }
    if (line.empty()) continue;
    const std::vector<std::string> f = split_csv_line(line);
    if (f.size() != field_count) {
      throw demos::UsageError(where + ": expected " + std::to_string(field_count) +
                              " fields, got " + std::to_string(f.size()));
    }
    const auto integer = [&](std::size_t i) {
      try {
        std::size_t used = 0;
        const long long value = std::stoll(f[i], &used);
        if (used != f[i].size()) throw std::invalid_argument("trailing");
        return value;
      } catch (const std::exception&) {
        throw demos::UsageError(where + ": " + header_fields[i] + ": not an integer: \"" + f[i] + "\"");
      }
    };
    const auto real = [&](std::size_t i) {
      try {
        std::size_t used = 0;
        const double value = std::stod(f[i], &used);
        if (used != f[i].size()) throw std::invalid_argument("trailing");
        return value;
      } catch (const std::exception&) {
        throw demos::UsageError(where + ": " + header_fields[i] + ": not a number: \"" + f[i] + "\"");
      }
    };
    const auto field_where = [&](std::size_t i) { return where + ": " + header_fields[i]; };
    LabResult r;
    LabMethod& m = r.method;
    r.job = integer(0);
    r.scenario = f[1];
    m.engine = parse_name(f[2], std::vector<Engine>{Engine::Impulse2d, Engine::Box2d, Engine::Chipmunk},
                          engine_name, field_where(2));
    m.solver = parse_name(f[4], solver_methods(), solver_name, field_where(4));
    m.velocity_iterations = static_cast<int>(integer(5));
    m.position_iterations = static_cast<int>(integer(6));
    m.substeps = static_cast<int>(integer(7));
    m.position_correction = parse_name(f[8], std::vector<PositionCorrection>{PositionCorrection::None,
                                              PositionCorrection::LinearProjection,
                                              PositionCorrection::NonlinearGaussSeidel},
                                       correction_name, field_where(8));
    m.integrator = parse_name(f[9], std::vector<Integrator>{Integrator::ExplicitEuler, Integrator::SemiImplicitEuler},
                              integrator_name, field_where(9));
    m.time_step = static_cast<float>(real(10));
    m.continuous = integer(11) != 0;
    m.speculative_margin = static_cast<float>(real(12));
    m.friction_mixing = parse_name(f[13], std::vector<FrictionMixing>{FrictionMixing::RootSumSquares,
                                           FrictionMixing::GeometricMean, FrictionMixing::Product,
                                           FrictionMixing::Average, FrictionMixing::Minimum,
                                           FrictionMixing::Maximum},
                                   friction_mixing_name, field_where(13));
    m.restitution_mixing = parse_name(f[14], std::vector<RestitutionMixing>{RestitutionMixing::Minimum,
                                              RestitutionMixing::Maximum,
                                              RestitutionMixing::Average},
                                      restitution_mixing_name, field_where(14));
    m.warm_starting = integer(15) != 0;
    m.block_solver = integer(16) != 0;
    m.shock_propagation = integer(17) != 0;
    r.steps = integer(18);
    r.bodies = static_cast<int>(integer(19));
    r.repeats = static_cast<int>(integer(20));
    r.ns_per_step = real(21);
    r.ns_per_step_body = real(22);
    r.us_per_simulated_second = real(23);
    r.instructions_per_step = real(24);
    r.error = real(25);
    r.unit = f[26];
    r.threshold = real(27);
    r.pass = integer(28) != 0;
    r.pareto = integer(29) != 0;
    r.recommended = integer(30) != 0;
    r.failure = f[31];
    results.push_back(r);
  }
  if (line_number == 0) throw demos::UsageError(file + ": empty file, expected a lab CSV");
  return results;
}

}  // namespace impulse2d::lab
