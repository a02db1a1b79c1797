#version 450 core
// `ssm` splat: the share of the light one micro-patch hides from the receiver seen through this
// soft-shadow-map texel. The patch is back-projected from the receiver onto the light. AREA:
// the covered area is the product of two interval intersections (Atty et al. 3.4, 4.2) and the
// host sums the patches with additive blending; overlapping back-projections count twice
// (5.1.2). SAMPLES: the light samples inside it are ORed into the texel's mask, the union of
// all patches of both sides (samples_resolve.comp counts them). Once per receiver layer.
#include "techniques/ssm/bindings.glsl"
#ifndef SAMPLES
#define SAMPLES 0
#endif
// The class of patches this program draws (bindings.glsl): it holds only their ways of counting
#ifndef PATCH_CLASS
#define PATCH_CLASS SSM_CLASS_MICRO
#endif
// The stencil of texels with nothing left to add (splat_done.frag), tested before the shader runs
layout(early_fragment_tests) in;
// Linear receiver depth, 1 = none
layout(binding = SSM_UNIT_SPLAT_RECEIVER) uniform sampler2DArray u_receiver;
uniform int u_layer;  // the receiver layer splatted into
uniform vec2 u_light_half;
uniform vec2 u_ssm_lo;
uniform vec2 u_ssm_texel;  // one soft-shadow-map texel at distance 1
uniform float u_receiver_near;
uniform float u_receiver_range;
uniform float u_depth_bias;  // a patch must be this fraction of z_R nearer than the receiver

layout(binding = SSM_UNIT_SPLAT_LAYER_IDS) uniform isampler2DArray u_layer_ids;
// Per receiver layer: the unit normal of its surface in the light's frame (receiver_planes.comp)
layout(binding = SSM_UNIT_SPLAT_PLANES) uniform sampler2DArray u_planes;
uniform int u_layered;  // 1: receiver layers with object ids (LAYERS > 1), however many hold one

flat in vec4 v_rect;  // the patch in window units at distance 1 (x0, y0, x1, y1)
flat in float v_depth;
flat in float v_depth_near;  // a merged patch's nearest micro-patch (lod.comp); else v_depth
flat in int v_object;
flat in int v_children;  // micro-patches per side merged into this one (lod.comp)
flat in ivec2 v_texel;   // its (first) occluder texel
flat in float v_reach;   // far side: its surface's depth span beyond it (splat.vert)
flat in vec4 v_sealed;   // its edges grown by u_seal toward its own object (splat.vert)
uniform float u_seal;
// A merged block of a tilted surface (SSM_CLASS_PLANE): its plane's corner distances
flat in vec4 v_corner_z;
uniform float u_lod_depth;  // its micro-patches lie within half of this of their distance

// A merged patch's micro-patches (a receiver near it in depth counts them one by one)
layout(binding = SSM_UNIT_SPLAT_OCC_DEPTH) uniform sampler2D u_occ_depth;  // linear
uniform float u_occ_near;
uniform float u_occ_range;
uniform vec2 u_occ_lo;     // occluder-map window at distance 1
uniform vec2 u_occ_texel;  // one texel of it

layout(location = 0) out vec4 o_occlusion;

// Receivers nearer than this many depth spans of a merged patch count its micro-patches.
const float kNearSpans = 4.0;

#if SAMPLES
// The light's 256 samples: sample (i, j) of a 16 x 16 grid sits at ((16 i + j + 0.5) / 256,
// (16 j + i + 0.5) / 256) of the light, so that each axis sees 256 distinct positions (a
// penumbra along a light edge steps by 1/256, not 1/16). Word w holds rows 2w and 2w + 1.
layout(binding = SSM_IMAGE_SPLAT_MASKS, r32ui) uniform coherent uimage2DArray u_masks;
uint g_mask[SSM_SAMPLE_WORDS];

// The samples of row J inside the sample-index box K (see addSamples) as bits 0-15: a run of
// i, where both the x and the y conditions hold (ceilings of n / 16 by arithmetic shifts).
uint rowRun(int j, ivec4 k) {
    int a = max(max((k.x - j + 15) >> 4, k.y - 16 * j), 0);
    int b = min(min((k.z - j + 15) >> 4, k.w - 16 * j), 16);
    return a < b ? ((1u << uint(b)) - 1u) & ~((1u << uint(a)) - 1u) : 0u;
}

// Ors the samples inside U (x0, y0, x1, y1 in light units [0, 1]) into g_mask, every row in a
// loop of constant length (no divergence, no dynamically indexed array).
void addSamples(vec4 u) {
    ivec4 k = ivec4(ceil(u * 256.0 - 0.5));  // sample indices 16i + j (x), 16j + i (y): [lo, hi)
    if (k.z <= k.x || k.w <= k.y) return;
    for (int w = 0; w < SSM_SAMPLE_WORDS; ++w)
        g_mask[w] |= rowRun(2 * w, k) | (rowRun(2 * w + 1, k) << 16u);
}

