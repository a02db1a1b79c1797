// `css` visibility (include-only; Annen et al. 2008, Figure 5) of one receiver, from the
// prefiltered basis images of basis.comp (mipmaps, or summed-area tables when FILTER_SAT):
//  1. the initial kernel: the cone from the receiver to the light cut by the near plane;
//  2. z_avg = filter(fbar z) / filter(fbar) from the CSM-Z and CSM basis over that kernel;
//  3. the final kernel D (d - z_avg) / (d z_avg) (PCSS), and the filtered complementary test
//     there, with ringing suppression (scale about 1/2, shift, clamp; the plateau divided
//     out) and contact sharpening v^p, p = 1 + A exp(-B (d - z_avg)).
// A receiver that casts is in the map itself: each kernel tests it nearer the light by the drop
// of its own tangent plane over part of the kernel (planeDrop), so it is not its own blocker.
// The entry points: visibility.frag (every pixel), visibility_coarse.frag and
// visibility_fine.frag (every other pixel, then interpolation where that is safe).
#ifndef PENUMBRA_CSS_VISIBILITY_GLSL
#define PENUMBRA_CSS_VISIBILITY_GLSL
#include "techniques/css/bindings.glsl"
#ifndef FILTER_SAT
#define FILTER_SAT 0
#endif
#ifndef MAX_ANISO
#define MAX_ANISO 8
#endif
#ifndef MIP_TAPS
#define MIP_TAPS 2
#endif
#ifndef SEARCH_TAPS
#define SEARCH_TAPS 1  // mipmap taps per side in the blocker searches: an average needs less
#endif
#ifndef SEARCH_STEPS
#define SEARCH_STEPS 0
#endif
#include "common/caster_flags.glsl"
#include "common/geometric_normal.glsl"
#include "common/light_horizon.glsl"
#include "techniques/css/basis_layout.glsl"

layout(binding = CSS_UNIT_VISIBILITY_POSITION) uniform sampler2D u_position;
// Mipmapped basis, or its (N+1)^2 SAT
layout(binding = CSS_UNIT_VISIBILITY_BASIS) uniform sampler2DArray u_basis;
// u_basis, bilinear in one level
layout(binding = CSS_UNIT_VISIBILITY_BASIS_SEARCH) uniform sampler2DArray u_basis_search;
// The G-buffer's object ids
layout(binding = CSS_UNIT_VISIBILITY_ID) uniform isampler2D u_id;

#include "common/light_frame.glsl"
uniform vec2 u_light_size;  // D along right and up
uniform vec2 u_window_lo;   // the map's window at distance 1 in the light's frame
uniform vec2 u_window_size;
uniform float u_near;        // the nearest caster's distance: the filter widths' near plane
uniform float u_depth_near;  // distances of normalised depth 0 and 1 (csm_maps.h DepthRange)
uniform float u_depth_far;
uniform float u_receiver_max;  // receivers past it (normalised) are tested at it: csm_maps.h
uniform float u_map_size;    // N
uniform float u_ring_scale;  // ringing suppression: s = clamp(scale (F - 1/2) + 1/2, 0, 1)
uniform float u_ring_shift;  // the test is evaluated at d - shift
uniform float u_ring_plateau;  // the umbra's plateau correction starts this far in front (0: off)
uniform float u_sharpen_a;   // contact sharpening v^p, p = 1 + A exp(-B (d - z_avg))
uniform float u_sharpen_b;
uniform float u_self_exclude;  // share of a kernel's half-width for the receiver's own plane
layout(std430, binding = CSS_BINDING_OBJECT_NEAREST) readonly buffer ObjectNearest {
    float u_object_nearest[];  // per object id: its bounds' nearest normalised depth
};

