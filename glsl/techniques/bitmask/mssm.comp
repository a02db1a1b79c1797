#version 450 core
// `bitmask` MSSM (multi-scale shadow map): layer k holds, per texel (x, y), the (min, max)
// distance over [x, x + 2^k) x [y, y + 2^k) (clamped at the map's edge). Layer 0 copies an HSM
// level (0 for the MSSM, a coarser one for the YSM's MSSM part); layer k combines four texels
// of layer k - 1.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rg32f, binding = 0) uniform readonly image2D u_hsm_level;
layout(rg32f, binding = 1) uniform image2DArray u_mssm;
uniform int u_layer;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_mssm).xy;
    if (any(greaterThanEqual(p, size))) return;
    vec2 r;
    if (u_layer == 0) {
        r = imageLoad(u_hsm_level, p).rg;
    } else {
        int h = 1 << (u_layer - 1);
        ivec2 q = min(p + h, size - 1);
        vec2 a = imageLoad(u_mssm, ivec3(p, u_layer - 1)).rg;
        vec2 b = imageLoad(u_mssm, ivec3(q.x, p.y, u_layer - 1)).rg;
        vec2 c = imageLoad(u_mssm, ivec3(p.x, q.y, u_layer - 1)).rg;
        vec2 d = imageLoad(u_mssm, ivec3(q, u_layer - 1)).rg;
        r = vec2(min(min(a.x, b.x), min(c.x, d.x)), max(max(a.y, b.y), max(c.y, d.y)));
    }
    imageStore(u_mssm, ivec3(p, u_layer), vec4(r, 0.0, 0.0));
}
