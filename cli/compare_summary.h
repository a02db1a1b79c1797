// What `penumbra compare` prints: idiff's text summary of a comparison, and the one line (plus
// a JSON object with --json) when it cannot compare.
#pragma once

#include <string>

#include "cli/compare_args.h"
#include "renderer/output/compare.h"

namespace penumbra::cli {

// V as the summary writes it: %g, or inf.
std::string formatValue(double v);

// The idiff-style summary of R on stdout, ending in PASS, WARNING or FAILURE.
void printSummary(const CompareArgs& a, const output::CompareResult& r);

// When compare cannot compare: the one line MESSAGE on stderr and, with --json, a JSON object
// holding it as `error` on stdout. Returns CODE.
int cannotCompare(bool json, const std::string& ref, const std::string& test, int code,
                  const std::string& message);

}  // namespace penumbra::cli
