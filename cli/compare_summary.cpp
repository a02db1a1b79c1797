// What `penumbra compare` prints: the text summary and the cannot-compare line (see
// compare_summary.h).
#include "cli/compare_summary.h"

#include <cmath>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

namespace penumbra::cli {

std::string formatValue(double v) {
    if (std::isinf(v)) return "inf";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

void printSummary(const CompareArgs& a, const output::CompareResult& r) {
    const long pixels = r.pixels;
    std::string channels;
    for (const auto& name : r.channels) channels += (channels.empty() ? "" : ",") + name;
    std::printf("Comparing \"%s\" and \"%s\" (%dx%d, channels %s)\n", a.ref.c_str(), a.test.c_str(),
                r.width, r.height, channels.c_str());
    if (!r.options.ids.empty())
        std::printf("  %ld pixels of the objects listed by --ids\n", r.pixels);
    std::printf("  Mean error = %s\n", formatValue(r.mae).c_str());
    std::printf("  RMS error = %s\n", formatValue(r.rmse).c_str());
    std::printf("  Max error = %s @ (%d, %d, %s)\n", formatValue(r.max).c_str(), r.max_x, r.max_y,
                r.max_channel.c_str());
    std::printf("  99th percentile error = %s\n", formatValue(r.p99).c_str());
    if (r.nonfinite > 0)
        std::printf("  %ld samples are NaN or inf (counted as infinite differences)\n",
                    r.nonfinite);
    if (r.shadow_pixels) {
        if (r.shadow_mae)
            std::printf("  Shadow-region MAE (visibility < %g) = %s over %ld pixels\n",
                        output::kShadowVisibility, formatValue(*r.shadow_mae).c_str(),
                        *r.shadow_pixels);
        else
            std::printf("  Shadow-region MAE: no pixel has visibility < %g in either image\n",
                        output::kShadowVisibility);
    }
    std::printf("  %ld pixels (%.3g%%) over %s (fail)\n", r.fail_pixels,
                pixels ? 100.0 * r.fail_fraction : 0.0, formatValue(r.options.fail).c_str());
    std::printf("  %ld pixels (%.3g%%) over %s (warn)\n", r.warn_pixels,
                pixels ? 100.0 * r.warn_fraction : 0.0, formatValue(r.options.warn).c_str());
    if (r.options.hard_fail && r.max > *r.options.hard_fail)
        std::printf("  Max error exceeds --hardfail %s\n",
                    formatValue(*r.options.hard_fail).c_str());
    switch (r.verdict) {
        case output::Verdict::Pass:
            std::printf("PASS\n");
            break;
        case output::Verdict::Warn:
            std::printf("WARNING\n");
            break;
        case output::Verdict::Fail:
            std::printf("FAILURE\n");
            break;
    }
}

int cannotCompare(bool json, const std::string& ref, const std::string& test, int code,
                  const std::string& message) {
    std::fprintf(stderr, "penumbra: %s\n", message.c_str());
    if (json) {
        nlohmann::json j = {{"error", message}, {"exit", code}};
        if (!ref.empty()) j["reference"] = ref;
        if (!test.empty()) j["test"] = test;
        std::cout << j.dump(2) << std::endl;
    }
    return code;
}

}  // namespace penumbra::cli
