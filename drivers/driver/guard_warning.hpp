#pragma once
// A warning when a model's guards acted during a run: a guard keeps the run finite, but where it
// acts the result is no longer the model's (MDR: the radius-update denominator floor of (37),
// the radius cap, the volume floor of (39)). The counts come from the model's report
// (RunSummary::model_counters, names containing "_guard_"); the warning goes to stderr and to
// summary.json "warnings".
#include "driver/run_options.hpp"

#include <cstdio>
#include <sstream>
#include <string>

namespace epac {
namespace driver {

// Appends the warning to sum.warnings (if any guard acted) and prints it to stderr.
inline void warn_on_guard_hits(RunSummary& sum) {
  std::ostringstream m;
  bool any = false;
  for (const auto& kv : sum.model_counters) {
    if (kv.first.find("_guard_") == std::string::npos || !(kv.second > 0.0)) continue;
    m << (any ? ", " : "") << kv.first << " = " << static_cast<long long>(kv.second);
    any = true;
  }
  if (!any) return;
  std::string text = "growth guards acted (" + m.str() +
                     "): the radius update was clamped there, so those particles do not follow the model";
  if (sum.initial_history.overlapping_contacts > 0 && !sum.initial_history.applied)
    text +=
        "; the scene started with overlapping contacts and fresh history (run.initial_history = \"zero\"), "
        "which loads each overlap in one increment: \"from_overlaps\" starts from a quasi-static load";
  else
    text += " (high confinement, radius cap or a time step too large for the compaction rate)";
  sum.warnings.push_back(text);
  std::fprintf(stderr, "epac-run: warning: %s\n", text.c_str());
}

}  // namespace driver
}  // namespace epac