// Ors the samples that a merged block's plane hides from the receiver P into g_mask: its
// corners, each at its own distance, back-projected from P onto the light (a plane's central
// projection is a quadrilateral, convex as every corner lies in front of P). Along row j a
// sample (i, j) moves by (16, 1) / 256 per i, so each edge bounds i on one side, at a bound
// linear in j: every row's run from four multiply-adds per edge.
void addQuad(vec3 p) {
    vec2 uv[4] = vec2[4](v_rect.xy, v_rect.zy, v_rect.zw, v_rect.xw);
    vec2 c[4];
    float twice_area = 0.0;
    for (int k = 0; k < 4; ++k) {
        float z = v_corner_z[k];
        vec2 onto = p.xy + (uv[k] * z - p.xy) * (p.z / (p.z - z));
        c[k] = (onto + u_light_half) / (2.0 * u_light_half);
    }
    for (int k = 0; k < 4; ++k)
        twice_area += c[k].x * c[(k + 1) & 3].y - c[k].y * c[(k + 1) & 3].x;
    if (twice_area == 0.0) return;
    float turn = sign(twice_area);  // counter-clockwise edges keep the inside on their left
    // Per edge: inside where f(j) + g i >= 0, f(j) = f0 + df j (sample (0, j) at
    // ((j + 0.5) / 256, (16 j + 0.5) / 256)).
    vec4 f0, df, g;
    for (int k = 0; k < 4; ++k) {
        vec2 a = c[k], e = (c[(k + 1) & 3] - a) * turn;
        f0[k] = (e.x * (0.5 / 256.0 - a.y) - e.y * (0.5 / 256.0 - a.x));
        df[k] = (e.x * 16.0 - e.y) / 256.0;
        g[k] = (e.x - e.y * 16.0) / 256.0;
    }
    bvec4 lower = greaterThan(g, vec4(0.0)), upper = lessThan(g, vec4(0.0));
    vec4 inverse = 1.0 / mix(vec4(1.0), g, not(equal(g, vec4(0.0))));
    for (int w = 0; w < SSM_SAMPLE_WORDS; ++w) {
        uint word = 0u;
        for (int half_row = 0; half_row < 2; ++half_row) {
            float j = float(2 * w + half_row);
            vec4 f = f0 + df * j, t = -f * inverse;
            // An edge with g = 0 keeps the whole row or none of it.
            vec4 from = mix(mix(vec4(-1.0), vec4(16.0), lessThan(f, vec4(0.0))), t, lower);
            vec4 to = mix(vec4(15.0), t, upper);
            float lo = max(max(from.x, from.y), max(from.z, from.w));
            float hi = min(min(to.x, to.y), min(to.z, to.w));
            int a = int(ceil(clamp(lo, 0.0, 16.0))), b = int(floor(clamp(hi, -1.0, 15.0)));
            uint run = a <= b ? ((2u << uint(b)) - 1u) & ~((1u << uint(a)) - 1u) : 0u;
            word |= run << uint(16 * half_row);
        }
        g_mask[w] |= word;
    }
}
#else
float g_sum = 0.0;  // the summed covered area
#endif

// Adds what rectangle R (x0, y0, x1, y1, light's frame at distance Z) hides from the receiver
// P: back-projected from P onto the light (distance 0), in light units [0, 1].
void add(vec4 r, float z, vec3 p) {
    float s = p.z / (p.z - z);
    vec4 onto = p.xyxy + (r - p.xyxy) * s;
    vec4 unit = clamp((onto + u_light_half.xyxy) / (2.0 * u_light_half.xyxy), 0.0, 1.0);
#if SAMPLES
    addSamples(unit);
#else
    vec2 c = unit.zw - unit.xy;
    g_sum += c.x * c.y;
#endif
}

// Whether the micro-patch R at distance Z lies wholly above the tangent plane N of the
// receiver P by MARGIN (its lowest corner: each axis's nearer side).
bool above(vec3 n, vec4 r, float z, vec3 p, float margin) {
    vec2 lo = min(n.xy * r.xy, n.xy * r.zw);
    return lo.x + lo.y + n.z * z - dot(n, p) > margin;
}

