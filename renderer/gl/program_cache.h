// Linked GL programs cached on disk as program binaries (glGetProgramBinary), so a process
// skips shader compilation for programs an earlier one built on the same driver: one file per
// program under $XDG_CACHE_HOME/penumbra/programs (else ~/.cache/penumbra/programs), named by a
// hash of the driver's strings and the program's sources. A file that is unreadable, corrupt,
// for other sources or refused by the driver is ignored (the program is compiled and the file
// replaced); nothing is written elsewhere. PENUMBRA_PROGRAM_CACHE=0 turns it off.
#pragma once

#include <filesystem>
#include <string>

#include <glad/gl.h>

namespace penumbra::gl {

// How this process's programs were made.
struct ProgramCacheStats {
    int compiled = 0;    // compiled and linked from source
    int from_cache = 0;  // loaded from a cached binary
};
ProgramCacheStats programCacheStats();

// The user's cache folder: $XDG_CACHE_HOME, else ~/.cache; empty when neither is an absolute
// path.
std::filesystem::path userCacheFolder();

// The folder cached programs go to; empty when the cache is off (PENUMBRA_PROGRAM_CACHE=0) or
// there is no user cache folder.
std::filesystem::path programCacheFolder();

// Creates programCacheFolder() if it is missing (failures ignored), or with the cache off the
// user's cache folder, before a driver starts: Mesa keeps its own shader cache in
// ~/.cache/mesa_shader_cache and, where ~/.cache is missing (a fresh account, a farm node),
// prints a line on stderr and runs without it.
void createProgramCacheFolder();

// KEY: everything the binary depends on (the program's stage names and sources; the driver's
// strings are added here). Loads the cached binary into PROGRAM: true when it links.
bool loadCachedProgram(GLuint program, const std::string& key);
// Stores PROGRAM (linked with GL_PROGRAM_BINARY_RETRIEVABLE_HINT) under KEY; failures are
// ignored.
void storeCachedProgram(GLuint program, const std::string& key);
// Counts a program compiled from source (for programCacheStats).
void countCompiledProgram();

}  // namespace penumbra::gl
