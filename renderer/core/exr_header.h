// A check of an OpenEXR file's header before a library decodes it: each attribute's declared
// size must fit in the file, since OpenEXR allocates what a header declares before reading it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>

namespace penumbra {

// Walks the attribute list of every header of the OpenEXR file IN (SIZE bytes, read from its
// start) and returns why it cannot be read when an attribute declares more bytes than the file
// holds or the header is cut short; an empty string when every attribute fits. Only the header
// is read: its attributes' values are skipped. A file that is not OpenEXR (no magic number) is
// left to the decoder: the answer is empty.
std::string exrHeaderProblem(std::istream& in, std::uintmax_t size);

// The same over BYTES in memory (an image embedded in another file).
std::string exrHeaderProblem(const unsigned char* bytes, std::size_t size);

}  // namespace penumbra
