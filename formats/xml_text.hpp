// Text inside an XML document (the JUnit report, the counterexample's SVG): the five special characters escaped,
// and the bytes XML 1.0 cannot hold (control characters but tab, newline and carriage return) as U+FFFD, so that
// whatever a candidate wrote, the document stays well formed. Other bytes pass as they are (UTF-8 in, UTF-8 out).
#pragma once

#include <string>
#include <string_view>

namespace circles::formats {

std::string xml_text(std::string_view text);

}  // namespace circles::formats
