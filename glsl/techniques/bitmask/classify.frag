#version 450 core
// `bitmask` pass 1 (Schwarz & Stamminger, Fig. 3 step 1): per pixel, the search area refined
// by its depth range, the class (lit and umbra need no back-projection) and the fractional
// level that meets the pixel's budget, written to the search-area and LOQ maps.
#include "techniques/bitmask/bindings.glsl"
#include "techniques/bitmask/search.glsl"

uniform int u_refine_steps;
uniform int u_budget;         // b_mo at the centre (0: unlimited)
uniform int u_budget_edge;    // b_mo at the corners with the falloff, where the map is 0
uniform int u_budget_falloff;
uniform int u_budget_map_on;  // 1: u_budget_map moves b_mo toward u_budget_edge
uniform int u_grow_query;     // 1: grow query areas to the budget level's texels
// v in [0, 1], stretched over the image
layout(binding = BITMASK_UNIT_CLASSIFY_BUDGET_MAP) uniform sampler2D u_budget_map;

layout(location = 0) out vec4 o_area;  // level-0 texels (x0, y0, x1, y1)
layout(location = 1) out vec4 o_loq;   // (level or -1, class, budget, 0)

// b_mo at PIX (a pixel centre): uniform, or falling off from the centre to the corners, and
// with a budget map moved toward u_budget_edge where the map is below 1.
int budgetAt(vec2 pix) {
    if (u_budget <= 0 || (u_budget_falloff == 0 && u_budget_map_on == 0)) return u_budget;
    vec2 size = vec2(textureSize(u_position, 0));
    float budget = float(u_budget);
    if (u_budget_falloff == 1) {
        float r = length((pix - 0.5 * size) / (0.5 * size)) / sqrt(2.0);
        budget = mix(float(u_budget), float(u_budget_edge), smoothstep(0.0, 1.0, r));
    }
    if (u_budget_map_on == 1)
        budget = mix(float(u_budget_edge), budget, texture(u_budget_map, pix / size).r);
    return int(round(budget));
}

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    int budget = budgetAt(gl_FragCoord.xy);
    o_area = vec4(0.0);
    o_loq = vec4(-1.0, float(CLASS_LIT), float(budget), 0.0);
    vec3 p, horizon;
    vec4 plane;
    int own;
    if (!receiverAt(pix, 0, p, horizon, plane, own)) return;
    float pz = biasedDepth(p);
    float z = u_near;
    if (pz <= z) return;
    vec4 area = searchArea(p, z);
    vec2 range = vec2(0.0);
    vec4 queried = area;
    for (int step = 0; step <= u_refine_steps; ++step) {
        if (areaMissesMap(area)) return;
        int align = u_grow_query == 1 ? int(ceil(budgetLevel(areaExtent(area), budget))) : 0;
        range = depthRange(area, align);
        queried = area;
        if (range.x >= pz) return;      // every texel is behind p: fully lit
        if (range.x <= z) break;        // the area cannot shrink further
        z = range.x;
        area = searchArea(p, z);
    }
    if (areaInsideMap(queried) && range.y < pz) {
        o_loq.y = float(CLASS_UMBRA);   // every texel of the area is in front of p
        return;
    }
    o_area = area;
    o_loq.x = budgetLevel(areaExtent(area), budget);
    o_loq.y = float(CLASS_PENUMBRA);
}
