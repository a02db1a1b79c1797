// What the renderer asks of OpenImageIO (decoding images, drawing and measuring text, scaling,
// JPEG), in a shared module of our own loaded only by the commands that need it (oiio_module.cpp).
#pragma once

#include <cstddef>
#include <memory>
#include <string>

namespace penumbra {

// The module is refused unless it was built from this header as the binary was (CMake keys both
// on a hash of this file, penumbra/oiio_interface.h): a stale module beside a new binary is an
// error, not a crash; a module from another commit with the same interface loads.
// A decoded image's first subimage: its size, origin and tiles (0 when scanline).
struct DecoderSpec {
    int width = 0, height = 0, depth = 0, channels = 0;
    int x = 0, y = 0, z = 0;
    int tile_width = 0, tile_height = 0;
};

// An open image file, read a strip of rows at a time.
class ImageDecoder {
public:
    virtual ~ImageDecoder() = default;
    virtual const DecoderSpec& spec() const = 0;
    // Rows [Y0, Y1) (from the top of the data window), the first CHANNELS channels as float,
    // interleaved, into OUT (tiled files: Y0 and Y1 on whole tiles or the image's end). False
    // with error() set when the pixels cannot be read.
    virtual bool readRows(int y0, int y1, int channels, float* out) = 0;
    virtual std::string error() = 0;
    virtual void close() = 0;
};

class OiioModule {
public:
    // The image at PATH, or at BYTES in memory in the format of EXTENSION (".hdr"); null with
    // ERROR set (possibly empty) when it cannot be opened.
    virtual std::unique_ptr<ImageDecoder> open(const std::string& path, std::string& error) = 0;
    virtual std::unique_ptr<ImageDecoder> openMemory(const unsigned char* bytes, std::size_t size,
                                                     const std::string& extension,
                                                     std::string& error) = 0;
    // Width in pixels of TEXT at SIZE in FONT (a file or a font name OpenImageIO searches
    // for); 0 when it cannot be measured.
    virtual int textWidth(const std::string& text, int size, const std::string& font) = 0;
    // The calls below return false with ERROR set (OpenImageIO's message) on failure.
    // Draws TEXT centred on (X, Y) into RGB (WIDTH x HEIGHT x 3 floats) in COLOUR.
    virtual bool drawText(float* rgb, int width, int height, int x, int y, const std::string& text,
                          int size, const std::string& font, const float colour[3],
                          std::string& error) = 0;
    // SRC (SW x SH RGB floats) scaled into DST (DW x DH) with OpenImageIO's default filter.
    virtual bool resize(const float* src, int sw, int sh, float* dst, int dw, int dh,
                        std::string& error) = 0;
    // RGB8 (W x H x 3 bytes) as a JPEG of QUALITY at PATH.
    virtual bool writeJpeg(const std::string& path, int w, int h, const unsigned char* rgb8,
                           int quality, std::string& error) = 0;

protected:
    ~OiioModule() = default;
};

// The module, loaded on first use: linked into this process already (the test programs), else
// libpenumbra_oiio.so beside the executable or in its installed library folder. Throws
// RuntimeError ("cannot load the OpenImageIO module ...: why") when it is missing or stale.
OiioModule& oiioModule();

}  // namespace penumbra
