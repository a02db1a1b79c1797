// Whether a sample of the sample G-buffer shows the same surface as its pixel's representative
// point (include-only; used by msaa_classify.frag and shade_samples.frag). Section 7 of
// Schwarz & Stamminger 2008 calls samples within a view-depth threshold tau identical; the
// object and the normal are checked too, so creases and touching objects count as edges.
#ifndef PENUMBRA_SAMPLE_MATCH_GLSL
#define PENUMBRA_SAMPLE_MATCH_GLSL

const float kSameDepth = 0.01;    // tau: relative view-depth difference of the same surface
const float kSameNormal = 0.985;  // cosine of the largest normal difference (10 degrees)

// ID, NORMAL (xyz, w = view depth): the sample's; REP_*: the representative's. Background
// (id -1) matches background.
bool sameSurface(int id, vec4 normal, int rep_id, vec4 rep_normal) {
    if (id != rep_id) return false;
    if (id < 0) return true;
    return abs(normal.w - rep_normal.w) <= kSameDepth * rep_normal.w &&
           dot(normal.xyz, rep_normal.xyz) >= kSameNormal;
}

#endif  // PENUMBRA_SAMPLE_MATCH_GLSL
