// Contact sheets: see contact_sheet.h. Scaling, text and JPEG through OpenImageIO (the module
// of core/oiio_module.h); PNG and EXR through the project's own writers (preview.h, exr.h).
#include "renderer/output/contact_sheet.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/oiio_module.h"
#include "renderer/output/exr.h"
#include "renderer/output/image.h"
#include "renderer/output/preview.h"

namespace penumbra::output {
namespace {

constexpr float kBackground = 0.12f;  // the sheet between tiles
constexpr float kTextColour = 0.92f;
constexpr int kMinFontSize = 9;
constexpr const char* kDefaultFont = "DejaVuSans";  // Debian: fonts-dejavu-core

std::string lowerExtension(const std::filesystem::path& path) {
    std::string e = path.extension().string();
    std::transform(e.begin(), e.end(), e.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
}

// Width in pixels of TEXT at SIZE in FONT (0 when it cannot be measured).
int textWidth(const std::string& text, int size, const std::string& font) {
    return oiioModule().textWidth(text, size, font);
}

// TEXT cut (at a UTF-8 character boundary) and ended with "..." until it fits WIDTH.
std::string shorten(std::string text, int width, int size, const std::string& font) {
    if (textWidth(text, size, font) <= width) return text;
    while (!text.empty()) {
        text.pop_back();
        while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80)
            text.pop_back();
        if (textWidth(text + "...", size, font) <= width) return text + "...";
    }
    return "";
}

// The largest size up to START at which every label fits WIDTH (at least kMinFontSize).
int fittingFontSize(const std::vector<std::string>& labels, int start, int width,
                    const std::string& font) {
    int size = start;
    for (; size > kMinFontSize; --size) {
        bool fits = true;
        for (const auto& l : labels) fits = fits && textWidth(l, size, font) <= width;
        if (fits) break;
    }
    return size;
}

}  // namespace

std::uint64_t SheetLayout::bytes() const {
    // float RGB while drawing, 8-bit RGB and its encoding while writing.
    const auto pixels = static_cast<std::uint64_t>(width()) * static_cast<std::uint64_t>(height());
    return pixels * (3 * sizeof(float) + 3 + 3);
}

std::string findLabelFont(const std::string& font) {
    const std::string name = font.empty() ? kDefaultFont : font;
    if (textWidth("Ag", 12, name) > 0) return name;
    if (!font.empty())
        throw InputError("--font: '" + quoteText(font) +
                         "' is not a TrueType font file or a font OpenImageIO finds");
    throw RuntimeError(
        "labels need a TrueType font and DejaVuSans is not installed (apt-get install "
        "fonts-dejavu-core), or give --font FILE.ttf, or --no-labels");
}

SheetLayout planSheet(int count, int columns, int tile_width, int tile_height,
                      const std::vector<std::string>& labels, const std::string& font) {
    SheetLayout l;
    l.count = count;
    l.columns = columns > 0 ? std::min(columns, count)
                            : static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    l.rows = (count + l.columns - 1) / l.columns;
    l.tile_width = tile_width;
    l.tile_height = tile_height;
    l.gap = std::clamp(tile_width / 40, 2, 16);
    if (!labels.empty()) {
        l.font = font;
        std::vector<std::string> lines = labels;
        for (std::string& text : lines)  // one line each: a control character becomes a space
            for (char& ch : text)
                if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) ch = ' ';
        const int start = std::clamp(tile_height / 9, kMinFontSize, 24);
        l.font_size = fittingFontSize(lines, start, tile_width, font);
        l.label_height = l.font_size + l.font_size / 2 + 2;
        for (const auto& text : lines)
            l.labels.push_back(shorten(text, tile_width, l.font_size, font));
    }
    return l;
}

ContactSheet::ContactSheet(SheetLayout layout) : layout_(std::move(layout)) {
    const auto w = static_cast<size_t>(layout_.width());
    const auto h = static_cast<size_t>(layout_.height());
    rgb_.assign(w * h * 3, kBackground);
    if (layout_.labels.empty()) return;
    OiioModule& oiio = oiioModule();
    const float colour[3] = {kTextColour, kTextColour, kTextColour};
    for (int i = 0; i < layout_.count && i < static_cast<int>(layout_.labels.size()); ++i) {
        const std::string& text = layout_.labels[static_cast<size_t>(i)];
        if (text.empty()) continue;
        const int col = i % layout_.columns, row = i / layout_.columns;
        const int x =
            layout_.gap + col * (layout_.tile_width + layout_.gap) + layout_.tile_width / 2;
        const int y = layout_.gap +
                      row * (layout_.tile_height + layout_.label_height + layout_.gap) +
                      layout_.tile_height + layout_.label_height / 2;
        std::string why;
        if (!oiio.drawText(rgb_.data(), static_cast<int>(layout_.width()),
                           static_cast<int>(layout_.height()), x, y, text, layout_.font_size,
                           layout_.font, colour, why))
            throw RuntimeError("cannot draw the label '" + quoteText(text) + "': " + why);
    }
}

