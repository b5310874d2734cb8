#pragma once
// Text from manifests, scene names and messages goes into the HTML report and
// the JUnit XML; escaped here once for both, so a case name can never close a
// tag or an attribute.
#include <string>

namespace physdbg::golden {

// &, <, >, " and ' as entities; control characters other than tab and line
// breaks (XML 1.0 allows none) as '?'.
std::string escapeMarkup(const std::string& text);

}  // namespace physdbg::golden
