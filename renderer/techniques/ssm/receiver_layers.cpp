// `ssm`'s receiver layers: see receiver_layers.h.
#include "renderer/techniques/ssm/receiver_layers.h"
#include "glsl/techniques/ssm/bindings.glsl"

#include <algorithm>
#include <array>
#include <cstdint>

namespace penumbra::techniques::ssm {
namespace {

// Nearest slots beyond the LAYERS - 1 that the layers need: room for fragments within the gap
// of a layer (a surface meeting another, overlapping parts of a mesh) before one is lost. A
// texel that fills them all before its layers are found sends the frame to the peeling.
constexpr int kSpareSlots = 3;

// The nearest slots: one for LAYERS <= 2 (the nearest fragment is layer 0 exactly).
int nearestSlots(int layers) {
    return layers <= 2 ? 1 : layers - 1 + kSpareSlots;
}

}  // namespace

// The one-pass build: the slots (r32ui array) and the per-layer resolve targets.
struct ReceiverLayers::KBuffer {
    int nearest;
    gl::Texture slots;
    passes::LightDepthPass insert_pass{"ssm receiver k-buffer",
                                       "techniques/ssm/kbuffer_insert.frag"};
    gl::Program resolve_program =
        gl::buildProgram("ssm receiver layers from the k-buffer",
                         {"passes/fullscreen.vert", "techniques/ssm/kbuffer_resolve.frag"});
    gl::Framebuffer insert_fbo;               // no attachments: the fragments write images only
    std::vector<gl::Framebuffer> layer_fbos;  // depth and ids of one layer each
    gl::Buffer counts = gl::createBuffer("ssm receiver layer counts");
    passes::Fullscreen fullscreen;

    KBuffer(const ReceiverLayers& r, const char* label)
        : nearest(nearestSlots(r.layers)),
          slots(gl::createTexture2DArray(GL_R32UI, r.size, r.size, kbufferSlots(r.layers), label)),
          insert_fbo(gl::createFramebuffer(label)) {
        glNamedFramebufferParameteri(insert_fbo.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, r.size);
        glNamedFramebufferParameteri(insert_fbo.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, r.size);
        passes::checkFramebuffer(insert_fbo, label);
        for (int k = 0; k < r.layers; ++k) {
            layer_fbos.push_back(gl::createFramebuffer(label));
            const GLuint fbo = layer_fbos.back().id();
            glNamedFramebufferTextureLayer(fbo, GL_DEPTH_ATTACHMENT, r.depth.id(), 0, k);
            glNamedFramebufferTextureLayer(fbo, GL_COLOR_ATTACHMENT0, r.ids.id(), 0, k);
            glNamedFramebufferDrawBuffer(fbo, GL_COLOR_ATTACHMENT0);
            passes::checkFramebuffer(layer_fbos.back(), label);
        }
        glNamedBufferStorage(counts.id(), 2 * sizeof(std::uint32_t), nullptr,
                             GL_DYNAMIC_STORAGE_BIT);
    }

    // Clears the slots and inserts every light-facing fragment (no depth test). The last
    // resolve that read the slots has finished: its counts were read back.
    void insert(const passes::GpuScene& scene, passes::GpuScene::Filter filter,
                const scene::RectLight& light, const passes::LightDepthView& view,
                const ReceiverLayers& r) const {
        const std::uint32_t empty = 0xffffffffu, none = 0;
        glClearTexSubImage(slots.id(), 0, 0, 0, 0, r.size, r.size, nearest, GL_RED_INTEGER,
                           GL_UNSIGNED_INT, &empty);
        if (r.layers > 1)
            glClearTexSubImage(slots.id(), 0, 0, 0, nearest, r.size, r.size, 1, GL_RED_INTEGER,
                               GL_UNSIGNED_INT, &none);
        glBindFramebuffer(GL_FRAMEBUFFER, insert_fbo.id());
        glViewport(0, 0, r.size, r.size);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glBindImageTexture(SSM_IMAGE_KBUFFER, slots.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
        const gl::Program& program = insert_pass.program();
        glUseProgram(program.id());
        gl::setUniform(program, "u_nearest_slots", nearest);
        gl::setUniform(program, "u_farthest", r.layers > 1 ? 1 : 0);
        insert_pass.draw(scene, filter, light, view);
        // The resolve reads the slots with image loads.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }

    // Writes R's layers from the slots, one full-screen draw each (depth by an ALWAYS test);
    // returns the most layers a texel holds and the texels whose slots overflowed.
    std::array<std::uint32_t, 2> resolve(const ReceiverLayers& r, float gap) const {
        const std::uint32_t zero[2] = {0, 0};
        glNamedBufferSubData(counts.id(), 0, sizeof(zero), zero);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);
        glDepthMask(GL_TRUE);
        glUseProgram(resolve_program.id());
        gl::setUniform(resolve_program, "u_layers", r.layers);
        gl::setUniform(resolve_program, "u_nearest_slots", nearest);
        gl::setUniform(resolve_program, "u_peel_gap", gap);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_BINDING_LAYER_COUNTS, counts.id());
        for (int k = 0; k < r.layers; ++k) {
            glBindFramebuffer(GL_FRAMEBUFFER, layer_fbos[size_t(k)].id());
            gl::setUniform(resolve_program, "u_layer", k);
            fullscreen.draw();
        }
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);
        glUseProgram(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // the counts' atomics, then the read
        std::array<std::uint32_t, 2> counts_read{};
        glGetNamedBufferSubData(counts.id(), 0, sizeof(counts_read), counts_read.data());
        return counts_read;
    }
};

// The peeling: a scratch map per layer, the farthest layer's resolve and target.
struct ReceiverLayers::Peeling {
    passes::LightDepthPass pass{"ssm receiver layers", "techniques/ssm/peel.frag"};
    passes::LightDepthTarget scratch;
    gl::Program resolve =
        gl::buildProgram("ssm farthest receiver layer",
                         {"passes/fullscreen.vert", "techniques/ssm/peel_resolve.frag"});
    gl::Framebuffer last_fbo;  // the array's last layer as a depth target
    passes::Fullscreen fullscreen;

