// contact-sheet's inputs: see contact_sheet_inputs.h.
#include "renderer/app/contact_sheet_inputs.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/output_paths.h"
#include "renderer/core/regular_file.h"
#include "renderer/output/exr.h"
#include "renderer/output/tone_map.h"
#include "renderer/scene/image_file.h"
#include "renderer/scene/json_file.h"

namespace penumbra::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kMaxInputSide = 32768;                // a PNG or JPEG input, per side
constexpr size_t kMaxSweepJson = size_t{64} << 20;  // DIR/sweep.json

std::string lowerExtension(const fs::path& path) {
    std::string e = path.extension().string();
    std::transform(e.begin(), e.end(), e.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
}

bool isExr(const fs::path& path) {
    return lowerExtension(path) == ".exr";
}

void requireImageFile(const fs::path& path, const std::string& label) {
    const std::string e = lowerExtension(path);
    if (e != ".exr" && e != ".png" && e != ".jpg" && e != ".jpeg")
        throw InputError(label + ": expected an .exr, .png, .jpg or .jpeg image");
    requireRegularFile(path, label);
}

// "technique.pcf" -> "pcf", "lights.0.size" -> "size"; VALUE compact, a string bare.
std::string shortValue(const std::string& key, const json& value) {
    const size_t dot = key.rfind('.');
    const std::string name = dot == std::string::npos ? key : key.substr(dot + 1);
    return name + "=" + (value.is_string() ? value.get_ref<const std::string&>() : value.dump());
}

std::string techniqueOf(const json& run) {
    const auto t = run.find("technique");
    return t != run.end() && t->is_string() ? t->get_ref<const std::string&>() : std::string();
}

// RUN's varied values in KEYS' order (the --vary order), then its technique: the part a
// shortened label loses first.
std::string runLabel(const json& run, const std::vector<std::string>& keys) {
    std::string label;
    const auto values = run.find("values");
    if (values != run.end() && values->is_object())
        for (const auto& key : keys) {
            const auto value = values->find(key);
            if (value == values->end() || key == "technique" || key == "technique.name") continue;
            label += shortValue(key, *value) + ' ';
        }
    return label + techniqueOf(run);
}

// The varied keys in --vary order: sweep.json's `varied`, else the first run's own.
std::vector<std::string> variedKeys(const json& sweep) {
    std::vector<std::string> keys;
    const auto varied = sweep.find("varied");
    if (varied != sweep.end() && varied->is_array())
        for (const auto& axis : *varied)
            if (axis.is_object() && axis.contains("key") && axis["key"].is_string())
                keys.push_back(axis["key"].get_ref<const std::string&>());
    const json& runs = sweep["runs"];
    if (keys.empty() && !runs.empty() && runs[0].is_object() && runs[0].contains("values") &&
        runs[0]["values"].is_object())
        for (const auto& [key, value] : runs[0]["values"].items()) keys.push_back(key);
    return keys;
}

// CHANNEL of IMAGE as grey (see readSheetPicture).
output::DisplayImage greyOf(const output::ImageChannel& channel, int width, int height) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (float v : channel.pixels)
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    const bool unit = lo >= 0.0f && hi <= 1.0f;
    const float base = unit || !(hi > lo) ? 0.0f : lo;
    const float span = unit || !(hi > lo) ? 1.0f : hi - lo;
    output::DisplayImage d{width, height, {}};
    d.rgb.reserve(channel.pixels.size() * 3);
    for (float v : channel.pixels) {
        const float g = std::isnan(v)   ? 0.0f
                        : std::isinf(v) ? (v > 0 ? 1.0f : 0.0f)
                                        : std::clamp((v - base) / span, 0.0f, 1.0f);
        d.rgb.insert(d.rgb.end(), {g, g, g});
    }
    return d;
}

std::string channelList(const output::Image& image) {
    std::string list;
    for (const auto& c : image.channels) list += (list.empty() ? "" : ", ") + c.name;
    return list.empty() ? "none" : list;
}

