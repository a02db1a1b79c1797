// Image comparison with OpenImageIO idiff's thresholds and verdicts, plus the error metrics
// the techniques are judged by (MAE, RMSE, max, p99, shadow-region MAE of Atty et al. 5.2.1).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/output/image.h"

namespace penumbra::output {

struct CompareOptions {
    double fail = 1e-6;         // a pixel fails when any channel differs by more than this
    double fail_percent = 0.0;  // ... and the test fails when more than this % of pixels fail
    double warn = 1e-6;
    double warn_percent = 0.0;
    std::optional<double> hard_fail;  // any difference above this fails outright
    std::vector<std::string> channels;  // empty: every channel both images have... see compare.cpp
};

enum class Verdict { Pass = 0, Warn = 1, Fail = 2 };

struct ChannelMetrics {
    std::string name;
    double mae = 0, rmse = 0, max = 0, p99 = 0;
    int max_x = 0, max_y = 0;
};

struct CompareResult {
    Verdict verdict = Verdict::Pass;
    int width = 0, height = 0;
    std::vector<std::string> channels;  // the channels compared
    double mae = 0, rmse = 0, max = 0, p99 = 0;  // over all compared channels and pixels
    int max_x = 0, max_y = 0;
    std::string max_channel;
    double fail_fraction = 0;  // share of pixels failing the fail threshold
    double warn_fraction = 0;
    // mean |ref - test| of `visibility` over pixels where either is below 0.999 (absent without
    // a visibility channel in both, or when no pixel is in shadow in either).
    std::optional<double> shadow_mae;
    std::optional<long> shadow_pixels;
    std::vector<ChannelMetrics> per_channel;
    nlohmann::json toJson() const;
};

// Thrown when sizes or the requested channels do not match (compare exits 3).
class CompareMismatch : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

CompareResult compareImages(const Image& ref, const Image& test, const CompareOptions& options);

// Absolute difference per compared channel (same channel names), for `compare --diff`.
Image differenceImage(const Image& ref, const Image& test, const CompareOptions& options);

}  // namespace penumbra::output
