// `bitmask` search areas (Schwarz & Stamminger, 3): the receiver in the light's frame, the
// shadow-map area that the light pyramid through it cuts at a depth, the depth range of an
// area from the HSM, MSSM or YSM, and the budget's level. Coordinates: window (x/z, y/z at the
// light's centre), texels of level 0 (window - lo) / texel. Needs ACCEL 0 HSM, 1 MSSM, 2 YSM.
#include "techniques/bitmask/bindings.glsl"
#ifndef MICROQUADS
#define MICROQUADS 0
#endif
#define CLASS_LIT 0
#define CLASS_PENUMBRA 1
#define CLASS_UMBRA 2

#include "common/geometric_normal.glsl"
#include "common/min_max_pyramid.glsl"

layout(binding = BITMASK_UNIT_SEARCH_POSITION) uniform sampler2D u_position;
layout(binding = BITMASK_UNIT_SEARCH_NORMAL) uniform sampler2D u_normal;
layout(binding = BITMASK_UNIT_SEARCH_ID) uniform isampler2D u_id;
// Per object id: (receives, casts, convex and both), 0 or 1
layout(binding = BITMASK_UNIT_SEARCH_RECEIVES) uniform sampler2D u_receives;
// (min, max) distance, mip pyramid
layout(binding = BITMASK_UNIT_SEARCH_HSM) uniform sampler2D u_hsm;
#if ACCEL != 0
// Layer k: 2^k x 2^k neighbourhoods
layout(binding = BITMASK_UNIT_SEARCH_MSSM) uniform sampler2DArray u_mssm;
uniform int u_mssm_base;                            // the HSM level that is MSSM layer 0
#endif

#include "common/light_frame.glsl"
uniform vec2 u_light_half;     // half the light's size
uniform vec2 u_win_lo;         // the map's window at distance 1
uniform vec2 u_texel;          // window units per level-0 texel
uniform int u_map_size;
uniform int u_levels;
uniform float u_near;          // the nearest caster's distance
uniform float u_normal_offset; // receiver offset along its normal, in texels at its distance
uniform float u_depth_bias;    // a micro-occluder counts when nearer than (1 - bias) * p.z