// A box kernel centred at C with size S (both in texels of the N x N map), prepared once and
// applied to each basis layer. SEARCH marks the blocker searches' kernels: with mipmaps they
// read through u_basis_search (bilinear in the nearest level, half the texels of trilinear
// filtering); the final test keeps trilinear filtering.
#if FILTER_SAT
struct Kernel {
    vec2 lo, hi;  // the box clipped to the map, in SAT texture coordinates
    float inv_area;
};
Kernel makeKernel(vec2 c, vec2 s, int taps_per_side, bool search) {
    // Outside the map every (centred) basis value is 0: clip the box, divide by its full area.
    float n1 = u_map_size + 1.0;
    Kernel k;
    k.lo = (clamp(c - 0.5 * s, 0.0, u_map_size) + 0.5) / n1;
    k.hi = (clamp(c + 0.5 * s, 0.0, u_map_size) + 0.5) / n1;
    k.inv_area = 1.0 / (s.x * s.y);
    return k;
}
// The table holds G at integer corners (row and column 0 are zero); bilinear filtering of it
// at a fractional corner is the exact integral of the piecewise-constant image.
vec4 boxMean(Kernel k, int layer) {
    vec4 sum = texture(u_basis, vec3(k.hi, layer)) - texture(u_basis, vec3(k.lo.x, k.hi.y, layer)) -
               texture(u_basis, vec3(k.hi.x, k.lo.y, layer)) + texture(u_basis, vec3(k.lo, layer));
    return sum * k.inv_area;
}
#else
struct Kernel {
    vec2 first, step;  // a grid of taps, in texture coordinates
    ivec2 taps;
    float lod;
    bool search;  // a blocker search: through u_basis_search
};
Kernel makeKernel(vec2 c, vec2 s, int taps_per_side, bool search) {
    // TAPS x TAPS trilinear taps per square of the shorter side (a rectangle gets more along
    // its longer axis, at most MAX_ANISO times more: anisotropic filtering), each at GL's level
    // for its footprint, log2(width): a grid of taps follows a box kernel more closely than one
    // coarse lookup, whose bilinear tent is twice the box's width.
    float tap = max(min(s.x, s.y) / float(taps_per_side), 1.0);
    Kernel k;
    k.taps = clamp(ivec2(ceil(s / tap - 0.01)), ivec2(1), ivec2(taps_per_side * MAX_ANISO));
    vec2 footprint = s / vec2(k.taps);
    k.lod = max(log2(max(footprint.x, footprint.y)), 0.0);
    k.step = footprint / u_map_size;
    k.first = (c - 0.5 * s + 0.5 * footprint) / u_map_size;
    k.search = search;
    return k;
}
vec4 boxMean(Kernel k, int layer) {
    vec4 sum = vec4(0.0);
    for (int y = 0; y < k.taps.y; ++y)
        for (int x = 0; x < k.taps.x; ++x)
            sum +=
                k.search
                    ? textureLod(u_basis_search, vec3(k.first + vec2(x, y) * k.step, layer), k.lod)
                    : textureLod(u_basis, vec3(k.first + vec2(x, y) * k.step, layer), k.lod);
    return sum / float(k.taps.x * k.taps.y);
}
#endif

// (sin, cos)(c_k ds) / c_k for k = 2i+1, 2i+2: the weights of basis layer pair I.
vec4 cssWeights(int i, float ds) {
    float c1 = cssCoefficient(2 * i + 1), c2 = cssCoefficient(2 * i + 2);
    vec4 w = vec4(sin(c1 * ds) / c1, cos(c1 * ds) / c1, sin(c2 * ds) / c2, cos(c2 * ds) / c2);
    return 2 * i + 2 > ORDER ? vec4(w.xy, 0.0, 0.0) : w;
}

