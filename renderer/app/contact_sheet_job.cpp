// The contact-sheet job: see contact_sheet_job.h.
#include "renderer/app/contact_sheet_job.h"

#include <cstdio>
#include <string>
#include <vector>

#include "renderer/app/contact_sheet_inputs.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/memory_limit.h"
#include "renderer/core/output_paths.h"

namespace penumbra::app {

int runContactSheetJob(const ContactSheetRequest& req) {
    std::vector<SheetInput> inputs = fileInputs(req.files, req.frames);
    if (req.sweep)
        for (auto& input : sweepInputs(*req.sweep)) inputs.push_back(std::move(input));
    if (inputs.empty())
        throw InputError(
            "contact-sheet: no images (give files, a pattern with -f, or --sweep DIR)");
    checkOutputPath(req.out, "-o");
    std::vector<std::string> read;
    for (const auto& input : inputs) read.push_back(input.path.string());
    if (namesAnyOf(req.out.string(), read))  // `-o out/sheet.png out/*.png`, run twice
        throw InputError("-o: '" + quoteText(req.out.string()) +
                         "' is one of the images; writing the sheet there would overwrite it "
                         "(name another file)");
    const std::string font = req.labels ? output::findLabelFont(req.font) : std::string();

    // The tile: --tile, else the first picture's size; every picture is scaled to fit it.
    output::DisplayImage first = readSheetPicture(inputs.front(), req.channel);
    const auto [tile_w, tile_h] = req.tile.value_or(std::pair{first.width, first.height});
    std::vector<std::string> labels;
    if (req.labels)
        for (const auto& input : inputs) labels.push_back(input.label);
    const output::SheetLayout layout = output::planSheet(static_cast<int>(inputs.size()),
                                                         req.columns, tile_w, tile_h, labels, font);
    const std::string size = std::to_string(layout.width()) + "x" + std::to_string(layout.height());
    if (layout.width() > output::kMaxSheetSide || layout.height() > output::kMaxSheetSide)
        throw InputError("-o: " + req.out.string() + ": the sheet would be " + size +
                         ", more than " + std::to_string(output::kMaxSheetSide) +
                         " pixels a side (--tile, --columns)");
    requireMemory(layout.bytes(), "-o: " + req.out.string(), "the " + size + " sheet");

    output::ContactSheet sheet(layout);
    sheet.place(0, first);
    first = {};
    for (size_t i = 1; i < inputs.size(); ++i)
        sheet.place(static_cast<int>(i), readSheetPicture(inputs[i], req.channel));
    sheet.write(req.out);
    if (!req.quiet)
        std::fprintf(stderr, "penumbra: contact-sheet: %zu images, %s: %s\n", inputs.size(),
                     size.c_str(), req.out.c_str());
    return 0;
}

}  // namespace penumbra::app
