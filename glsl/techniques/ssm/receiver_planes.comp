#version 450 core
// `ssm` receiver tangent planes, one per texel of each receiver layer: the unit normal (toward
// the light's centre) of the layer's surface in the light's frame, from the neighbouring texels
// nearer in depth; zero where the layer has no receiver or no neighbour. splat.frag lets a
// micro-patch shadow its own object's surface where the patch lies above this plane.
#include "techniques/ssm/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
// The receiver layers (linear depth, 1 = none)
layout(binding = SSM_UNIT_PLANES_LAYERS) uniform sampler2DArray u_layers;
layout(rgba16f, binding = SSM_IMAGE_PLANES_TARGET) uniform writeonly image2DArray u_target;
uniform vec2 u_ssm_lo;     // soft-shadow-map window at distance 1
uniform vec2 u_ssm_texel;  // one texel of it
uniform float u_receiver_near;
uniform float u_receiver_range;

// The receiver of layer K at texel T in the light's frame (x, y at its depth, z), w = 0 where
// the layer has none.
vec4 receiverAt(ivec2 t, int k) {
    if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, textureSize(u_layers, 0).xy)))
        return vec4(0.0);
    float d = texelFetch(u_layers, ivec3(t, k), 0).r;
    if (d >= 1.0) return vec4(0.0);
    float z = u_receiver_near + d * u_receiver_range;
    return vec4((u_ssm_lo + (vec2(t) + 0.5) * u_ssm_texel) * z, z, 1.0);
}

// The step from P (at T) to the receiver at T + STEP or T - STEP: the one nearer in depth, so
// that an edge of the layer does not tilt the plane (zero where neither exists).
vec3 surfaceStep(ivec2 t, int k, ivec2 step, vec3 p) {
    vec4 a = receiverAt(t + step, k), b = receiverAt(t - step, k);
    if (a.w == 0.0 && b.w == 0.0) return vec3(0.0);
    if (b.w == 0.0 || (a.w != 0.0 && abs(a.z - p.z) <= abs(b.z - p.z))) return a.xyz - p;
    return p - b.xyz;
}

void main() {
    ivec3 t = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(t.xy, imageSize(u_target).xy))) return;
    vec4 p = receiverAt(t.xy, t.z);
    vec3 n = vec3(0.0);
    if (p.w != 0.0) {
        n = cross(surfaceStep(t.xy, t.z, ivec2(1, 0), p.xyz),
                  surfaceStep(t.xy, t.z, ivec2(0, 1), p.xyz));
        if (dot(n, n) > 0.0) n = normalize(dot(n, p.xyz) > 0.0 ? -n : n);
    }
    imageStore(u_target, t, vec4(n, 0.0));
}
