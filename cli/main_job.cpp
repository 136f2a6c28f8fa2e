#include "cli/main_job.hpp"

#include "cli/oracle_report.hpp"
#include "cli/run.hpp"  // print_comparison
#include "conform/check_trace.hpp"
#include "formats/scene.hpp"

namespace circles::cli {

int main_job(std::size_t steps, std::ostream& out) {
  const formats::Scene scene = formats::default_scene();
  report_oracle(scene.circles, "the embedded default scene", steps, out);
  // Every engine against the correctly rounded oracle, on the same scene and steps.
  out << "\nthe engines, each stepped beside the oracle (a rounding engine against the correctly rounded step "
         "from its own last world; the exact engine against the oracle's exact sequence)\n";
  bool all_agree = true;
  for (const engines::EngineEntry& e : engines::engines()) {
    if (e.name == "oracle") continue;
    const conform::Comparison c = conform::compare_with_oracle(e, formats::doubles_of(scene), steps, 0);
    print_comparison(e, c, out);
    all_agree = all_agree && !c.difference;
  }
  return all_agree ? 0 : 1;
}

}  // namespace circles::cli
