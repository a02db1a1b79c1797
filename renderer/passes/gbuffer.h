// The G-buffer pass shared by every technique: world position, normal (+ view depth), linear
// albedo and object id per pixel, rendered once per frame from the camera.
#pragma once

#include <glm/glm.hpp>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/gpu_scene.h"

namespace penumbra::passes {

struct CameraMatrices {
    glm::mat4 view{1.0f}, projection{1.0f};
    glm::vec3 position{0.0f};
};

CameraMatrices cameraMatrices(const scene::Camera& camera, int width, int height);

// The G-buffer programs (glsl/passes/gbuffer.*): for untextured materials and, sampling the
// base colour texture, for textured ones.
struct GBufferPrograms {
    gl::Program plain, textured;
};
GBufferPrograms buildGBufferPrograms();

// Clears FBO (colour 0-4: position, normal, albedo, id, geometric normal; and depth) and draws
// SCENE into it with PROGRAMS through VIEW and PROJECTION: the G-buffer passes' one draw.
void drawGBuffer(GLuint fbo, int width, int height, const GBufferPrograms& programs,
                 const GpuScene& scene, const glm::mat4& view, const glm::mat4& projection);

class GBuffer {
public:
    GBuffer(int width, int height);
    void render(const GpuScene& scene, const CameraMatrices& camera);

    int width() const { return width_; }
    int height() const { return height_; }
    const gl::Texture& position() const { return position_; }  // RGBA32F: xyz, w = coverage
    const gl::Texture& normal() const { return normal_; }      // RGBA32F: xyz, w = view depth
    const gl::Texture& albedo() const { return albedo_; }      // RGBA16F linear
    const gl::Texture& id() const { return id_; }              // R32I, -1 = none
    // RGBA16F: xyz, the drawn triangle's normal (the horizon rule's plane, as exact's rays see it)
    const gl::Texture& geometricNormal() const { return geometric_normal_; }
    // Binds geometricNormal() to its unit (common/geometric_normal.glsl) for the next draws.
    void bindGeometricNormal() const;
    const gl::Texture& depth() const { return depth_; }  // DEPTH32F (hardware depth)

private:
    int width_, height_;
    gl::Texture position_, normal_, albedo_, id_, geometric_normal_, depth_;
    gl::Framebuffer fbo_;
    GBufferPrograms programs_;
};

}  // namespace penumbra::passes
