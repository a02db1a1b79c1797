// What `penumbra contact-sheet` puts on a sheet: its inputs (files, frame patterns, a sweep
// folder's runs in sweep.json order) with their labels, and each input read as a picture for
// the sheet (an EXR's beauty tone-mapped as the preview is, or one channel as grey).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "renderer/output/contact_sheet.h"

namespace penumbra::app {

struct SheetInput {
    std::filesystem::path path;
    std::string label;
};

// FILES as given, or, with FRAMES, each file a pattern expanded per frame as render's -o is
// (core/output_paths.h); labels are the file stems. Throws InputError for a name that is not
// .exr, .png, .jpg or .jpeg, or not a regular file.
std::vector<SheetInput> fileInputs(const std::vector<std::string>& files,
                                   const std::optional<std::vector<int>>& frames);

// The runs of the sweep folder DIR in DIR/sweep.json's order, labelled "key=value ...
// TECHNIQUE", the keys in --vary order, each shortened to its last part (technique.pcf=3 ->
// pcf=3). Throws InputError naming
// --sweep for a folder without a readable sweep.json, or a run EXR outside DIR or missing.
std::vector<SheetInput> sweepInputs(const std::filesystem::path& dir);

// INPUT as a picture for the sheet. An EXR shows CHANNEL: "beauty" (R, G, B tone-mapped as
// the PNG preview is) or one channel as grey (as it is when its values lie in [0, 1], else
// stretched from its smallest finite value, black, to its largest, white; +inf white, NaN and
// -inf black). A PNG or JPEG shows its picture (grey when it has one or two channels) and
// takes only CHANNEL "beauty". Throws InputError naming the file (for a missing channel, with
// the channels it has).
output::DisplayImage readSheetPicture(const SheetInput& input, const std::string& channel);

}  // namespace penumbra::app
