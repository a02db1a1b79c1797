// One headless GL context for the whole GL test binary, and a helper that renders a scene file
// with a technique and overrides and returns the image.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "renderer/gl/context.h"
#include "renderer/output/image.h"
#include "renderer/scene/scene_source.h"

namespace penumbra::testing {

const gl::ContextInfo& glInfo();

// Renders frame FRAME of tests/data/gl/NAME (relative to the source tree) with OVERRIDES
// (-D style) and checks that no GL error was raised.
output::Image renderScene(const std::string& name, const std::vector<scene::Override>& overrides,
                          int frame = 0);

// The largest |a[i] - b[i]| of two equally long channels.
double maxAbsDifference(const std::vector<float>& a, const std::vector<float>& b);

// Values of channel NAME, which must exist.
const std::vector<float>& channel(const output::Image& image, const std::string& name);

}  // namespace penumbra::testing
