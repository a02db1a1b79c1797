// OpenEXR's standard camera attributes for a frame: worldToCamera and worldToNDC (M44f, as the
// OpenEXR standard attributes define them) and the camera's fov, near and far (floats).
#pragma once

#include "renderer/output/image.h"
#include "renderer/scene/scene.h"

namespace penumbra::frame {

// Adds to IMAGE: `worldToCamera` (world to a left-handed camera space, +x right, +y up, +z the
// viewing direction: objects in front have z > 0, Z's depth), `worldToNDC` (world to NDC, (0, 0)
// the top left and (1, 1) the bottom right corner of the image, after dividing by w: pixel
// (i, j)'s centre is at ((i + 0.5) / width, (j + 0.5) / height)), and the floats
// `penumbra/camera/fov_y` (degrees), `penumbra/camera/near`, `penumbra/camera/far` (metres).
void addCameraAttributes(output::Image& image, const scene::Camera& camera, int width, int height);

}  // namespace penumbra::frame