// Adds what is hidden from the receiver P at texel T, a surface of the patch's own
// object, by the patch R at distance Z where its micro-patches lie wholly above P's tangent
// plane (receiver_planes.comp) by a margin for that plane's estimate: the light they hide lies
// above P's horizon, none of it the part the visibility pass takes in closed form. A patch
// merged by lod.comp counts each of its v_children^2 micro-patches so, a row at a time: in a
// row the ones above the plane are a run, as each one's lowest corner rises linearly.
void addOwnObject(ivec2 t, vec4 r, float z, vec3 p) {
    vec3 n = texelFetch(u_planes, ivec3(t, u_layer), 0).xyz;
    if (n == vec3(0.0)) return;
    float margin = (u_depth_bias + 2.0 * max(u_ssm_texel.x, u_ssm_texel.y)) * p.z;
    if (PATCH_CLASS == SSM_CLASS_MICRO || v_children == 1) {
        if (above(n, r, z, p, margin)) add(r, z, p);
        return;
    }
    // No row has a micro-patch above the plane where the block's highest corner is not (each
    // micro-patch's lowest corner lies no higher): the rows' loop would add nothing.
    vec2 hi = max(n.xy * r.xy, n.xy * r.zw);
    if (hi.x + hi.y + n.z * z - dot(n, p) <= margin - 1e-5 * p.z) return;
    int k = v_children;
    vec2 w = (r.zw - r.xy) / float(k);  // one micro-patch
    float rise = n.x * w.x;             // of the lowest corner from a column to the next
    for (int j = 0; j < k; ++j) {
        float y0 = r.y + float(j) * w.y, y1 = y0 + w.y;
        // Column 0's lowest corner over the plane, less the margin.
        float h =
            n.x * r.x + min(0.0, rise) + min(n.y * y0, n.y * y1) + n.z * z - dot(n, p) - margin;
        int first = 0, last = k - 1;  // the run above the plane: h + rise * i > 0
        if (rise > 0.0)
            first = max(int(floor(-h / rise)) + 1, 0);
        else if (rise < 0.0)
            last = min(int(ceil(-h / rise)) - 1, k - 1);
        else if (h <= 0.0)
            continue;
        if (first <= last)
            add(vec4(r.x + float(first) * w.x, y0, r.x + float(last + 1) * w.x, y1), z, p);
    }
}

// Whether no micro-patch of a merged block's plane can lie above the tangent plane N of the
// receiver P by MARGIN (addMicroPatches' test, which then adds nothing): the plane's highest
// corner over that plane (a plane's extremes over its rectangle lie at its corners) stays below
// MARGIN by more than a micro-patch may stray from the plane: half of lod_depth (lod.comp's
// merge rule) and the plane's depth change over one micro-patch and its seal.
bool planeBelow(vec3 n, vec3 p, float margin) {
    vec2 uv[4] = vec2[4](v_rect.xy, v_rect.zy, v_rect.zw, v_rect.xw);
    float highest = -1e30, reach = 0.0;
    for (int k = 0; k < 4; ++k) {
        vec3 ray = vec3(uv[k], 1.0);
        highest = max(highest, dot(n, ray * v_corner_z[k]));
        reach = max(reach, abs(dot(n, ray)));
    }
    vec4 z = v_corner_z;
    float z_min = min(min(z.x, z.y), min(z.z, z.w)), z_max = max(max(z.x, z.y), max(z.z, z.w));
    // Along an axis the plane's depth changes at most (z_max - z_min) (z_max / z_min)^2 over the
    // block's width per texel (1 / depth is linear in texels); a sealed micro-patch's corners lie
    // within 0.75 texels of its middle on each axis.
    float ratio = z_max / z_min;
    float stray = 0.5 * u_lod_depth * z_max / (1.0 - 0.5 * u_lod_depth) +
                  1.5 * (z_max - z_min) * ratio * ratio / float(v_children);
    return highest - dot(n, p) + stray * reach + 1e-5 * p.z < margin;
}

