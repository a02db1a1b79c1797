#version 450 core
// Stores light_depth.vert's depth: in the depth buffer (linear, so receivers compare depths
// linearly; nearest or farthest surface by the host's depth test), with IDS also the object id
// in colour 0; with DISTANCE, the distance as (min, max) in colour 0 (the level 0 of a min/max
// pyramid) under the rasteriser's own depth, and with IDS too (object id, 1e30) in colour 1 (the
// texel's owner: passes::DistancePyramid::owners()); with RANGE, the depth in colours 0 and 1,
// which MIN and MAX blending keep as the nearest and the farthest surface in one draw (no depth
// test).
#ifndef IDS
#define IDS 0
#endif
#ifndef DISTANCE
#define DISTANCE 0
#endif
#ifndef RANGE
#define RANGE 0
#endif
in float v_depth;
#if RANGE
layout(location = 0) out float o_nearest;
layout(location = 1) out float o_farthest;
void main() {
    o_nearest = clamp(v_depth, 0.0, 1.0);
    o_farthest = o_nearest;
}
#elif DISTANCE
layout(location = 0) out vec2 o_range;
#if IDS
uniform int u_object_id;
layout(location = 1) out vec2 o_owner;
#endif
void main() {
    o_range = vec2(v_depth);
#if IDS
    o_owner = vec2(float(u_object_id), 1e30);
#endif
}
#else
#if IDS
uniform int u_object_id;
layout(location = 0) out int o_id;
#endif
void main() {
    gl_FragDepth = clamp(v_depth, 0.0, 1.0);
#if IDS
    o_id = u_object_id;
#endif
}
#endif
