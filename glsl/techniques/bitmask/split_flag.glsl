// `bitmask` splitting's mark (`split`; backproject.glsl): a microrect whose farthest caster texel
// lies kSplitRatio times as far as its nearest or more carries the mark in the lowest mantissa
// bit of its nearest distance (one part in 2^23 of it), so the back-projection, which fetches
// that distance anyway, finds the few that may split without a fetch of its own.
#ifndef BITMASK_SPLIT_FLAG_GLSL
#define BITMASK_SPLIT_FLAG_GLSL

// A far caster merged with a near one, not the curvature of one caster's surface, which the
// coarse levels approximate at their nearest depth everywhere (a sphere whose centre lies 5
// radii from the light spans 1.2 from its nearest point to its silhouette).
const float kSplitRatio = 1.25;

// NEAR with the mark set where FAR lies kSplitRatio times as far or more, cleared elsewhere.
float markSplit(float near, float far) {
    uint bits = floatBitsToUint(near) & ~1u;
    return uintBitsToFloat(far >= near * kSplitRatio ? bits | 1u : bits);
}

bool splitMarked(float near) {
    return (floatBitsToUint(near) & 1u) != 0u;
}

#endif
