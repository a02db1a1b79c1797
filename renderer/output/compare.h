// Image comparison with OpenImageIO idiff's thresholds and verdicts, plus the error metrics
// the techniques are judged by (MAE, RMSE, max, p99, shadow-region MAE of Atty et al. 5.2.1).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/output/image.h"

namespace penumbra::output {

struct CompareOptions {
    double fail = 1e-6;         // a pixel fails when any channel differs by more than this
    double fail_percent = 0.0;  // ... and the test fails when more than this % of pixels fail
    double warn = 1e-6;         // same pair for the warning verdict
    double warn_percent = 0.0;
    std::optional<double> hard_fail;    // any difference above this fails outright
    std::vector<std::string> channels;  // empty: every channel of the reference
    // Non-empty: only pixels whose reference `id` channel (object index) is one of these are
    // compared; every count, fraction and mean is over them.
    std::vector<int> ids;
};

enum class Verdict { Pass = 0, Warn = 1, Fail = 2 };

// "pass", "warn", "fail".
const char* verdictName(Verdict verdict);

// Metrics of one channel. Equal values differ by 0, equal infinities included (Z is +inf on
// the background in both images). Any other difference involving NaN or inf is infinite: it
// counts in `max` and `nonfinite`, while mae, rmse and p99 are over the finite ones only.
struct ChannelMetrics {
    std::string name;
    double mae = 0, rmse = 0, max = 0, p99 = 0;
    int max_x = 0, max_y = 0;
    long nonfinite = 0;  // samples where either image holds NaN or inf, unless both hold one inf
};

struct CompareResult {
    Verdict verdict = Verdict::Pass;
    CompareOptions options;  // the thresholds the verdict used
    int width = 0, height = 0;
    long pixels = 0;                             // pixels compared: all, or those of options.ids
    std::vector<std::string> channels;           // the channels compared, in order
    double mae = 0, rmse = 0, max = 0, p99 = 0;  // over all compared channels and pixels
    int max_x = 0, max_y = 0;
    std::string max_channel;
    long nonfinite = 0;        // compared samples with NaN or inf in either image
    long fail_pixels = 0;      // pixels with a channel differing by more than options.fail
    long warn_pixels = 0;      // ... by more than options.warn
    double fail_fraction = 0;  // fail_pixels / pixels
    double warn_fraction = 0;
    // Mean |ref - test| of `visibility` over compared pixels where either is below 0.999, and their
    // count. Both absent without a visibility channel in both images; shadow_mae is also absent
    // when no pixel is in shadow in either. Pixels with non-finite visibility are left out.
    std::optional<double> shadow_mae;
    std::optional<long> shadow_pixels;
    std::vector<ChannelMetrics> per_channel;

    // snake_case keys; infinite values (max after a NaN) become null.
    nlohmann::json toJson() const;
};

// Thrown when sizes or the requested channels do not match, or --ids selects no pixel
// (compare exits 3). The message
// names the side ("reference" or "test") and the channel; `side` says which file is at fault.
class CompareMismatch : public std::runtime_error {
public:
    enum class Side { Both, Reference, Test };
    CompareMismatch(Side side, const std::string& message)
        : std::runtime_error(message), side_(side) {}
    Side side() const { return side_; }

private:
    Side side_;
};

// Visibility below this counts as shadow for shadow_mae.
inline constexpr double kShadowVisibility = 0.999;

CompareResult compareImages(const Image& ref, const Image& test, const CompareOptions& options);

// Absolute difference per compared channel (same channel names, stored as float; infinite where
// either image is NaN or inf), for `compare --diff`. Throws CompareMismatch like compareImages.
Image differenceImage(const Image& ref, const Image& test, const CompareOptions& options);

}  // namespace penumbra::output
