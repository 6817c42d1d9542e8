#pragma once
/// @file junit.h
/// A JUnit XML report of golden checks, the format CI test reporters (GitLab, Jenkins,
/// GitHub actions that publish test results) read.

#include <string>
#include <vector>

namespace impulse2d::golden {

/// One golden check as a JUnit test case.
struct JUnitCase {
  std::string classname;  ///< the scene, e.g. "dominoes"
  std::string name;       ///< the golden frame, e.g. "landed"
  double seconds = 0.0;   ///< how long the check took
  bool failed = false;    ///< true for a failure
  std::string skipped;    ///< why only part was checked (e.g. no baseline); empty: none
  std::string failure_type;     ///< the failure class id, e.g. "behaviour_changed"
  std::string failure_message;  ///< the full failure message
};

/// `<testsuites><testsuite name=suite ...><testcase .../>...` as text.
std::string junit_xml(const std::string& suite, const std::vector<JUnitCase>& cases);


}  // namespace impulse2d::golden
