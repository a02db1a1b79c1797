// `bitmask`'s image budget map: the first channel of a PNG or EXR, rows turned bottom first for
// GL, clamped to [0, 1], the path relative to the scene file; and every refusal naming the key
// technique.budget_map and the path.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "renderer/core/error.h"
#include "renderer/techniques/bitmask/budget_map.h"

using namespace penumbra;
using techniques::bitmask::readBudgetMap;

namespace {

std::filesystem::path scratch() {
    const char* tmp = std::getenv("PENUMBRA_TEST_TMP");
    const auto dir = std::filesystem::path(tmp ? tmp : "/tmp") / "budget_map";
    std::filesystem::create_directories(dir);
    return dir;
}

void writeImage(const std::filesystem::path& path, int width, int height, int channels,
                const std::vector<float>& pixels, OIIO::TypeDesc type) {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(width, height, channels, type);
    ASSERT_TRUE(out->open(path.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
}

std::string errorOf(const std::filesystem::path& scene, const std::string& file) {
    try {
        readBudgetMap(scene, file);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(BudgetMap, ReadsTheFirstChannelBottomRowFirst) {
    const auto dir = scratch();
    // 2 x 2 RGB, top row (0.25, 1) then bottom row (0, 0.5); green and blue ignored.
    writeImage(dir / "map.png", 2, 2, 3, {0.25f, 9, 9, 1, 9, 9, 0, 9, 9, 0.5f, 9, 9},
               OIIO::TypeDesc::UINT16);
    const auto map = readBudgetMap(dir / "scene.json", "map.png");  // relative to the scene
    ASSERT_EQ(map.width, 2);
    ASSERT_EQ(map.height, 2);
    ASSERT_EQ(map.values.size(), 4u);
    EXPECT_NEAR(map.values[0], 0.0f, 1e-4f);  // bottom row first
    EXPECT_NEAR(map.values[1], 0.5f, 1e-4f);
    EXPECT_NEAR(map.values[2], 0.25f, 1e-4f);
    EXPECT_NEAR(map.values[3], 1.0f, 1e-4f);
    // EXR values outside [0, 1] are clamped; an absolute path ignores the scene's folder.
    writeImage(dir / "wide.exr", 3, 1, 1, {-2, 0.75f, 4}, OIIO::TypeDesc::FLOAT);
    const auto exr = readBudgetMap("/elsewhere/scene.json", (dir / "wide.exr").string());
    EXPECT_EQ(exr.values, (std::vector<float>{0, 0.75f, 1}));
}

TEST(BudgetMap, RefusalsNameTheKeyAndThePath) {
    const auto dir = scratch();
    const auto scene = dir / "scene.json";
    const std::string key = "technique.budget_map: " + (dir / "").string();
    EXPECT_EQ(errorOf(scene, "missing.png"), key + "missing.png: no such file");
    EXPECT_EQ(errorOf(scene, "map.jpg"), key + "map.jpg: expected a .png or .exr image");
    std::filesystem::create_directories(dir / "folder.png");
    EXPECT_EQ(errorOf(scene, "folder.png"), key + "folder.png: is a folder");
    std::ofstream(dir / "text.png") << "not a png\n";
    EXPECT_EQ(errorOf(scene, "text.png").rfind(key + "text.png: cannot read image", 0), 0u)
        << errorOf(scene, "text.png");
    writeImage(dir / "nan.exr", 2, 1, 1, {0.5f, std::nanf("")}, OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(errorOf(scene, "nan.exr"), key + "nan.exr: non-finite pixel at (1, 0)");
    const int big = techniques::bitmask::kMaxBudgetMapSize + 1;
    writeImage(dir / "big.exr", big, 1, 1, std::vector<float>(size_t(big), 1.0f),
               OIIO::TypeDesc::HALF);
    EXPECT_EQ(errorOf(scene, "big.exr"), key + "big.exr: image too large (" + std::to_string(big) +
                                             "x1, limit " + std::to_string(big - 1) + ")");
    for (const auto& e : {errorOf(scene, "missing.png"), errorOf(scene, "text.png")})
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;  // one line
}
