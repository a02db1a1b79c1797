// `penumbra contact-sheet IMAGES... -o SHEET.png`: argv -> ContactSheetRequest.
#include <cstdio>

#include "cli/args.h"
#include "cli/commands.h"
#include "renderer/app/contact_sheet_job.h"
#include "renderer/core/frame_spec.h"
#include "renderer/core/json_bounds.h"
#include "renderer/output/contact_sheet.h"

namespace penumbra::cli {
namespace {

constexpr int kMaxTileSide = 16384;
constexpr int kMaxColumns = 10000;

constexpr const char* kHelp =
    R"(usage: penumbra contact-sheet [IMAGE...] [--sweep DIR] -o SHEET.png [options]

Puts images in a labelled grid: EXR files (this program's outputs), PNG or JPEG files, the
frames of a pattern (-f), or the runs of a sweep folder (--sweep), in that order. Each image
is scaled to fit its tile, keeping its aspect (images of different sizes are fine).

  IMAGE...              .exr, .png, .jpg or .jpeg files; with -f, patterns as render's -o:
                        a run of # becomes the zero-padded frame (out/walk.####.exr)
  -f, --frames SPEC     the frames of each pattern: 7, 1-24, 1-24:4, 1-3,5
  --sweep DIR           the runs of a `penumbra sweep` folder in DIR/sweep.json's order,
                        labelled by varied values and technique (pcf=3 size=[1,1] hard)
  -o, --output SHEET    the sheet: .png, .exr (display-encoded RGB) or .jpg (required)
  --columns N           columns (default: ceil(sqrt(images)), a near-square grid)
  --tile WxH            the size each image is scaled to fit (default: the first image's)
  --channel C           what an EXR shows: beauty (R, G, B tone-mapped as render's
                        --preview; the default), visibility, or any channel name as grey
  --labels, --no-labels  a label under each image: its file stem, or a sweep run's values
                        (default: labels)
  --font FONT           a TrueType font file or name for the labels (default: DejaVuSans,
                        Debian's fonts-dejavu-core)
  --memory-limit SIZE   refuse a sheet that would need more (8G, 512M; default half the
                        physical memory)
  -q, --quiet           no summary line

exit codes: 0 written, 1 the sheet could not be drawn or written (or no font for the
labels), 2 bad command line or input (a missing or unreadable image, a channel it lacks,
an output that is a folder): nothing is written then.
)";

}  // namespace

int runContactSheet(const Args& args) {
    ArgCursor c("contact-sheet", args);
    app::ContactSheetRequest req;
    std::optional<std::string> out;
    while (!c.done()) {
        if (c.flag("-h", "--help")) {
            std::fputs(kHelp, stdout);
            return 0;
        }
        std::optional<std::string> v;
        if ((v = c.option("-f", "--frames"))) {
            req.frames = parseFrameSpec(*v, "--frames");
        } else if ((v = c.option("", "--sweep"))) {
            if (v->empty()) c.fail("--sweep: empty folder name");
            req.sweep = *v;
        } else if ((v = c.option("-o", "--output"))) {
            if (v->empty()) c.fail("--output: empty file name");
            if (!output::isSheetFormat(*v))
                c.fail("--output: '" + quoteText(*v) + "' must end in .png, .exr, .jpg or .jpeg");
            out = *v;
        } else if ((v = c.option("", "--columns"))) {
            req.columns = parseInt(c, "--columns", *v, 1, kMaxColumns);
        } else if ((v = c.option("", "--tile"))) {
            req.tile = parseSize(c, "--tile", *v);
            if (req.tile->first > kMaxTileSide || req.tile->second > kMaxTileSide)
                c.fail("--tile: at most " + std::to_string(kMaxTileSide) + " pixels a side, got '" +
                       quoteText(*v) + "'");
        } else if ((v = c.option("", "--channel"))) {
            if (v->empty()) c.fail("--channel: empty channel name");
            req.channel = *v;
        } else if (c.flag("", "--labels")) {
            req.labels = true;
        } else if (c.flag("", "--no-labels")) {
            req.labels = false;
        } else if ((v = c.option("", "--font"))) {
            if (v->empty()) c.fail("--font: empty font name");
            req.font = *v;
        } else if (c.flag("-q", "--quiet")) {
            req.quiet = true;
        } else if (parseMemoryLimitFlag(c)) {
        } else if ((v = c.positional())) {
            req.files.push_back(*v);
        } else {
            c.unknown();
        }
    }
    if (!out) c.fail("missing -o SHEET.png (see --help)");
    if (req.files.empty() && !req.sweep)
        c.fail("no images: give files, a pattern with -f, or --sweep DIR (see --help)");
    if (req.frames && req.files.empty())
        c.fail("--frames: needs a file pattern such as out/a.####.exr");
    req.out = *out;
    return app::runContactSheetJob(req);
}

}  // namespace penumbra::cli
