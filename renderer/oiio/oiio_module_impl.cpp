// libpenumbra_oiio.so: the OpenImageIO calls behind core/oiio_module.h, built from this file
// alone (no renderer library: the binary's state is never duplicated here) and loaded on demand.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <cstring>
#include <memory>
#include <string>

#include "penumbra/oiio_interface.h"
#include "renderer/core/oiio_module.h"

namespace penumbra {
namespace {

class Decoder final : public ImageDecoder {
public:
    Decoder(std::unique_ptr<OIIO::ImageInput> input,
            std::unique_ptr<OIIO::Filesystem::IOMemReader> proxy)
        : proxy_(std::move(proxy)), input_(std::move(input)) {
        const OIIO::ImageSpec& s = input_->spec();
        spec_ = {s.width, s.height, s.depth,      s.nchannels,  s.x,
                 s.y,     s.z,      s.tile_width, s.tile_height};
    }
    const DecoderSpec& spec() const override { return spec_; }
    bool readRows(int y0, int y1, int channels, float* out) override {
        const DecoderSpec& s = spec_;
        if (s.tile_width > 0)
            return input_->read_tiles(0, 0, s.x, s.x + s.width, s.y + y0, s.y + y1, s.z, s.z + 1, 0,
                                      channels, OIIO::TypeDesc::FLOAT, out);
        return input_->read_scanlines(0, 0, s.y + y0, s.y + y1, s.z, 0, channels,
                                      OIIO::TypeDesc::FLOAT, out);
    }
    std::string error() override { return input_->geterror(); }
    void close() override { input_->close(); }

private:
    std::unique_ptr<OIIO::Filesystem::IOMemReader> proxy_;  // outlives the input reading it
    std::unique_ptr<OIIO::ImageInput> input_;
    DecoderSpec spec_;
};

// Opens NAME with the reader of EXTENSION's format alone (through PROXY where given): where that
// reader fails, ImageInput::open() tries every other format OpenImageIO has, dozens of plugins,
// which read a file of another format than its name says and, on a damaged PNG (a fuzz finding),
// doubled the time the PNG reader spent (png_chunks.h). Empty, with ERROR, where it cannot.
std::unique_ptr<OIIO::ImageInput> openAs(const std::string& name, const std::string& extension,
                                         OIIO::Filesystem::IOProxy* proxy, std::string& error) {
    // By the extension without its dot: ".hdr" alone reads as a file name with no extension.
    const std::string format =
        extension.empty() || extension[0] != '.' ? extension : extension.substr(1);
    auto input = OIIO::ImageInput::create(format, false);
    if (!input) {
        error = OIIO::geterror();
        if (error.empty()) error = "no reader for " + extension + " files";
        return nullptr;
    }
    if (proxy && !input->set_ioproxy(proxy)) {
        error = "the " + extension + " reader cannot read from memory";
        return nullptr;
    }
    OIIO::ImageSpec spec;
    if (!input->open(name, spec)) {
        error = input->geterror();
        if (error.empty()) error = "not a readable " + extension + " image";
        return nullptr;
    }
    return input;
}

class Module final : public OiioModule {
public:
    std::unique_ptr<ImageDecoder> open(const std::string& path, std::string& error) override {
        const std::string extension = OIIO::Strutil::lower(OIIO::Filesystem::extension(path));
        auto input = openAs(path, extension, nullptr, error);
        if (!input) return nullptr;
        return std::make_unique<Decoder>(std::move(input), nullptr);
    }

    std::unique_ptr<ImageDecoder> openMemory(const unsigned char* bytes, std::size_t size,
                                             const std::string& extension,
                                             std::string& error) override {
        auto proxy = std::make_unique<OIIO::Filesystem::IOMemReader>(bytes, size);
        auto input = openAs("memory" + extension, extension, proxy.get(), error);
        if (!input) return nullptr;
        return std::make_unique<Decoder>(std::move(input), std::move(proxy));
    }

    int textWidth(const std::string& text, int size, const std::string& font) override {
        const OIIO::ROI r = OIIO::ImageBufAlgo::text_size(text, size, font);
        if (!r.defined()) {
            OIIO::geterror();  // clear it: the caller reports
            return 0;
        }
        return r.width();
    }

    bool drawText(float* rgb, int width, int height, int x, int y, const std::string& text,
                  int size, const std::string& font, const float colour[3],
                  std::string& error) override {
        OIIO::ImageBuf buf(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT), rgb);
        if (OIIO::ImageBufAlgo::render_text(buf, x, y, text, size, font, {colour, 3},
                                            OIIO::ImageBufAlgo::TextAlignX::Center,
                                            OIIO::ImageBufAlgo::TextAlignY::Center))
            return true;
        error = buf.geterror();
        return false;
    }

    bool resize(const float* src, int sw, int sh, float* dst, int dw, int dh,
                std::string& error) override {
        const OIIO::ImageBuf from(OIIO::ImageSpec(sw, sh, 3, OIIO::TypeDesc::FLOAT),
                                  const_cast<float*>(src));
        OIIO::ImageBuf to(OIIO::ImageSpec(dw, dh, 3, OIIO::TypeDesc::FLOAT));
        if (!OIIO::ImageBufAlgo::resize(to, from)) {
            error = to.geterror();
            return false;
        }
        to.get_pixels(OIIO::ROI(0, dw, 0, dh, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, dst);
        return true;
    }

    bool writeJpeg(const std::string& path, int w, int h, const unsigned char* rgb8, int quality,
                   std::string& error) override {
        auto out = OIIO::ImageOutput::create("jpeg");
        if (!out) {
            error = "no JPEG writer: " + OIIO::geterror();
            return false;
        }
        OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
        spec.attribute("Compression", "jpeg:" + std::to_string(quality));
        if (out->open(path, spec) && out->write_image(OIIO::TypeDesc::UINT8, rgb8) && out->close())
            return true;
        error = out->geterror();
        return false;
    }
};

}  // namespace
}  // namespace penumbra

// The entry the loader looks up: the module, or null when the caller was built from another
// revision of core/oiio_module.h (its hash, penumbra/oiio_interface.h).
extern "C" __attribute__((visibility("default"))) penumbra::OiioModule* penumbra_oiio_module(
    const char* interface) {
    if (!interface || std::strcmp(interface, PENUMBRA_OIIO_INTERFACE) != 0) return nullptr;
    static penumbra::Module module;
    return &module;
}