// The filtered complementary test fbar (1 = blocked) over kernel K, given the series weights
// W of the shifted receiver depth (cssWeights; seriesAt) and
// EMPTY = fbar(ds, 1), the test of an empty texel; and, when WITH_Z, the filtered fbar z
// (CSM-Z). The basis is stored minus its empty-texel value, so the series sums give
// sum_i w_i (fbar(d, z_i) - EMPTY) over the kernel; adding EMPTY back for the covered texels
// only (coverage from the z layer) gives the sum over casters alone. An empty texel never
// blocks, so it adds exactly 0 instead of the truncated series' ringing, which would swamp a
// thin caster in a wide kernel. Z_COVERAGE is the kernel's mean of the z layer ((z - 1),
// coverage, zm - z), when the caller has it already (the first search's early-out). Returns
// (fbar, fbar zm, the mean of zm - z over the kernel's casters): with blocker_depth middle the
// CSM-Z basis weights by zm, and its constant term is 1/2 zm as well.
vec3 filteredTestWith(Kernel k, vec4 w[CSS_PAIRS], float empty, bool with_z, vec4 z_coverage) {
    float f = 0.0, fz = 0.0;
    for (int i = 0; i < CSS_PAIRS; ++i) {
        vec4 b = boxMean(k, i);  // cos, sin, cos, sin
        f += 2.0 * (w[i].x * b.x - w[i].y * b.y + w[i].z * b.z - w[i].w * b.w);
        if (with_z) {
            vec4 bz = boxMean(k, CSS_PAIRS + i);
            fz += 2.0 * (w[i].x * bz.x - w[i].y * bz.y + w[i].z * bz.z - w[i].w * bz.w);
        }
    }
    f += z_coverage.y * empty;
    fz += 0.5 * (z_coverage.x + z_coverage.z) + z_coverage.y * empty;
    return vec3(f, fz, z_coverage.z / max(z_coverage.y, 1e-6));
}
vec3 filteredTest(Kernel k, vec4 w[CSS_PAIRS], float empty, bool with_z) {
    return filteredTestWith(k, w, empty, with_z, boxMean(k, 2 * CSS_PAIRS));
}

// The series weights of the shifted receiver depth DS (cssWeights per layer pair) and the test
// of an empty texel, fbar(ds, 1) = 1/2 + 2 sum_k sin(c_k (ds - 1)) / c_k
// = 1/2 - 2 sum_k sin(c_k ds) / c_k (sin(c_k (x - 1)) = -sin(c_k x) for odd multiples of pi).
void seriesAt(float ds, out vec4 w[CSS_PAIRS], out float empty) {
    empty = 0.5;
    for (int i = 0; i < CSS_PAIRS; ++i) {
        w[i] = cssWeights(i, ds);
        empty -= 2.0 * (w[i].x + w[i].z);
    }
}

// The truncated series' test of one caster X in front of the test depth (normalised depth):
// 1/2 + 2 sum_k sin(c_k x) / c_k. Past its ramp it ripples about 1 (Gibbs): with M = 4,
// 0.946-1.074 for x in [0.1, 0.9] and 0.961 at 1/2, so a plain umbra read 0.04 too light.
float seriesStep(float x) {
    float f = 0.5;
    for (int k = 1; k <= ORDER; ++k) {
        float ck = cssCoefficient(k);
        f += 2.0 * sin(ck * x) / ck;
    }
    return f;
}

// The final test F of a kernel whose casters' mean (nearest) depth lies X in front of the test
// depth, with the series' plateau divided out: F = coverage x seriesStep(x) where the casters
// lie near one depth (an umbra, a caster's own penumbra), so F / seriesStep(x) is the blocked
// share. Only past u_ring_plateau (fully from twice it), where the series is on its plateau;
// nearer, the ramp is the ring shift's and the contact sharpening's.
float plateauCorrected(float f, float x) {
    if (u_ring_plateau <= 0.0) return f;
    return f / mix(1.0, seriesStep(x), smoothstep(u_ring_plateau, 2.0 * u_ring_plateau, x));
}

// The receiver's own surface in the map (an object that casts): how far its tangent plane
// comes nearer the light than the receiver anywhere under a kernel of half-size H (tangent
// units) centred at direction U (tangent units), in normalised depth. The plane through the
// receiver (light-frame offset L, normal N) meets the ray (u, v, 1) at depth
// (N.L) / (N.(u, v, 1)), a linear-fractional function whose minimum over a box lies at a
// corner; a plane seen edge-on inside the kernel reaches the light, so it can come as near as
// depth 0. Every texel of the kernel is tested against the receiver's depth less this drop,
// so the receiver (and a convex object around it) does not count as its own blocker: what it
// hides of the light is the horizon rule's share, counted once.
float planeDrop(vec3 l, vec3 n, vec2 u, vec2 h) {
    // Over the box, sign(k) N.(u, v, 1) spans centre +- spread; the nearest depth is |k| over
    // its largest value, unless its smallest is not positive (the plane seen edge-on).
    float k = dot(n, l), centre = dot(n, vec3(u, 1.0)) * sign(k);
    float spread = dot(abs(n.xy), h);
    float nearest = centre - spread > 0.0 ? abs(k) / (centre + spread) : 0.0;
    return (l.z - nearest) / (u_depth_far - u_depth_near);
}

