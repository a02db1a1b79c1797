// One headless GL context for the whole GL test binary, and a helper that renders a scene file
// with a technique and overrides and returns the image.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/frame/render_frame.h"
#include "renderer/gl/context.h"
#include "renderer/gl/handles.h"
#include "renderer/output/image.h"
#include "renderer/scene/scene_source.h"

namespace penumbra::testing {

const gl::ContextInfo& glInfo();

// The technique block of the ground truth every accuracy test measures against: `exact` with
// 32 x 32 shadow rays per pixel.
inline constexpr const char* kGroundTruth = R"({"name": "exact", "samples": 32})";

// Renders frame FRAME of tests/data/gl/NAME (relative to the source tree) with OVERRIDES
// (-D style) and checks that no GL error was raised; the technique statistics go to STATS
// when given.
output::Image renderScene(const std::string& name, const std::vector<scene::Override>& overrides,
                          int frame = 0, nlohmann::json* stats = nullptr);
// As renderScene (frame 0), with CONFIGURE applied to the frame renderer before it renders.
output::Image renderSceneWith(const std::string& name,
                              const std::vector<scene::Override>& overrides,
                              const std::function<void(frame::FrameRenderer&)>& configure);

// Shadow-region MAE (Atty et al. 5.2.1) of IMG's visibility against the closed form of
// closed_form.json (a 0.8 m square occluder at (0.2, 1.5, 0.1) parallel to a square light of half
// size LIGHT_HALF at y = 3), over floor pixels (id 0) where either is below 0.999. Expects at
// more than MIN_PIXELS such pixels.
double closedFormShadowMae(const output::Image& img, double light_half, long min_pixels);

// Shadow-region MAE (Atty et al. 5.2.1) of TEST's visibility against REF's over the floor
// (id 0), the receiver of the test scenes, where either is below 0.999. Expects more than
// MIN_PIXELS such pixels.
double floorShadowMae(const output::Image& ref, const output::Image& test, long min_pixels = 500);
// The same over the pixels of object OBJECT (its index in the scene's objects).
double objectShadowMae(const output::Image& ref, const output::Image& test, int object,
                       long min_pixels = 500);

// Shadow-region MAE: mean |a[i] - truth[i]| over pixels where either is below 0.999 (in
// shadow). Expects more than MIN_PIXELS such pixels.
double shadowRegionMae(const std::vector<float>& a, const std::vector<float>& truth,
                       long min_pixels = 500);

// Exact unshadowed irradiance of LIGHT (double precision) at pixel I of IMG, from its P and N.
double pixelIrradiance(const scene::RectLight& light, const output::Image& img, size_t i);

// The sum of channel NAME of IMG over the pixels of object ID (by IDS's `id` channel; IMG's
// own when IDS is null).
double sumOverObject(const output::Image& img, const std::string& name, int id,
                     const output::Image* ids = nullptr);

// The largest |a[i] - b[i]| of two equally long channels.
double maxAbsDifference(const std::vector<float>& a, const std::vector<float>& b);

// Values of channel NAME, which must exist.
const std::vector<float>& channel(const output::Image& image, const std::string& name);

// A program LABEL linked from STAGES (each a shader stage and its whole source), for tests of
// shader code that no pass compiles alone; a stage that does not compile or a program that
// does not link fails the test.
gl::Program linkTestProgram(const std::string& label,
                            std::initializer_list<std::pair<GLenum, std::string>> stages);

}  // namespace penumbra::testing