void ContactSheet::place(int index, const DisplayImage& image) {
    if (index < 0 || index >= layout_.count || image.width <= 0 || image.height <= 0 ||
        image.rgb.size() !=
            static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 3)
        throw RuntimeError("contact sheet: no cell " + std::to_string(index) +
                           " or an empty image");
    const double scale = std::min(static_cast<double>(layout_.tile_width) / image.width,
                                  static_cast<double>(layout_.tile_height) / image.height);
    const int fw =
        std::clamp(static_cast<int>(std::lround(image.width * scale)), 1, layout_.tile_width);
    const int fh =
        std::clamp(static_cast<int>(std::lround(image.height * scale)), 1, layout_.tile_height);
    std::vector<float> px;
    if (fw == image.width && fh == image.height) {
        px = image.rgb;
    } else {
        px.resize(static_cast<size_t>(fw) * static_cast<size_t>(fh) * 3);
        std::string why;
        if (!oiioModule().resize(image.rgb.data(), image.width, image.height, px.data(), fw, fh,
                                 why))
            throw RuntimeError("contact sheet: cannot scale cell " + std::to_string(index + 1) +
                               ": " + why);
    }
    const int col = index % layout_.columns, row = index / layout_.columns;
    const int x0 =
        layout_.gap + col * (layout_.tile_width + layout_.gap) + (layout_.tile_width - fw) / 2;
    const int y0 = layout_.gap + row * (layout_.tile_height + layout_.label_height + layout_.gap) +
                   (layout_.tile_height - fh) / 2;
    const auto sheet_w = static_cast<size_t>(layout_.width());
    const auto row_floats = static_cast<size_t>(fw) * 3;
    for (int y = 0; y < fh; ++y) {
        const float* from = px.data() + static_cast<size_t>(y) * row_floats;
        float* to =
            rgb_.data() + (static_cast<size_t>(y0 + y) * sheet_w + static_cast<size_t>(x0)) * 3;
        for (size_t i = 0; i < row_floats; ++i) to[i] = std::clamp(from[i], 0.0f, 1.0f);
    }
}

bool isSheetFormat(const std::filesystem::path& path) {
    const std::string e = lowerExtension(path);
    return e == ".png" || e == ".exr" || e == ".jpg" || e == ".jpeg";
}

void ContactSheet::write(const std::filesystem::path& path) const {
    const int w = static_cast<int>(layout_.width()), h = static_cast<int>(layout_.height());
    const std::string ext = lowerExtension(path);
    if (ext == ".exr") {
        Image image;
        image.width = w;
        image.height = h;
        image.channels.reserve(3);
        for (int c = 0; c < 3; ++c) {
            auto& ch = image.add(std::string(1, "RGB"[c]), PixelType::Half);
            for (size_t i = 0; i < ch.pixels.size(); ++i) ch.pixels[i] = rgb_[i * 3 + size_t(c)];
        }
        image.attributes.emplace_back("penumbra/contact_sheet", "display-encoded RGB");
        writeExr(path, image);
        return;
    }
    std::vector<unsigned char> rgb8(rgb_.size());
    for (size_t i = 0; i < rgb_.size(); ++i)
        rgb8[i] = static_cast<unsigned char>(std::lround(std::clamp(rgb_[i], 0.0f, 1.0f) * 255.0f));
    if (ext == ".png") return writePngRgb8(path, w, h, rgb8);
    if (ext != ".jpg" && ext != ".jpeg")
        throw RuntimeError(path.string() + ": a contact sheet is .png, .exr, .jpg or .jpeg");
    OiioModule& oiio = oiioModule();  // loaded before the temporary file is made
    writeAtomically(path, [&](const std::filesystem::path& tmp) {
        std::string why;
        if (!oiio.writeJpeg(tmp.string(), w, h, rgb8.data(), 92, why))
            throw std::runtime_error(why);
    });
}

}  // namespace penumbra::output
