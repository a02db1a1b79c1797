// Cryptomatte: MurmurHash3_x86_32 against published vectors and the spec's own manifest example,
// the uint32_to_float32 conversion derived bit by bit, and an EXR whose manifest reads back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include <nlohmann/json.hpp>

#include "renderer/output/cryptomatte.h"
#include "renderer/output/exr.h"
#include "tests/unit/output/image_attribute.h"
#include "tests/unit/output/scratch_folder.h"

namespace penumbra::output {
namespace {

using testing::attribute;
using testing::ScratchFolder;

TEST(Cryptomatte, MurmurHashMatchesReferenceVectors) {
    EXPECT_EQ(murmurHash3(""), 0u);
    EXPECT_EQ(murmurHash3("hello"), 0x248bfa47u);
    EXPECT_EQ(murmurHash3("The quick brown fox jumps over the lazy dog"), 0x2e4ff723u);
    // The Cryptomatte specification's manifest example: {"bunny":"13851a76","default":"42c9679f"}.
    EXPECT_EQ(murmurHash3("bunny"), 0x13851a76u);
    EXPECT_EQ(murmurHash3("default"), 0x42c9679fu);
}

TEST(Cryptomatte, IdIsTheHashWithItsExponentClamped) {
    auto bits = [](float f) {
        uint32_t b;
        std::memcpy(&b, &f, sizeof b);
        return b;
    };
    // 0x42c9679f: exponent 0x85 is in [1, 254], so the bits are kept: 100.70238.
    EXPECT_EQ(bits(cryptomatteId(0x42c9679fu)), 0x42c9679fu);
    EXPECT_NEAR(cryptomatteId(0x42c9679fu), 100.70238f, 1e-4f);
    // Exponent 0 becomes 1 (no denormal), 255 becomes 254 (no inf or NaN); sign and mantissa kept.
    EXPECT_EQ(bits(cryptomatteId(0x00000005u)), 0x00800005u);
    EXPECT_EQ(bits(cryptomatteId(0xffffffffu)), 0xff7fffffu);
    EXPECT_TRUE(std::isfinite(cryptomatteId(0x7f800000u)));
}

TEST(Cryptomatte, ChannelsAndManifestReadBack) {
    Image image;
    image.width = 3;
    image.height = 1;
    image.add("A", PixelType::Half).pixels = {1.0f, 0.5f, 0.0f};
    image.add("id", PixelType::Float).pixels = {0.0f, 1.0f, -1.0f};
    addCryptomatte(image, "CryptoObject", {"floor", "bunny"}, 4);
    ScratchFolder dir;
    writeExr(dir / "c.exr", image);
    const Image read = readExr(dir / "c.exr");

    // The key is the first 7 hex digits of the layer name's hash.
    ASSERT_EQ(murmurHash3("CryptoObject"), 0x3ae39a58u);
    const std::string prefix = "cryptomatte/3ae39a5/";
    EXPECT_EQ(attribute(read, prefix + "name"), "CryptoObject");
    EXPECT_EQ(attribute(read, prefix + "hash"), "MurmurHash3_32");
    EXPECT_EQ(attribute(read, prefix + "conversion"), "uint32_to_float32");
    const auto manifest =
        nlohmann::json::parse(attribute(read, prefix + "manifest"), nullptr, false);
    EXPECT_EQ(manifest, nlohmann::json({{"floor", "7819c83c"}, {"bunny", "13851a76"}}));

    const ImageChannel* rank = read.find("CryptoObject00.R");
    const ImageChannel* coverage = read.find("CryptoObject00.G");
    ASSERT_TRUE(rank && coverage);
    EXPECT_EQ(rank->type, PixelType::Float);
    EXPECT_EQ(rank->pixels[0], cryptomatteId(0x7819c83cu));
    EXPECT_EQ(rank->pixels[1], cryptomatteId(0x13851a76u));
    EXPECT_EQ(rank->pixels[2], 0.0f);                                     // background: no object
    EXPECT_EQ(coverage->pixels, (std::vector<float>{1.0f, 0.5f, 0.0f}));  // A at 4 samples
    EXPECT_NE(read.find("CryptoObject00.B"), nullptr);
    EXPECT_NE(read.find("CryptoObject00.A"), nullptr);

    // At one sample a covered pixel's coverage is 1 whatever A says.
    Image one;
    one.width = 1;
    one.height = 1;
    one.add("A", PixelType::Half).pixels = {0.25f};
    one.add("id", PixelType::Float).pixels = {0.0f};
    addCryptomatte(one, "CryptoObject", {"floor"}, 1);
    const ImageChannel* oneCoverage = one.find("CryptoObject00.G");
    ASSERT_TRUE(oneCoverage);
    EXPECT_EQ(oneCoverage->pixels[0], 1.0f);
}

}  // namespace
}  // namespace penumbra::output
