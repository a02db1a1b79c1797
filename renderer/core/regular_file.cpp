// Regular-file checks for inputs and outputs: see regular_file.h.
#include "renderer/core/regular_file.h"

#include "renderer/core/error.h"

namespace penumbra {

std::string notRegularFileReason(const std::filesystem::path& path, bool follow_symlinks) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status =
        follow_symlinks ? fs::status(path, ec) : fs::symlink_status(path, ec);
    switch (status.type()) {
        case fs::file_type::regular:
            return "";
        case fs::file_type::not_found:
            return "no such file";
        case fs::file_type::none:
            return "cannot read file (" + ec.message() + ")";
        case fs::file_type::directory:
            return "is a folder";
        case fs::file_type::fifo:
            return "is a FIFO";
        case fs::file_type::block:
        case fs::file_type::character:
            return "is a device";
        case fs::file_type::socket:
            return "is a socket";
        case fs::file_type::symlink:
            return "is a symbolic link";
        default:
            return "not a regular file";
    }
}

void requireRegularFile(const std::filesystem::path& path, const std::string& label) {
    if (const std::string why = notRegularFileReason(path); !why.empty())
        throw InputError(label + ": " + why);
}

std::string notReplaceableReason(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::symlink_status(path, ec).type() == std::filesystem::file_type::not_found)
        return "";
    return notRegularFileReason(path, false);
}

}  // namespace penumbra
