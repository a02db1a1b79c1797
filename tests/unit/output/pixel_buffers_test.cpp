// Pixel storage reused across a sequence's images, and the float to half conversion the EXR
// writer uses: reused buffers come back zeroed when asked (never another image's pixels), an
// image written through reused storage has the bytes of one written without, and the F16C
// path converts every kind of value as Imath does.
#include <Imath/half.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "renderer/output/exr.h"
#include "renderer/output/half_bits.h"
#include "renderer/output/image.h"
#include "renderer/output/pixel_buffers.h"
#include "tests/unit/output/scratch_folder.h"

namespace penumbra::output {
namespace {

using testing::ScratchFolder;

TEST(PixelBuffers, ReusedStorageIsZeroedWhenAskedAndKeptWhenNot) {
    PixelBuffers buffers;
    Image first;
    first.width = 4;
    first.height = 3;
    first.buffers = &buffers;
    ImageChannel& c = first.add("R", PixelType::Half);
    for (float& v : c.pixels) v = 7.0f;
    const float* storage = c.pixels.data();
    buffers.recycle(std::move(first));
    EXPECT_TRUE(first.channels.empty());

    std::vector<float> zeroed = buffers.take(12, Fill::Zeros);
    EXPECT_EQ(zeroed.data(), storage);  // the same memory, not a new allocation
    EXPECT_EQ(zeroed, std::vector<float>(12, 0.0f));
    for (float& v : zeroed) v = 3.0f;
    Image second;
    second.width = 4;
    second.height = 3;
    second.channels.push_back({"G", PixelType::Half, std::move(zeroed)});
    buffers.recycle(std::move(second));
    const std::vector<float> kept = buffers.take(12, Fill::Undefined);
    EXPECT_EQ(kept.data(), storage);
    EXPECT_EQ(kept, std::vector<float>(12, 3.0f));  // Undefined: nothing written
    // Larger than anything given back: new storage, zeros.
    EXPECT_EQ(buffers.take(100, Fill::Undefined), std::vector<float>(100, 0.0f));
}

TEST(PixelBuffers, KeepsTheSmallestThatFitsAndABoundedNumber) {
    PixelBuffers buffers;
    Image image;
    image.width = 1;
    image.height = 1;
    for (size_t n : {50u, 10u, 30u})
        image.channels.push_back({"c", PixelType::Float, std::vector<float>(n, 1.0f)});
    buffers.recycle(std::move(image));
    EXPECT_EQ(buffers.take(20, Fill::Zeros).capacity(), 30u);
    EXPECT_EQ(buffers.take(20, Fill::Zeros).capacity(), 50u);
    EXPECT_EQ(buffers.take(20, Fill::Zeros).capacity(), 20u);  // only 10 left: a new one

    Image many;
    for (size_t i = 0; i < PixelBuffers::kKept + 10; ++i)
        many.channels.push_back({"c", PixelType::Float, std::vector<float>(1, 1.0f)});
    buffers.recycle(std::move(many));
    size_t reused = 0;
    for (size_t i = 0; i < PixelBuffers::kKept + 10; ++i)
        reused += buffers.take(1, Fill::Undefined)[0] == 1.0f ? 1 : 0;
    EXPECT_EQ(reused, PixelBuffers::kKept);
}

std::string bytesOf(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

TEST(PixelBuffers, AnImageWrittenThroughReusedStorageHasTheSameBytes) {
    ScratchFolder dir;
    PixelBuffers buffers;
    auto make = [&](PixelBuffers* from, float offset) {
        Image image;
        image.width = 37;  // not a multiple of 8: the conversion's tail
        image.height = 5;
        image.buffers = from;
        for (const auto& [name, type] :
             {std::pair{"R", PixelType::Half}, {"Z", PixelType::Float}, {"N.X", PixelType::Half}}) {
            ImageChannel& c = image.add(name, type, Fill::Undefined);
            for (size_t i = 0; i < c.pixels.size(); ++i)
                c.pixels[i] = offset + std::sin(static_cast<float>(i)) * 1000.0f;
        }
        return image;
    };
    for (float offset : {0.0f, 0.5f, -3.0f}) {  // the later images reuse the earlier's storage
        const auto tag = std::to_string(static_cast<int>(offset * 10));
        Image reused = make(&buffers, offset);
        writeExr(dir.path() / ("reused" + tag + ".exr"), reused);
        buffers.recycle(std::move(reused));
        writeExr(dir.path() / ("own" + tag + ".exr"), make(nullptr, offset));
        EXPECT_EQ(bytesOf(dir.path() / ("reused" + tag + ".exr")),
                  bytesOf(dir.path() / ("own" + tag + ".exr")))
            << "offset " << offset;
    }
}

TEST(HalfBits, ConvertsEveryKindOfValueAsImathDoes) {
    std::vector<float> values = {0.0f,     -0.0f,    1.0f,     -1.0f,   0.5f,    65504.0f,
                                 65520.0f, 1e9f,     -1e9f,    6.1e-5f, 6.0e-8f, 2.9e-8f,
                                 1e-12f,   3.14159f, 1.00049f, 1.00146f};
    values.push_back(std::numeric_limits<float>::infinity());
    values.push_back(-std::numeric_limits<float>::infinity());
    values.push_back(std::numeric_limits<float>::denorm_min());
    for (int i = 0; i < 20000; ++i)  // exponents from far below half's range to above it
        values.push_back(std::ldexp(1.0f + static_cast<float>(i % 1024) / 1024.0f, i % 50 - 30) *
                         (i % 3 == 0 ? -1.0f : 1.0f));
    values.push_back(std::nanf(""));
    std::vector<std::uint16_t> fast(values.size()), portable(values.size());
    toHalfBits(values.data(), fast.data(), values.size());
    toHalfBitsPortable(values.data(), portable.data(), values.size());
    for (size_t i = 0; i + 1 < values.size(); ++i)
        ASSERT_EQ(fast[i], portable[i]) << "value " << values[i];
    Imath::half nan;
    nan.setBits(fast.back());
    EXPECT_TRUE(nan.isNan());
    std::printf("toHalfBits uses F16C here: %s\n", toHalfBitsUsesF16c() ? "yes" : "no");
}

}  // namespace
}  // namespace penumbra::output
