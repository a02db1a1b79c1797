// Animation tracks: parsing and shape checks against the document, and evaluation at a frame
// (linear between keys, held outside them).
#include "renderer/scene/animation.h"

#include <algorithm>
#include <map>

#include "renderer/core/frame_spec.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/json_field.h"
#include "renderer/scene/dotted_key.h"

namespace penumbra::scene {
namespace {

constexpr long kMaxKeyFrame = 10'000'000;
constexpr std::size_t kMaxKeys = 10'000;  // per track: each key frame is validated at load

// "a number" or "3 numbers": the shape of an animatable value.
std::string shapeOf(const nlohmann::json& v) {
    return v.is_number() ? "a number" : std::to_string(v.size()) + " numbers";
}

bool sameShape(const Field& value, const nlohmann::json& like) {
    if (like.is_number()) return value.json().is_number();
    return value.isNumberArray() && value.json().size() == like.size();
}

AnimationTrack parseTrack(const Field& f, const nlohmann::json& doc) {
    f.expectObject({"key", "keys"});
    AnimationTrack track;
    const Field key = f.member("key");
    if (!key.present()) key.fail("missing (the dotted key of the value to animate)");
    track.key = key.string();
    const auto parts = splitDottedKey(track.key);
    if (!parts) key.fail("malformed key '" + quoteText(track.key) + "'");
    track.parts = *parts;
    if (track.parts[0] == "animation") key.fail("the animation block cannot be animated");
    // The image's size and samples are fixed for a whole render (its buffers are made once).
    if (track.parts[0] == "image")
        key.fail(std::string("'") + quoteText(track.key) +
                 "' cannot be animated (one image size per render)");
    const nlohmann::json* target = findAt(doc, track.parts);
    if (!target)
        key.fail(std::string("'") + quoteText(track.key) + "' does not exist in the scene");
    const Field target_field(target, track.key, key.file());
    if (!target->is_number() && !(target_field.isNumberArray() && !target->empty()))
        key.fail(std::string("'") + quoteText(track.key) + "' is " + describeType(*target) +
                 ", not a number or an array of numbers");

    const Field keys = f.member("keys");
    if (!keys.present()) keys.fail("missing (a list of [frame, value])");
    const std::size_t count = keys.arraySize();
    if (count == 0) keys.fail("needs at least one [frame, value]");
    if (count > kMaxKeys)
        keys.fail(std::to_string(count) + " keys, more than the limit of " +
                  std::to_string(kMaxKeys));
    for (std::size_t i = 0; i < count; ++i) {
        const Field pair = keys.element(i);
        if (!pair.json().is_array() || pair.json().size() != 2) pair.expected("[frame, value]");
        const int frame = static_cast<int>(pair.element(0).integer(-kMaxKeyFrame, kMaxKeyFrame));
        if (!track.frames.empty() && frame <= track.frames.back())
            pair.element(0).fail("frame " + std::to_string(frame) +
                                 " is not after the previous key's frame " +
                                 std::to_string(track.frames.back()));
        const Field value = pair.element(1);
        if (!sameShape(value, *target))
            value.expected(shapeOf(*target) + " like " + quoteText(track.key));
        if (value.json().is_number())
            (void)value.number();  // finite and float-sized
        else
            for (std::size_t c = 0; c < value.json().size(); ++c) (void)value.element(c).number();
        track.frames.push_back(frame);
        track.values.push_back(value.json());
    }
    return track;
}

}  // namespace

Animation parseAnimation(const nlohmann::json& doc, const std::string& file) {
    Animation animation;
    const auto it = doc.find("animation");
    if (it == doc.end()) return animation;
    const Field f(&*it, "animation", file);
    f.expectObject({"frames", "tracks"});
    if (const Field frames = f.member("frames"); frames.present()) {
        animation.frames = frames.string();
        (void)parseFrameSpec(*animation.frames, file + ": animation.frames");
    }
    if (const Field tracks = f.member("tracks"); tracks.present()) {
        const std::size_t count = tracks.arraySize();
        std::map<std::vector<std::string>, std::size_t> animated;  // target -> its track
        for (std::size_t i = 0; i < count; ++i) {
            animation.tracks.push_back(parseTrack(tracks.element(i), doc));
            const auto [earlier, fresh] = animated.emplace(animation.tracks.back().parts, i);
            if (!fresh)
                tracks.element(i).member("key").fail(
                    std::string("'") + quoteText(animation.tracks.back().key) +
                    "' is animated by animation.tracks." + std::to_string(earlier->second) +
                    " already (one track per value)");
        }
    }
    return animation;
}

nlohmann::json trackValueAt(const AnimationTrack& track, int frame) {
    const auto& frames = track.frames;
    if (frame <= frames.front()) return track.values.front();
    if (frame >= frames.back()) return track.values.back();
    const std::size_t next = static_cast<std::size_t>(
        std::upper_bound(frames.begin(), frames.end(), frame) - frames.begin());
    const std::size_t prev = next - 1;
    if (frames[prev] == frame) return track.values[prev];
    const double t = static_cast<double>(frame - frames[prev]) /
                     static_cast<double>(frames[next] - frames[prev]);
    auto lerp = [t](const nlohmann::json& a, const nlohmann::json& b) {
        const double x = a.get<double>();
        const double y = b.get<double>();
        return x == y ? x : x + (y - x) * t;
    };
    const nlohmann::json& a = track.values[prev];
    const nlohmann::json& b = track.values[next];
    if (a.is_number()) return lerp(a, b);
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i = 0; i < a.size(); ++i) out.push_back(lerp(a[i], b[i]));
    return out;
}

void applyTrack(nlohmann::json& doc, const AnimationTrack& track, int frame) {
    if (nlohmann::json* target = findAt(doc, track.parts)) *target = trackValueAt(track, frame);
}

}  // namespace penumbra::scene