// Adds a merged patch's occlusion of the receiver P at texel T micro-patch by micro-patch, at
// their own depths, as the unmerged splat counts them (OWN: P is of the patch's object).
void addMicroPatches(ivec2 t, vec3 p, bool own) {
    vec3 n = texelFetch(u_planes, ivec3(t, u_layer), 0).xyz;
    if (own && n == vec3(0.0)) return;
    float margin = (u_depth_bias + 2.0 * max(u_ssm_texel.x, u_ssm_texel.y)) * p.z;
    // On its own object, a plane whose micro-patches all lie below the receiver's tangent plane
    // adds nothing (on rand3001, 19 of a million such fragments added a sample)
    if (PATCH_CLASS == SSM_CLASS_PLANE && own && planeBelow(n, p, margin)) return;
    for (int j = 0; j < v_children; ++j)
        for (int i = 0; i < v_children; ++i) {
            ivec2 c = v_texel + ivec2(i, j);
            float z = u_occ_near + texelFetch(u_occ_depth, c, 0).r * u_occ_range;
            if (p.z - z <= u_depth_bias * p.z) continue;
            vec2 lo = u_occ_lo + vec2(c) * u_occ_texel;
            // Inner edges grow as the block's grew toward its neighbours (splat.vert).
            vec4 grow = vec4(i > 0 ? 1.0 : v_sealed.x, j > 0 ? 1.0 : v_sealed.y,
                             i < v_children - 1 ? 1.0 : v_sealed.z,
                             j < v_children - 1 ? 1.0 : v_sealed.w) * u_seal;
            vec4 r = (vec4(lo, lo + u_occ_texel) + vec4(-grow.xy, grow.zw) * u_occ_texel.xyxy) * z;
            if (!own || above(n, r, z, p, margin)) add(r, z, p);
        }
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    float dr = texelFetch(u_receiver, ivec3(texel, u_layer), 0).r;
    if (dr >= 1.0) discard;
    float zr = u_receiver_near + dr * u_receiver_range;
    // No micro-patch in front of it (nor, far side, its surface's span)
    if (zr - v_depth_near <= u_depth_bias * zr + v_reach) discard;
    vec3 p = vec3((u_ssm_lo + (vec2(texel) + 0.5) * u_ssm_texel) * zr, zr);
    // A patch shadows its own object's surface only where it lies wholly above that surface's
    // tangent plane here (a head over the body it rests on, an ear over a head): below the
    // plane it could hide only light below the horizon, which the visibility pass takes in
    // closed form. Not where it merely lies in front of that surface at its texel: a box's top
    // face in front of its steep lit wall striped the wall (random scene rand20: 0.31).
    bool own = u_layered != 0 && texelFetch(u_layer_ids, ivec3(texel, u_layer), 0).r == v_object;
#if SAMPLES
    // The samples hidden here so far: a snapshot, but bits are only ever set, so a patch whose
    // samples are all among them adds nothing (no atomic), and a texel that hides the whole
    // light is done (7 % less splat on rand3001 at 320x240).
    uint have[SSM_SAMPLE_WORDS];
    uint all = ~0u;
    for (int w = 0; w < SSM_SAMPLE_WORDS; ++w) {
        have[w] = imageLoad(u_masks, ivec3(texel, u_layer * SSM_SAMPLE_WORDS + w)).r;
        all &= have[w];
        g_mask[w] = 0u;
    }
    if (all == ~0u) discard;
#endif
    // One call site per way of counting (each is inlined where it is called; a software
    // rasteriser runs every inlined copy for every fragment, lanes masked off or not), and in
    // each class's program only its class's ways.
    const int kMicroPatches = 0, kPlane = 1, kOwnObject = 2, kPatch = 3;
    int how = kPatch;
    if (PATCH_CLASS == SSM_CLASS_PLANE) {
        // A tilted block's plane: its back-projection where every corner lies in front of the
        // receiver by more than its micro-patches may stray from it; else, or on its own
        // object (the tangent-plane test), micro-patch by micro-patch.
        float far = max(max(v_corner_z.x, v_corner_z.y), max(v_corner_z.z, v_corner_z.w));
        how = own || zr - far <= (u_depth_bias + kNearSpans * u_lod_depth) * zr ? kMicroPatches
                                                                                 : kPlane;
    } else if (PATCH_CLASS == SSM_CLASS_FLAT &&
               zr - v_depth_near <=
                   kNearSpans * 2.0 * (v_depth - v_depth_near) + u_depth_bias * zr) {
        // Near a merged patch in depth, within a few of its depth spans, its one depth would
        // misplace the micro-patches' back-projections, or count ones the bias drops: count
        // them one by one (at most lod.comp's largest block).
        how = kMicroPatches;
    } else {
        if (zr - v_depth <= u_depth_bias * zr) discard;
        how = own ? kOwnObject : kPatch;
    }
    if (PATCH_CLASS != SSM_CLASS_MICRO && how == kMicroPatches)
        addMicroPatches(texel, p, own);
#if SAMPLES
    else if (PATCH_CLASS == SSM_CLASS_PLANE && how == kPlane)
        addQuad(p);
#endif
    else if (PATCH_CLASS != SSM_CLASS_PLANE && how == kOwnObject)
        addOwnObject(texel, v_rect * v_depth, v_depth, p);
    else if (PATCH_CLASS != SSM_CLASS_PLANE)
        add(v_rect * v_depth, v_depth, p);
#if SAMPLES
    // The colour writes are masked off: the masks are the output.
    for (int w = 0; w < SSM_SAMPLE_WORDS; ++w)
        if ((g_mask[w] & ~have[w]) != 0u)
            imageAtomicOr(u_masks, ivec3(texel, u_layer * SSM_SAMPLE_WORDS + w), g_mask[w]);
    o_occlusion = vec4(0.0);
#else
    if (g_sum == 0.0) discard;
    o_occlusion = vec4(g_sum, 0.0, 0.0, 0.0);
#endif
}
