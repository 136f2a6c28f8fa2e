// The verdict as JUnit XML (`circles conform --junit FILE.xml`, a row of conform/report_formats.hpp), which GitHub
// Actions, GitLab and Jenkins read: one <testsuite> of one <testcase> per family, with a <failure> (its message
// the line that names the field, its text the printed counterexample) in each family that failed (with
// --keep-going, more than one) and in each unexpected pass, <skipped> in an expected failure, a skipped family and
// a family not reached, and an <error> in each family not checked when the run cannot check (when it was
// interrupted, in each family that did not fail).
#pragma once

#include "conform/conform.hpp"

#include <string>

namespace circles::conform {

// The JUnit XML. `text`: the run's counterexample as `circles conform` prints it (counterexample_text,
// conform/verdict_text.hpp), the text of its family's <failure>.
std::string junit_report(const Verdict& verdict, const std::string& text);

}  // namespace circles::conform
