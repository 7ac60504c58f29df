#pragma once
// What `coldblast reproduce` writes about its result (presentation; the pipeline is
// compare/reproduce.*): REPORT.md (a summary, the numbers, the three verdict tables, the tracer's
// amplitudes beside the MD's), table1.md and summary.json.
#include <string>

#include "common/output.hpp"
#include "compare/reproduce.hpp"

namespace coldblast::compare {

/// REPORT.md of a reproduction; `figures`: link the reports' figures.
std::string reproduce_markdown(const ReproduceResult& result, bool figures);

/// The paper's Table 1 beside coldblast's numbers (Markdown; written as table1.md and pasted into
/// docs/verification.md).
std::string table1_markdown(const ReproduceResult& result);

/// summary.json of a reproduction (keys in docs/cli.md, `## reproduce`).
common::Json reproduce_summary(const ReproduceResult& result);

}  // namespace coldblast::compare
