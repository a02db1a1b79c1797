// Regular files only: inputs that are FIFOs, devices or folders are named as such; outputs never
// replace them (and a failed rename says why, not "Success").
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <string>

#include "../output/scratch_folder.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/core/regular_file.h"

using penumbra::checkOutputPath;
using penumbra::InputError;
using penumbra::notRegularFileReason;
using penumbra::notReplaceableReason;
using penumbra::requireRegularFile;
using penumbra::RuntimeError;
using penumbra::writeFileAtomically;
using penumbra::output::testing::ScratchFolder;

TEST(RegularFile, InputsNameWhatIsInTheWay) {
    ScratchFolder dir;
    std::ofstream(dir / "file") << "x";
    ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
    std::filesystem::create_directory(dir / "folder");
    EXPECT_EQ(notRegularFileReason(dir / "file"), "");
    EXPECT_EQ(notRegularFileReason(dir / "fifo"), "is a FIFO");
    EXPECT_EQ(notRegularFileReason(dir / "folder"), "is a folder");
    EXPECT_EQ(notRegularFileReason(dir / "missing"), "no such file");
    EXPECT_EQ(notRegularFileReason("/dev/null"), "is a device");
    try {
        requireRegularFile(dir / "fifo", "scene.json");
        FAIL() << "a FIFO was accepted";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "scene.json: is a FIFO");
    }
}

TEST(RegularFile, OutputsReplaceOnlyRegularFiles) {
    ScratchFolder dir;
    std::ofstream(dir / "old.json") << "old";
    ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
    std::filesystem::create_directory(dir / "folder");
    std::filesystem::create_symlink(dir / "old.json", dir / "link");
    EXPECT_EQ(notReplaceableReason(dir / "new.json"), "");
    EXPECT_EQ(notReplaceableReason(dir / "old.json"), "");
    EXPECT_EQ(notReplaceableReason(dir / "link"), "is a symbolic link");
    EXPECT_EQ(notReplaceableReason("/dev/null"), "is a device");

    writeFileAtomically(dir / "old.json", "new");
    for (const char* name : {"fifo", "folder", "link"}) {
        try {
            writeFileAtomically(dir / name, "x");
            FAIL() << name << " was replaced";
        } catch (const RuntimeError& e) {
            EXPECT_NE(std::string(e.what()).find("an output replaces only a regular file"),
                      std::string::npos)
                << e.what();
        }
    }
    EXPECT_THROW(writeFileAtomically("/dev/null", "x"), RuntimeError);
    EXPECT_TRUE(std::filesystem::is_fifo(dir / "fifo"));
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link"));
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"fifo", "folder", "link", "old.json"}));
    try {
        checkOutputPath("/dev/null", "--timings");
        FAIL() << "/dev/null accepted as an output";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "--timings: /dev/null: is a device (an output replaces only a regular file)");
    }
}