    Peeling(const ReceiverLayers& r, const char* label)
        : scratch(r.size, label, true), last_fbo(gl::createFramebuffer(label)) {
        glNamedFramebufferTextureLayer(last_fbo.id(), GL_DEPTH_ATTACHMENT, r.depth.id(), 0,
                                       r.layers - 1);
        glNamedFramebufferDrawBuffer(last_fbo.id(), GL_NONE);
        passes::checkFramebuffer(last_fbo, label);
    }
};

ReceiverLayers::Build ReceiverLayers::buildFor(std::size_t objects) {
    return objects <= SSM_KBUFFER_MAX_OBJECTS ? Build::KBuffer : Build::Peel;
}

int ReceiverLayers::kbufferSlots(int layers) {
    return nearestSlots(layers) + (layers > 1 ? 1 : 0);
}

ReceiverLayers::ReceiverLayers(int size_, int layers_, Build build_, const char* label)
    : size(size_),
      layers(layers_),
      build(build_),
      depth(gl::createTexture2DArray(GL_DEPTH_COMPONENT32F, size_, size_, layers_, label)),
      ids(gl::createTexture2DArray(GL_R32I, size_, size_, layers_, label)) {
    if (build == Build::KBuffer)
        kbuffer_ = std::make_unique<KBuffer>(*this, label);
    else
        peeling_ = std::make_unique<Peeling>(*this, label);
}

ReceiverLayers::~ReceiverLayers() = default;

ReceiverLayers::Result ReceiverLayers::render(const passes::GpuScene& scene,
                                              passes::GpuScene::Filter filter,
                                              const scene::RectLight& light,
                                              const passes::LightDepthView& view, float gap) {
    if (build == Build::Peel) {
        const int used = peel(scene, filter, light, view, gap);
        return {used, std::min(used + 1, layers)};
    }
    kbuffer_->insert(scene, filter, light, view, *this);
    const auto [used, overflowed] = kbuffer_->resolve(*this, gap);
    if (overflowed == 0) return {int(used), 1};
    const int peeled = peel(scene, filter, light, view, gap);
    return {peeled, 1 + std::min(peeled + 1, layers)};
}

int ReceiverLayers::peel(const passes::GpuScene& scene, passes::GpuScene::Filter filter,
                         const scene::RectLight& light, const passes::LightDepthView& view,
                         float gap) {
    if (!peeling_) peeling_ = std::make_unique<Peeling>(*this, "ssm receiver layers (peeled)");
    Peeling& p = *peeling_;
    const gl::Program& program = p.pass.program();
    glUseProgram(program.id());
    gl::setUniform(program, "u_peel_gap", gap);
    // Each layer is drawn into the scratch map, reading the layer before from the array, and
    // then copied into the array: a layer is never sampled while it is drawn.
    glBindTextureUnit(SSM_UNIT_PEEL_PREVIOUS, depth.id());
    const gl::Query any = gl::createQuery(GL_ANY_SAMPLES_PASSED, "ssm receiver layer");
    int used = 0;
    for (int k = 0; k < layers; ++k) {
        glUseProgram(program.id());
        gl::setUniform(program, "u_layer", k);
        const bool farthest = k > 0 && k == layers - 1;
        glBeginQuery(GL_ANY_SAMPLES_PASSED, any.id());
        p.scratch.render(scene, p.pass, filter, light, view, farthest);
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        if (farthest) {
            // Cleared to 0 for the greater test: written with 1 for "none" instead.
            glBindFramebuffer(GL_FRAMEBUFFER, p.last_fbo.id());
            glViewport(0, 0, size, size);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_ALWAYS);
            glDepthMask(GL_TRUE);
            glUseProgram(p.resolve.id());
            glBindTextureUnit(SSM_UNIT_RESOLVE_DEPTH, p.scratch.depth.id());
            glBindTextureUnit(SSM_UNIT_RESOLVE_IDS, p.scratch.ids.id());
            p.fullscreen.draw();
            glDepthFunc(GL_LESS);
            glDisable(GL_DEPTH_TEST);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glBindTextureUnit(SSM_UNIT_PEEL_PREVIOUS, depth.id());
        } else {
            glCopyImageSubData(p.scratch.depth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, depth.id(),
                               GL_TEXTURE_2D_ARRAY, 0, 0, 0, k, size, size, 1);
        }
        glCopyImageSubData(p.scratch.ids.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ids.id(),
                           GL_TEXTURE_2D_ARRAY, 0, 0, 0, k, size, size, 1);
        GLuint passed = 0;
        glGetQueryObjectuiv(any.id(), GL_QUERY_RESULT, &passed);
        if (!passed) {
            // Empty from here on: the deeper layers keep "none" (1) for the lookups.
            const float none = 1.0f;
            const GLint no_id = -1;
            if (k + 1 < layers) {
                glClearTexSubImage(depth.id(), 0, 0, 0, k + 1, size, size, layers - k - 1,
                                   GL_DEPTH_COMPONENT, GL_FLOAT, &none);
                glClearTexSubImage(ids.id(), 0, 0, 0, k + 1, size, size, layers - k - 1,
                                   GL_RED_INTEGER, GL_INT, &no_id);
            }
            break;
        }
        used = k + 1;
    }
    return used;
}

}  // namespace penumbra::techniques::ssm
