// The process's memory limit (--memory-limit, default half the physical memory): every large
// allocation an input implies is estimated and checked against it before it is made.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace penumbra {

// Half of the machine's physical memory (4 GiB when it cannot be read).
std::uint64_t defaultMemoryLimit();

// The limit in bytes: the one set last, else defaultMemoryLimit().
std::uint64_t memoryLimit();
void setMemoryLimit(std::uint64_t bytes);

// "8G", "512M", "1.5GiB", "1000000" (bytes); K, M, G, T are powers of 1024, an optional "B" or
// "iB" may follow. nullopt for anything else, zero, or more than 2^60 bytes.
std::optional<std::uint64_t> parseMemorySize(std::string_view text);

// "1.5 GiB", "300 MiB", "12 KiB", "17 bytes".
std::string formatBytes(std::uint64_t bytes);

// Throws InputError("WHERE: WHAT needs about X, more than the memory limit of Y
// (--memory-limit)") when BYTES exceed memoryLimit().
void requireMemory(std::uint64_t bytes, const std::string& where, const std::string& what);

// A * B * ... saturating at UINT64_MAX (estimates of hostile sizes must not wrap).
std::uint64_t saturatingProduct(std::initializer_list<std::uint64_t> factors);

}  // namespace penumbra