output::DisplayImage exrPicture(const fs::path& path, const std::string& channel) {
    output::Image image;
    try {
        image = output::readExr(path);
    } catch (const output::UnreadableImage& e) {
        throw InputError(e.what());
    }
    if (channel != "beauty") {
        const output::ImageChannel* c = image.find(channel);
        if (!c)
            throw InputError(path.string() + ": no channel '" + quoteText(channel) +
                             "' (--channel); it has " + channelList(image));
        return greyOf(*c, image.width, image.height);
    }
    const output::ImageChannel* rgb[3] = {image.find("R"), image.find("G"), image.find("B")};
    if (!rgb[0] || !rgb[1] || !rgb[2])
        throw InputError(path.string() + ": no beauty channels R, G, B (--channel); it has " +
                         channelList(image));
    output::DisplayImage d{image.width, image.height, {}};
    d.rgb.resize(rgb[0]->pixels.size() * 3);
    for (size_t i = 0; i < rgb[0]->pixels.size(); ++i)
        for (size_t c = 0; c < 3; ++c) d.rgb[i * 3 + c] = output::toneMap(rgb[c]->pixels[i], 0.0f);
    return d;
}

}  // namespace

std::vector<SheetInput> fileInputs(const std::vector<std::string>& files,
                                   const std::optional<std::vector<int>>& frames) {
    std::vector<SheetInput> inputs;
    for (const auto& file : files) {
        std::vector<std::string> names;
        if (!frames)
            names.push_back(file);
        else
            for (int f : *frames) names.push_back(expandFramePattern(file, f, frames->size() > 1));
        for (const auto& name : names) {
            requireImageFile(name, name);
            inputs.push_back({name, fs::path(name).stem().string()});
        }
    }
    return inputs;
}

std::vector<SheetInput> sweepInputs(const fs::path& dir) {
    const fs::path file = dir / "sweep.json";
    const std::string label = "--sweep: " + file.string();
    if (!fs::exists(file))
        throw InputError("--sweep: " + dir.string() + ": no sweep.json (not a sweep folder)");
    const json sweep = scene::parseJsonText(scene::readTextFile(file, label, kMaxSweepJson), label);
    if (!sweep.is_object() || sweep.value("schema", json()) != "penumbra-sweep" ||
        !sweep.contains("runs") || !sweep["runs"].is_array())
        throw InputError(label + ": not a penumbra sweep (schema penumbra-sweep with runs)");
    const std::vector<std::string> keys = variedKeys(sweep);
    std::vector<SheetInput> inputs;
    for (const auto& run : sweep["runs"]) {
        const json exr = run.is_object() ? run.value("exr", json()) : json();
        const fs::path rel =
            exr.is_string() ? fs::path(exr.get<std::string>()).lexically_normal() : fs::path();
        if (rel.empty() || rel.is_absolute() || *rel.begin() == "..")
            throw InputError(label + ": run " + std::to_string(inputs.size() + 1) +
                             ": `exr` must name a file inside the sweep folder");
        requireImageFile(dir / rel, (dir / rel).string());
        inputs.push_back({dir / rel, runLabel(run, keys)});
    }
    if (inputs.empty()) throw InputError(label + ": the sweep lists no runs");
    return inputs;
}

output::DisplayImage readSheetPicture(const SheetInput& input, const std::string& channel) {
    if (isExr(input.path)) return exrPicture(input.path, channel);
    if (channel != "beauty")
        throw InputError(input.path.string() + ": --channel " + quoteText(channel) +
                         " needs an EXR (a PNG or JPEG holds only its picture)");
    const std::string label = input.path.string();
    const scene::FloatImage im = scene::readFloatImage(input.path, label, {".png", ".jpg", ".jpeg"},
                                                       "a .png or .jpg image", kMaxInputSide, 3);
    output::DisplayImage d{im.width, im.height, {}};
    const auto n = static_cast<size_t>(im.width) * static_cast<size_t>(im.height);
    d.rgb.resize(n * 3);
    for (size_t i = 0; i < n; ++i)
        for (size_t c = 0; c < 3; ++c)
            d.rgb[i * 3 + c] =
                im.pixels[i * static_cast<size_t>(im.channels) + (im.channels >= 3 ? c : 0)];
    return d;
}

}  // namespace penumbra::app
