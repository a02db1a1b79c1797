// Animation tracks: numeric values of the scene document, addressed by dotted key, keyed at
// frames, interpolated linearly between keys and held before the first and after the last.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace penumbra::scene {

struct AnimationTrack {
    std::string key;                     // dotted key of the animated value ("lights.0.position")
    std::vector<std::string> parts;      // KEY split at dots
    std::vector<int> frames;             // strictly increasing, at least one
    std::vector<nlohmann::json> values;  // one per frame: a number or an array of numbers
};

struct Animation {
    std::optional<std::string> frames;  // "animation.frames", checked with parseFrameSpec
    std::vector<AnimationTrack> tracks;
};

// Reads DOC's "animation" block. Each track's key must address a number or an array of numbers
// in DOC, and every key value must have that shape. Throws InputError naming the key.
Animation parseAnimation(const nlohmann::json& doc, const std::string& file);

// The track's value at FRAME.
nlohmann::json trackValueAt(const AnimationTrack& track, int frame);

// Writes the track's value at FRAME into DOC (whose shape parseAnimation checked).
void applyTrack(nlohmann::json& doc, const AnimationTrack& track, int frame);

}  // namespace penumbra::scene
