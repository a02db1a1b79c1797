// One allocation a render implies, for the memory budget checked before anything is allocated
// (renderer/app/memory_budget.h): the key that sizes it, what it is, and its bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace penumbra {

struct MemoryTerm {
    std::string key;           // "image.width", "image.samples", "technique.map_size", ...
    std::string what;          // "the G-buffer", "shadow map array (4096^2 x 32)", ...
    std::uint64_t bytes = 0;   // the whole allocation
    bool one_texture = false;  // a single GL texture (checked against a software limit)
};

using MemoryTerms = std::vector<MemoryTerm>;

// "256^2": a square map's size in a term's text.
inline std::string squareText(int size) {
    return std::to_string(size) + "^2";
}

}  // namespace penumbra
