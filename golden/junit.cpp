/// @file junit.cpp
#include "golden/junit.h"

#include <sstream>

#include "golden/report.h"

namespace impulse2d::golden {

std::string junit_xml(const std::string& suite, const std::vector<JUnitCase>& cases) {
  int failures = 0;
  int skipped = 0;
  double seconds = 0.0;
  for (const JUnitCase& test : cases) {
    failures += test.failed ? 1 : 0;
    skipped += !test.failed && !test.skipped.empty() ? 1 : 0;
    seconds += test.seconds;
  }
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites tests=\"" << cases.size()
      << "\" failures=\"" << failures << "\" time=\"" << seconds << "\">\n  <testsuite name=\""
      << escape_html(suite) << "\" tests=\"" << cases.size() << "\" failures=\"" << failures
      << "\" errors=\"0\" skipped=\"" << skipped << "\" time=\"" << seconds << "\">\n";
  for (const JUnitCase& test : cases) {
    xml << "    <testcase classname=\"" << escape_html(test.classname) << "\" name=\""
        << escape_html(test.name) << "\" time=\"" << test.seconds << "\"";
    if (!test.failed && test.skipped.empty()) {
      xml << "/>\n";
      continue;
    }
    if (!test.failed) {
      xml << ">\n      <skipped message=\"" << escape_html(test.skipped) << "\"/>\n    </testcase>\n";
      continue;
    }
    xml << ">\n      <failure type=\"" << escape_html(test.failure_type) << "\" message=\""
        << escape_html(test.failure_type) << "\">" << escape_html(test.failure_message)
        << "</failure>\n    </testcase>\n";
  }
  xml << "  </testsuite>\n</testsuites>\n";
  return xml.str();
}

}  // namespace impulse2d::golden
