// `penumbra contact-sheet` as a job: its inputs gathered and checked, the sheet's size checked
// against kMaxSheetSide and the memory limit, then each input read, scaled into its tile and
// the sheet written (nothing is written when an input fails).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace penumbra::app {

struct ContactSheetRequest {
    std::vector<std::string> files;              // EXR, PNG or JPEG files, or patterns with frames
    std::optional<std::vector<int>> frames;      // -f SPEC: each file a pattern
    std::optional<std::filesystem::path> sweep;  // --sweep DIR, after the files
    std::filesystem::path out;                   // -o
    int columns = 0;                             // 0: ceil(sqrt(count))
    std::optional<std::pair<int, int>> tile;     // --tile WxH; else the first picture's size
    std::string channel = "beauty";
    bool labels = true;
    std::string font;  // --font; empty: DejaVuSans
    bool quiet = false;
};

// Returns 0. Throws InputError (exit 2) for bad input before anything is written,
// RuntimeError (exit 1) when the sheet cannot be drawn or written.
int runContactSheetJob(const ContactSheetRequest& req);

}  // namespace penumbra::app
