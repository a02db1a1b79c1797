// A check of a PNG file's chunk lengths before a library decodes it: libpng allocates what a
// chunk declares before reading it (a 336-byte file declaring a 1.2 GB text chunk took seconds).
#pragma once

#include <cstdint>
#include <istream>
#include <string>

namespace penumbra {

// Walks the chunks of the PNG file IN (SIZE bytes, read from its start) and returns why it
// cannot be read when a chunk declares more bytes than the file holds after it (or more than
// the format's 2^31 - 1); an empty string when every chunk up to IEND fits. Only the chunks'
// headers are read. A file that is not PNG (no signature), or one cut short inside a chunk
// header, is left to the decoder: the answer is empty.
std::string pngChunkProblem(std::istream& in, std::uintmax_t size);

}  // namespace penumbra