// The fraction of the light above the tangent plane of receiver P (normal N): the part below
// is hidden by the receiver's own surface, as every light-sample shadow map sees it for a
// closed object that casts (common/light_horizon.glsl). Objects that cast no shadow do not
// hide the light from themselves (main() takes 1 for them).
float aboveHorizon(vec3 p, vec3 n) {
    return centredLightShareAboveHorizon(u_light_centre, u_light_right, u_light_up, u_light_size, p,
                                         n);
}

// A camera pixel's surface: world position, object id, whether it casts, its geometric normal
// (for one that casts) and the share of the light above its tangent plane (1 for one that does
// not cast).
struct Receiver {
    vec3 pos, normal;
    int id;
    bool casts;
    float horizon;
};

// The receiver at PIX; false where the pixel holds no surface.
bool receiverAt(ivec2 pix, out Receiver r) {
    vec4 pos = texelFetch(u_position, pix, 0);
    if (pos.w == 0.0) return false;
    r.pos = pos.xyz;
    r.id = texelFetch(u_id, pix, 0).r;
    r.casts = objectCasts(r.id);
    r.normal = r.casts ? geometricNormal(pix) : vec3(0.0);
    r.horizon = r.casts ? aboveHorizon(r.pos, r.normal) : 1.0;
    return true;
}

// The map texel (N x N map, fractional) that world point P projects to from the light's centre.
vec2 mapTexel(vec3 p) {
    vec3 dl = p - u_light_centre;
    vec2 u = vec2(dot(dl, u_light_right), dot(dl, u_light_up)) / dot(dl, u_light_forward);
    return (u - u_window_lo) * (u_map_size / u_window_size);
}

// Receiver R in the light's frame (L: offset from the light's centre along right, up and
// forward), its direction U = L.xy / L.z and its map texel C; false where it is no farther
// than the nearest caster (nothing can block it).
bool inLightFrame(Receiver r, out vec3 l, out vec2 u, out vec2 c) {
    vec3 dl = r.pos - u_light_centre;
    l = vec3(dot(dl, u_light_right), dot(dl, u_light_up), dot(dl, u_light_forward));
    u = l.xy / l.z;
    c = (u - u_window_lo) * (u_map_size / u_window_size);
    return l.z > u_near;
}

// Stage 1's search kernel (in texels) of a receiver at distance ZW along the light's axis: the
// cone to the light where it crosses the near plane.
vec2 firstSearchSize(float zw) {
    return max(u_light_size * (zw - u_near) / (zw * u_near) * (u_map_size / u_window_size),
               vec2(1.0));
}

// Whether receiver R (whose horizon is above 0) has a caster under its first search kernel:
// where it has none, cssShadow() returns (1, 0, 0) (visibility_cover.frag marks the others).
bool hasCasterInSearch(Receiver r) {
    vec3 l;
    vec2 u, c;
    if (!inLightFrame(r, l, u, c)) return false;
    return boxMean(makeKernel(c, firstSearchSize(l.z), SEARCH_TAPS, true), 2 * CSS_PAIRS).y >
           1e-6;
}

