#version 450 core
// `bitmask` gap filling's reads in one: per texel of a level, the micro-occluder's distance with
// those of its neighbours below and above (y - 1, y + 1; kNone past the map's edge, where no
// neighbour joins), so that backproject.glsl fetches one texel where it fetched three. OWN_IDS 1:
// and its owner (microrects.comp) packed in .w for backproject.glsl's ownObject(), which then
// costs no fetch of its own: the nearest distance of other objects' texels with its low 8 bits
// replaced by the object id + 1 (0: none or unknown), that distance rounded towards 0.
#include "techniques/bitmask/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
#ifndef OWN_IDS
#define OWN_IDS 0
#endif
#if OWN_IDS
// The owners' level (passes::DistancePyramid::owners()); unknown where u_owned is 0
layout(binding = BITMASK_UNIT_NEIGHBOURS_OWNERS) uniform sampler2D u_owners;
uniform int u_owned;
#endif

// The level's distances in .r: the (min, max) pyramid, or the microrects' depths (levels 1 and up)
layout(binding = BITMASK_UNIT_NEIGHBOURS_SOURCE) uniform sampler2D u_source;
layout(rgba32f, binding = BITMASK_IMAGE_NEIGHBOURS_OUT) writeonly uniform image2D o_neighbours;
uniform int u_level;
uniform int u_size;  // texels a side at u_level

// Farther than any receiver: gap filling joins only a neighbour in front of the receiver.
const float kNone = 3.0e38;

void main() {
    ivec2 xy = ivec2(gl_GlobalInvocationID.xy);
    if (xy.x >= u_size || xy.y >= u_size) return;
    float z = texelFetch(u_source, xy, u_level).r;
    float below = xy.y > 0 ? texelFetch(u_source, xy - ivec2(0, 1), u_level).r : kNone;
    float above = xy.y < u_size - 1 ? texelFetch(u_source, xy + ivec2(0, 1), u_level).r : kNone;
    float owner = 0.0;
#if OWN_IDS
    if (u_owned == 1) {
        vec2 o = texelFetch(u_owners, xy, u_level).rg;
        uint id = o.x >= 0.0 ? uint(o.x) + 1u : 0u;  // the host keeps ids below 255
        owner = uintBitsToFloat((floatBitsToUint(o.y) & ~0xFFu) | id);
    }
#endif
    imageStore(o_neighbours, xy, vec4(z, below, above, owner));
}
