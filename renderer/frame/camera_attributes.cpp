// OpenEXR camera attributes: see camera_attributes.h. GL's view and projection (column vectors,
// camera looking down -z) are turned into Imath's row-vector matrices.
#include "renderer/frame/camera_attributes.h"

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/passes/gbuffer.h"

namespace penumbra::frame {

namespace {

// Imath's M[i][j] (p' = p M) is GLM's m[i][j] (column i, row j; p' = m p): the same numbers.
std::array<float, 16> imathOrder(const glm::mat4& m) {
    std::array<float, 16> r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[static_cast<size_t>(4 * i + j)] = m[i][j];
    return r;
}

}  // namespace

void addCameraAttributes(output::Image& image, const scene::Camera& camera, int width, int height) {
    const passes::CameraMatrices m = passes::cameraMatrices(camera, width, height);
    // GL's eye space looks down -z; OpenEXR's camera space (RenderMan's) looks down +z.
    const glm::mat4 flipZ = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 1.0f, -1.0f));
    // Clip space to NDC before the divide by w: x' = (x + w) / 2, y' = (w - y) / 2 (y down).
    glm::mat4 toNdc(1.0f);
    toNdc[0][0] = 0.5f;
    toNdc[1][1] = -0.5f;
    toNdc[3][0] = 0.5f;  // column 3 multiplies w
    toNdc[3][1] = 0.5f;
    image.matrix_attributes.emplace_back("worldToCamera", imathOrder(flipZ * m.view));
    image.matrix_attributes.emplace_back("worldToNDC", imathOrder(toNdc * m.projection * m.view));
    image.float_attributes.emplace_back("penumbra/camera/fov_y", camera.fov_y);
    image.float_attributes.emplace_back("penumbra/camera/near", camera.near);
    image.float_attributes.emplace_back("penumbra/camera/far", camera.far);
}

}  // namespace penumbra::frame
