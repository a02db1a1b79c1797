#version 450 core
// `bitmask` gap filling's reads in one: per texel of a level, the micro-occluder's distance with
// those of its neighbours below and above (y - 1, y + 1; kNone past the map's edge, where no
// neighbour joins), so that backproject.glsl fetches one texel where it fetched three.
#include "techniques/bitmask/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

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
    imageStore(o_neighbours, xy, vec4(z, below, above, 0.0));
}
