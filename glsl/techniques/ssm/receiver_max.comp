#version 450 core
// `ssm` receiver pyramid, one per receiver layer: level 0 is layer u_layer's linear depth
// (empty as -1); each further level holds the farthest receiver of the texels below it, so a
// splat quad finds the farthest receiver of its layer under it in four fetches, and a quad
// over none is culled.
#include "techniques/ssm/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
// The pyramids themselves
layout(binding = SSM_UNIT_RECEIVER_MAX_SOURCE) uniform sampler2DArray u_source;
// The receiver layers
layout(binding = SSM_UNIT_RECEIVER_MAX_LAYERS) uniform sampler2DArray u_layers;
uniform int u_layer;
// Level, layer u_layer
layout(r32f, binding = SSM_IMAGE_RECEIVER_MAX_TARGET) uniform writeonly image2D u_target;
uniform int u_from_depth;    // 1: read the layer's depth, 0: reduce level u_source_level
uniform int u_source_level;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_target);
    if (any(greaterThanEqual(p, size))) return;
    float d;
    if (u_from_depth == 1) {
        d = texelFetch(u_layers, ivec3(p, u_layer), 0).r;
        if (d >= 1.0) d = -1.0;
    } else {
        // 3 x 3, not 2 x 2: an odd level's last row and column belong to the texels before.
        ivec2 below = textureSize(u_source, u_source_level).xy - 1;
        d = -1.0;
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x)
                d = max(d, texelFetch(u_source, ivec3(min(2 * p + ivec2(x, y), below), u_layer),
                                      u_source_level).r);
    }
    imageStore(u_target, p, vec4(d, 0.0, 0.0, 0.0));
}