// The shadow of receiver R (whose horizon is above 0): (S, z_avg, the final kernel's width in
// texels along its wider axis), visibility = horizon S; (1, 0, 0) where no blocker is found.
vec3 cssShadow(Receiver r) {
    vec3 l;
    vec2 u, c;
    if (!inLightFrame(r, l, u, c)) return vec3(1.0, 0.0, 0.0);  // nearer than every caster
    float zw = l.z;
    vec3 nl = vec3(dot(r.normal, u_light_right), dot(r.normal, u_light_up),
                   dot(r.normal, u_light_forward));
    vec2 texels_per_tan = u_map_size / u_window_size;
    // The receiver's normalised depth (DR: unclamped, for the contact sharpening's distance).
    float dr = (zw - u_depth_near) / (u_depth_far - u_depth_near);
    float d = min(dr, u_receiver_max);
    float ds = max(d - u_ring_shift, 0.0);
    // The test depth under a kernel of S texels: ds, less the drop of the receiver's own
    // plane over u_self_exclude of the kernel's half-width when the receiver is in the map,
    // but no nearer than its object comes to the light: its own surface lies behind both. A
    // plane seen edge-on in a wide kernel drops to depth 0, which would hide every blocker
    // from a face nearly edge-on to the light (a tilted box's face under a sphere it touches).
    bool exclude = r.casts && u_self_exclude > 0.0;
    vec2 half_tan = 0.5 * u_self_exclude / texels_per_tan;
    // (less the ring shift, as the receiver's own depth: the reconstructed step is smooth).
    float own = r.id < u_object_nearest.length()
                    ? clamp(u_object_nearest[r.id] - u_ring_shift, 0.0, ds) : 0.0;
#define TEST_DEPTH(S) (exclude ? max(ds - planeDrop(l, nl, u, half_tan * (S)), own) : ds)

    // Stage 1: the search kernel where the cone to the light crosses the near plane.
    vec2 w0 = firstSearchSize(zw);
    Kernel k0 = makeKernel(c, w0, SEARCH_TAPS, true);
    // No caster under the search kernel: nothing can block (empty texels add exactly 0).
    vec4 z_coverage = boxMean(k0, 2 * CSS_PAIRS);
    if (z_coverage.y <= 1e-6) return vec3(1.0, 0.0, 0.0);

    // The searches share the widest kernel's test depth (its drop is the largest).
    vec4 w[CSS_PAIRS];
    float empty;
    seriesAt(TEST_DEPTH(w0), w, empty);
    vec3 search = filteredTestWith(k0, w, empty, true, z_coverage);
    if (search.x < 1e-3) return vec3(1.0, 0.0, 0.0);  // no blocker in the search area
    // Stage 2: the average blocker depth; SEARCH_STEPS times more, the search kernel is the
    // cone cut at the plane of the current z_avg instead of the near plane (the paper's
    // suggested iteration, section 3.2), which drops blockers outside the receiver's cone.
    // A receiver that casts takes its blockers' nearest surfaces (the kernel's mean zm - z
    // less). Measured on the corpus, not derived: better where such receivers take other
    // casters' shadows (both_everywhere's floor, curved_receiver), worse on a duck's head over
    // its body; restricted to receivers facing away from the light it changed nothing.
    float z_avg = clamp(search.y / search.x - (r.casts ? search.z : 0.0), 0.0, d);
    float zb = max(u_depth_near + z_avg * (u_depth_far - u_depth_near), u_near);
    for (int i = 0; i < SEARCH_STEPS; ++i) {
        vec2 ws = max(u_light_size * (zw - zb) / (zw * zb) * texels_per_tan, vec2(1.0));
        vec3 refined = filteredTest(makeKernel(c, ws, SEARCH_TAPS, true), w, empty, true);
        if (refined.x < 1e-3) break;  // keep the last estimate
        z_avg = clamp(refined.y / refined.x - (r.casts ? refined.z : 0.0), 0.0, d);
        zb = max(u_depth_near + z_avg * (u_depth_far - u_depth_near), u_near);
    }
    // Stage 3: the final kernel and the filtered test.
    // Widened by the ringing scale: the scaled test ramps over 1 / scale of the kernel, so a
    // kernel scale times wider keeps the penumbra's width (exact at a straight shadow edge).
    vec2 w1 = max(u_ring_scale * u_light_size * (zw - zb) / (zw * zb) * texels_per_tan, vec2(1.0));
    float ds1 = TEST_DEPTH(w1);
    if (exclude) seriesAt(ds1, w, empty);
    Kernel k1 = makeKernel(c, w1, MIP_TAPS, false);
    vec4 z_coverage1 = boxMean(k1, 2 * CSS_PAIRS);
    float f = filteredTestWith(k1, w, empty, false, z_coverage1).x;
    if (z_coverage1.y > 1e-6) f = plateauCorrected(f, ds1 - 1.0 - z_coverage1.x / z_coverage1.y);
    float s = clamp(u_ring_scale * (f - 0.5) + 0.5, 0.0, 1.0);
    float p = 1.0 + u_sharpen_a * exp(-u_sharpen_b * (dr - z_avg));
    return vec3(pow(1.0 - s, p), z_avg, max(w1.x, w1.y));
}

#endif  // PENUMBRA_CSS_VISIBILITY_GLSL
