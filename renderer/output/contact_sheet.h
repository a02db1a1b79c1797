// A contact sheet: pictures in a grid of equal tiles, each scaled to fit its tile (aspect kept,
// centred), with an optional label under each drawn in a TrueType font through OpenImageIO;
// written as PNG, EXR or JPEG by the output's extension, atomically.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::output {

// A picture ready for the sheet: display-encoded RGB in [0, 1], interleaved, rows top first.
struct DisplayImage {
    int width = 0, height = 0;
    std::vector<float> rgb;
};

inline constexpr int kMaxSheetSide = 65535;  // JPEG's limit, and PNG readers'

// The geometry of a sheet: COUNT cells in COLUMNS columns, each a tile with a label strip
// under it (label_height 0 without labels), GAP pixels between cells and around them.
struct SheetLayout {
    int count = 0, columns = 0, rows = 0;
    int tile_width = 0, tile_height = 0;
    int label_height = 0, font_size = 0;
    int gap = 0;
    std::string font;                 // the font file or name; empty without labels
    std::vector<std::string> labels;  // per cell, shortened to fit its tile; empty without

    // 64-bit: a hostile count or tile is refused by size, not wrapped.
    std::int64_t width() const {
        return std::int64_t{columns} * tile_width + (std::int64_t{columns} + 1) * gap;
    }
    std::int64_t height() const {
        return std::int64_t{rows} * (tile_height + label_height) + (std::int64_t{rows} + 1) * gap;
    }
    // Bytes the sheet needs while it is drawn and encoded.
    std::uint64_t bytes() const;
};

// The font for labels: FONT (a file or a font name OpenImageIO searches for), or DejaVuSans
// (Debian's fonts-dejavu-core) when FONT is empty. Throws InputError naming --font when a
// given font does not load, RuntimeError when the default is not installed.
std::string findLabelFont(const std::string& font);

// The layout of COUNT cells (COLUMNS, or ceil(sqrt(COUNT)) when 0) of TILE_WIDTH x TILE_HEIGHT,
// labelled with LABELS in FONT (none when LABELS is empty): one font size for every label,
// the largest up to about a ninth of the tile height at which they fit (at least 9 px),
// and labels still too wide cut with "...".
SheetLayout planSheet(int count, int columns, int tile_width, int tile_height,
                      const std::vector<std::string>& labels, const std::string& font);

class ContactSheet {
public:
    // The background and the labels (throws RuntimeError when a label cannot be drawn). The
    // caller has checked the layout's size (kMaxSheetSide, bytes() against the memory limit).
    explicit ContactSheet(SheetLayout layout);
    // Scales IMAGE to fit cell INDEX's tile (aspect kept, centred) and draws it there.
    void place(int index, const DisplayImage& image);
    // Writes PATH (.png, .exr as half RGB of the display values, .jpg/.jpeg) atomically.
    // Throws RuntimeError naming PATH.
    void write(const std::filesystem::path& path) const;
    const SheetLayout& layout() const { return layout_; }

private:
    SheetLayout layout_;
    std::vector<float> rgb_;  // width() x height() x 3
};

// True when PATH ends in a sheet format ContactSheet::write knows (case ignored).
bool isSheetFormat(const std::filesystem::path& path);

}  // namespace penumbra::output
