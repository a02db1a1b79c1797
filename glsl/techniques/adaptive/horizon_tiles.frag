#version 450 core
// `adaptive`: flags the screen tiles that hold a caster's pixel whose tangent plane cuts the
// light: its own surface hides the light's part below the plane (lit_eval.frag), which the
// maps' bits do not show, so every split of a cell is refined in these tiles too.
#include "techniques/adaptive/bindings.glsl"

layout(std430, binding = ADAPTIVE_BINDING_LIT_HORIZON_TILES) writeonly buffer HorizonTiles {
    uint u_horizon_tiles[];  // per tile: 1 where some pixel's plane cuts the light
};

layout(binding = ADAPTIVE_UNIT_COMPARE_POSITION) uniform sampler2D u_position;
layout(binding = ADAPTIVE_UNIT_COMPARE_ID) uniform isampler2D u_id;

uniform int u_tile_side;     // screen tiles' side in pixels
uniform int u_tile_columns;  // screen tiles per row
uniform vec2 u_light_half;   // half the light's size
#include "common/light_frame.glsl"
#include "common/caster_flags.glsl"
#include "common/geometric_normal.glsl"
#include "techniques/adaptive/horizon.glsl"

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(u_position, pixel, 0);
    if (pos.w == 0.0 || !objectCasts(texelFetch(u_id, pixel, 0).r)) return;
    if (!tangentCutsLight(inLightAxes(geometricNormal(pixel)), inLightAxes(pos.xyz), u_light_half))
        return;
    ivec2 tile = pixel / u_tile_side;
    u_horizon_tiles[tile.y * u_tile_columns + tile.x] = 1u;  // every writer writes 1
}
