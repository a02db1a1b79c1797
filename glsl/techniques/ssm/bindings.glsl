// Binding points of `ssm`'s shaders (texture and image units, buffers) for its GLSL and
// its C++ alike: #defines and // comments only, which both preprocessors read (see
// glsl/common/bindings.glsl); the C++ includes "glsl/techniques/ssm/bindings.glsl".
#ifndef PENUMBRA_SSM_BINDINGS_GLSL
#define PENUMBRA_SSM_BINDINGS_GLSL

// kbuffer_insert.frag and kbuffer_resolve.frag (receiver layers in one pass): a slot holds
// (depth quantised to SSM_KBUFFER_DEPTH_STEPS) << SSM_KBUFFER_ID_BITS | object id, so object ids
// up to SSM_KBUFFER_MAX_OBJECTS - 1 fit beside 0xffffffff, an empty nearest slot
#define SSM_IMAGE_KBUFFER 0
#define SSM_KBUFFER_ID_BITS 12
#define SSM_KBUFFER_DEPTH_STEPS 1048575  // 2^20 - 1: depth 1 is the largest value
#define SSM_KBUFFER_MAX_OBJECTS 4095
// peel.frag (receiver layers, the fallback) and peel_resolve.frag
#define SSM_UNIT_PEEL_PREVIOUS 5  // the layers peeled so far
#define SSM_UNIT_RESOLVE_DEPTH 0
#define SSM_UNIT_RESOLVE_IDS 1
// occluder_peel.frag (far_side=second)
#define SSM_UNIT_OCC_PEEL_FRONT 5
// receiver_max.comp
#define SSM_UNIT_RECEIVER_MAX_SOURCE 0
#define SSM_UNIT_RECEIVER_MAX_LAYERS 1
#define SSM_IMAGE_RECEIVER_MAX_TARGET 0
// receiver_planes.comp
#define SSM_UNIT_PLANES_LAYERS 0
#define SSM_IMAGE_PLANES_TARGET 0
// compact.comp
#define SSM_UNIT_COMPACT_OCCLUDER 0
#define SSM_UNIT_COMPACT_SLOPES 1  // with `lod`: lod.comp's plane slopes
// lod.comp
#define SSM_UNIT_LOD_DEPTH 0
#define SSM_UNIT_LOD_IDS 1
#define SSM_UNIT_LOD_PYRAMID 2
#define SSM_IMAGE_LOD_LEVEL 0
#define SSM_IMAGE_LOD_PATCHES 1
#define SSM_IMAGE_LOD_SLOPES 2
// splat.vert and splat.frag
#define SSM_UNIT_SPLAT_RECEIVER 1
#define SSM_UNIT_SPLAT_RECEIVER_MAX 2
#define SSM_UNIT_SPLAT_OCC_IDS 6
#define SSM_UNIT_SPLAT_LAYER_IDS 8
#define SSM_UNIT_SPLAT_PLANES 9
#define SSM_UNIT_SPLAT_OCC_DEPTH 10  // the side's linear occluder depth (merged patches)
#define SSM_IMAGE_SPLAT_MASKS 0      // accumulate=samples: the light-sample masks
#define SSM_SAMPLE_WORDS 8           // their 32-bit words per texel (ssm.h kSampleWords)
// splat_done.frag (the splat's stencil of finished texels)
#define SSM_UNIT_DONE_RECEIVER 1
#define SSM_IMAGE_DONE_MASKS 0
// samples_resolve.comp
#define SSM_IMAGE_RESOLVE_MASKS 0
#define SSM_IMAGE_RESOLVE_TARGET 1
// visibility.frag
#define SSM_UNIT_VISIBILITY_POSITION 0
#define SSM_UNIT_VISIBILITY_ID 1
#define SSM_UNIT_VISIBILITY_RECEIVES 2
#define SSM_UNIT_VISIBILITY_SSM 3
#define SSM_UNIT_VISIBILITY_SSM_BACK 4
#define SSM_UNIT_VISIBILITY_LAYERS 5
#define SSM_UNIT_VISIBILITY_LAYER_IDS 6  // the object id per layer texel
// A micro-patch's texel index holds its lod level from this bit (micro_patches.h kLevelShift)
#define SSM_LEVEL_SHIFT 24
// The splat's patch classes, each drawn by its own program (PATCH_CLASS) from its own range of
// the list (micro_patches.h PatchClass): a software rasteriser runs every branch a shader has
// for every fragment, so each program holds only its class's ways of counting
#define SSM_CLASS_MICRO 0  // an unmerged micro-patch
#define SSM_CLASS_FLAT 1   // a merged block at one depth (lod.comp)
#define SSM_CLASS_PLANE 2  // a merged block on a tilted plane (lod.comp, accumulate=samples)
#define SSM_CLASSES 3
// Buffers
#define SSM_BINDING_COUNTERS 3      // splat.vert's Counters
#define SSM_BINDING_PATCHES 4       // splat.vert's and compact.comp's Patches
#define SSM_BINDING_COMMAND 5       // the splat's draw command per class (compact.comp, splat.vert)
#define SSM_BINDING_RUNS 6          // compact.comp's Runs (path gpu)
#define SSM_BINDING_LAYER_COUNTS 7  // kbuffer_resolve.frag's LayerCounts

#endif