// The receiver at pixel PIX in the light's frame (x right, y up, z forward), offset along its
// normal by u_normal_offset level-0 texels and, for a receiver that also casts, by up to
// 2^LEVEL - 1 more as its surface's slope from the light needs (a level-l micropatch of its own
// surface holds the nearest depth of 2^l x 2^l texels, so it lies up to that much nearer the
// light: a level-0 offset left coarse levels shadowing their own surface in bands); false
// where the pixel has no receiving geometry or lies behind the light. HORIZON is its tangent
// plane seen from the light: the height of light point (u, v) (the light as the unit square,
// u along right) above the plane is horizon.x + horizon.y u + horizon.z v. Only an object
// that casts hides the light below its plane (as its far side does for `exact`), a receiver or
// not (role `occluder`: false, but HORIZON set, for its visibility); others get the plane 1
// (all above). PLANE: on a flat face of an object that casts, its tangent plane in the light's
// frame (normal, offset: (x, y, z) lies on it where dot(normal, (x, y, z)) = offset), for
// backproject.glsl's ownSurface() (not with microquads); else 0. OWN: the receiver's object id
// where that object casts and is convex (it cannot shadow itself beyond its tangent plane, the
// horizon's share), for backproject.glsl's ownObject(); else -1.
bool receiverAt(ivec2 pix, int level, out vec3 p, out vec3 horizon, out vec4 plane, out int own) {
    p = vec3(0.0);
    horizon = vec3(1.0, 0.0, 0.0);
    plane = vec4(0.0);
    own = -1;
    vec4 pos = texelFetch(u_position, pix, 0);
    if (pos.w == 0.0) return false;
    int id = texelFetch(u_id, pix, 0).r;
    vec3 role = id < 0 ? vec3(0.0) : texelFetch(u_receives, ivec2(id, 0), 0).rgb;
    if (role.x < 0.5 && role.y < 0.5) return false;
    vec3 n = normalize(texelFetch(u_normal, pix, 0).xyz);
    vec3 d = pos.xyz - u_light_centre;
    float z = dot(d, u_light_forward);
    if (z <= 0.0) return false;
    float most = 1.0;  // the slope's cap (below)
    if (role.y > 0.5) {
        // The plane of the drawn triangle: the surface that hides the light from itself.
        vec3 g = geometricNormal(pix);
        if (dot(g, n) > 0.9999) most = 2.0;  // a flat face (shading normal = the facet's)
        vec2 e = 2.0 * u_light_half * vec2(dot(g, u_light_right), dot(g, u_light_up));
        horizon = vec3(-dot(d, g) - 0.5 * (e.x + e.y), e);
        if (most == 2.0 && MICROQUADS == 0) {
            vec3 gn = vec3(dot(g, u_light_right), dot(g, u_light_up), dot(g, u_light_forward));
            plane = vec4(gn, dot(g, d));
        }
    }
    if (role.x < 0.5) return false;
    // (Not on a closed object's far side seen at a silhouette: its normal faces inwards there.)
    if (role.z > 0.5 && !seenFromBehind(pix)) own = id;
    // The surface's depth step per lateral step, sin / cos^2 of the angle between its normal and
    // the direction to the light's centre, is what the offset along the normal must make up, up
    // to 1 (45 degrees) on a smooth surface and 2 (62 degrees) on a flat face. A flat face
    // cannot shadow itself, so the clearance costs it nothing, and capped at 1 the lit face of
    // a box tilted 24 degrees was striped by its own coarse microrects
    // (tests/data/gl/tilted_box.json); on a smooth surface it would hide the object's shadows on
    // itself (2 everywhere: duck_resting's head on its body, receivers 0.062 -> 0.077).
    float c = clamp(-dot(n, normalize(d)), 0.05, 1.0);
    float slope = min(sqrt(1.0 - c * c) / (c * c), most);
    float extra = role.y > 0.5 ? float((1 << level) - 1) * slope : 0.0;
    float texel = max(u_texel.x, u_texel.y) * z;
    if (plane.xyz != vec3(0.0)) {
        // A flat face takes the level's part along the ray to the light's centre only: its own
        // micro-occluders are left out by ownSurface() instead. Along its normal, a face nearly
        // edge-on to the light moved sideways by up to 2 (2^l - 1) texels, out of the shadow
        // cast on it (random scene rand9307: a box's front face under a floating sphere, 0.09
        // in exact, read 0.46).
        d += n * (u_normal_offset * texel) - normalize(d) * (extra * c * texel);
    } else {
        d += n * ((u_normal_offset + extra) * texel);
    }
    p = vec3(dot(d, u_light_right), dot(d, u_light_up), dot(d, u_light_forward));
    return p.z > 0.0;
}

// Whether part of the light lies below the receiver's tangent plane HORIZON (receiverAt()).
bool crossesHorizon(vec3 horizon) {
    return horizon.x + min(horizon.y, 0.0) + min(horizon.z, 0.0) < 0.0;
}

// The distance below which a micro-occluder shadows P.
float biasedDepth(vec3 p) { return p.z * (1.0 - u_depth_bias); }

// The search area of P at depth Z: the light pyramid through P cut at Z, in level-0 texels
// (x0, y0, x1, y1), unclipped.
vec4 searchArea(vec3 p, float z) {
    return lightSearchArea(p, z, u_light_half, u_win_lo, u_texel);
}

bool areaMissesMap(vec4 a) { return areaMissesMap(a, u_map_size); }

bool areaInsideMap(vec4 a) {
    return a.x >= 0.0 && a.y >= 0.0 && a.z < float(u_map_size) && a.w < float(u_map_size);
}

