// The point at which a receiver is tested against a light's shadow maps: on an object that
// casts, moved along its normal against self-shadowing; elsewhere the receiver itself.
// Include-only, after common/light_frame.glsl.
#ifndef PENUMBRA_RECEIVER_POINT_GLSL
#define PENUMBRA_RECEIVER_POINT_GLSL

// POS (world) with normal N, moved by OFFSET texels of TEXEL world size per unit distance from
// the light's plane when CASTS. An object that casts no shadow is in no map, so it cannot
// shadow itself, and an offset would only move the shadows it receives (most at contacts).
vec3 receiverTestPoint(vec3 pos, vec3 n, bool casts, float offset, float texel) {
    if (!casts) return pos;
    float dist = max(dot(pos - u_light_centre, u_light_forward), 0.0);
    return pos + n * (offset * texel * dist);
}

#endif
