// `ssm`'s receiver layers: the receivers seen from the light's centre sorted into LAYERS
// surfaces per texel, in one geometry pass (a k-buffer) or, as a fallback, by depth peeling.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/gpu_scene.h"
#include "renderer/passes/light_depth.h"

namespace penumbra::techniques::ssm {

// LAYERS receiver depth maps of SIZE^2 texels from the light's centre (a DEPTH32F array):
// layer 0 the nearest light-facing receiver surface, layer k the nearest one more than the
// peel gap beyond layer k - 1, and with LAYERS > 1 the last the farthest one beyond the layer
// before it (so the floor under a deep stack of surfaces is always a layer); 1 where a layer
// has none.
struct ReceiverLayers {
    // KBuffer: one pass of the receivers inserts each fragment (depth quantised to 20 bits,
    // object id in the low 12) into its texel's sorted slots, then a resolve per layer walks
    // them (kbuffer_insert.frag, kbuffer_resolve.frag). Peel: one pass per layer
    // (peel.frag): for scenes whose object ids do not fit 12 bits, and for a frame whose
    // slots overflowed (more surfaces within the gap of each other than spare slots).
    enum class Build { KBuffer, Peel };
    // The k-buffer when the scene's OBJECTS ids fit its 12 bits.
    static Build buildFor(std::size_t objects);

    int size, layers;
    Build build;
    gl::Texture depth;  // 2D array, LAYERS layers
    gl::Texture ids;    // 2D array of the surfaces' object ids (R32I, -1 = none)
    ReceiverLayers(int size, int layers, Build build, const char* label);
    ~ReceiverLayers();

    // What render() did: the layers that hold a receiver and the geometry passes it drew.
    struct Result {
        int used = 0, passes = 0;
    };
    // Sorts the objects FILTER selects through VIEW into the layers, each at least GAP
    // (normalised depth) beyond the one before.
    Result render(const passes::GpuScene& scene, passes::GpuScene::Filter filter,
                  const scene::RectLight& light, const passes::LightDepthView& view, float gap);

    // The k-buffer's slots per texel: the nearest fragments the layers but the last are taken
    // from (LAYERS - 1, and spares for surfaces within the gap of a layer), and with
    // LAYERS > 1 the farthest; bytes per texel are 4 times this.
    static int kbufferSlots(int layers);

private:
    struct KBuffer;
    struct Peeling;
    std::unique_ptr<KBuffer> kbuffer_;
    std::unique_ptr<Peeling> peeling_;  // made when first needed
    int peel(const passes::GpuScene& scene, passes::GpuScene::Filter filter,
             const scene::RectLight& light, const passes::LightDepthView& view, float gap);
};

}  // namespace penumbra::techniques::ssm