// The b_mo of an "unlimited" budget (0): level 0 up to 64 x 64 texels of search area, coarser
// levels where it is larger, so that no pixel back-projects more than about 65 x 65
// micro-occluders (the multi-resolution bound of section 3). On a square area a level-l
// micropatch at the nearest occluder's depth then back-projects onto at most 1/64 of the
// light's width, a quarter of the spacing of 16 x 16 light samples. (llvmpipe also ends a shader's loops after 65535 iterations in all:
// an unbounded area lost every row past the first 64 thousand texels, a straight seam.)
const int kUnlimitedBudget = 65;

// The fractional level at which a search area of EXTENT (areaExtent()) spans at most BUDGET
// texels per axis (extent / 2^l <= budget - 1), its longer side at most (BUDGET - 1)^2
// (BUDGET <= 0 is kUnlimitedBudget).
float budgetLevel(vec2 extent, int budget) {
    float b = float(budget <= 0 ? kUnlimitedBudget : budget) - 1.0;
    float e = max(extent.x, extent.y / b);
    return clamp(log2(max(e, 1e-6) / b), 0.0, float(u_levels - 1));
}

// The extent of search area A (level-0 texels) that sets its level: its longer side inside the
// map (the paper's width of a square area), over the root of the whole area's aspect where
// that is not square, so that the level follows the area's size, not its longer side, and the
// longer side itself (budgetLevel()). A light longer than 2:1 has longer areas than texels
// (passes::occluderWindow): read by its longer side, an area 50 times longer than wide (a
// 100:1 light over texels of 2:1) was read where its shorter side is a fraction of a texel,
// and a shadow's edge across the strip came out in stairs of that level's texels
// (tests/data/gl/strip_light.json; at 320 x 240, light_aspect_1to16 0.0164 -> 0.0362 against
// `exact`). An area cut by the map's edge keeps its
// longer side: spending the budget on its cut part too made 31 of the corpus's 45 scenes
// better (median 0.0183 -> 0.0169) but frames up to 1.5x slower (light_size_2 at 1024 x 768).
vec2 areaExtent(vec4 a) {
    vec4 c = clamp(a, vec4(0.0), vec4(float(u_map_size)));
    float side = max(c.z - c.x, c.w - c.y);
    vec2 u = max(a.zw - a.xy, vec2(1e-6));
    float aspect = max(u.x, u.y) / min(u.x, u.y);
    return vec2(aspect > 1.01 ? side / sqrt(aspect) : side, side);
}

// The HSM level at which the inclusive texel range R (level 0) spans at most 2 x 2 texels.
int hsmQueryLevel(ivec4 r) { return pyramidLevel(r, u_levels); }

vec2 hsmRange(ivec4 r, int k) { return pyramidRange(u_hsm, r, k); }

#if ACCEL != 0
#include "techniques/bitmask/mssm_range.glsl"

vec2 mssmRange(ivec4 r) { return mssmRange(u_mssm, r); }
#endif

// The (min, max) distance over area A (level-0 texels), grown outward to whole texels of level
// ALIGN first, so that a pixel is called lit only where every level-ALIGN micro-occluder it
// would back-project is behind it (section 6, "over-precision").
vec2 depthRange(vec4 a, int align) {
    ivec4 r = clamp(ivec4(floor(a)), ivec4(0), ivec4(u_map_size - 1));
    r.xy = (r.xy >> align) << align;
    r.zw = min(((r.zw >> align) << align) + ((1 << align) - 1), ivec2(u_map_size - 1));
#if ACCEL == 0
    return hsmRange(r, hsmQueryLevel(r));
#elif ACCEL == 1
    return mssmRange(r);
#else
    int k = hsmQueryLevel(r);
    if (k <= u_mssm_base) return hsmRange(r, k);
    return mssmRange(r >> u_mssm_base);
#endif
}

// The texels of LEVEL that hold area A (level-0 texels), clamped to [0, size - LAST].
ivec4 levelRange(vec4 a, int level, int last) {
    int n = u_map_size >> level;
    return clamp(ivec4(floor(a / float(1 << level))), ivec4(0), ivec4(max(n - last, 0)));
}
