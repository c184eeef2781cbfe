#pragma once
// Reading files the user names (scenes, recipes, images, glTF buffers) without trusting them:
// the path must be a regular file (a directory, /dev/zero, a FIFO or a link to one is refused,
// since reading them never ends or blocks) no larger than a stated limit. docs/robustness.md.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace diptych {

// Largest JSON text (scene, recipe, glTF JSON) we read: the largest shared scene is < 1 MiB.
constexpr std::uintmax_t kMaxJsonFileBytes = std::uintmax_t(64) << 20;
// Largest binary input (image, .glb, glTF buffer).
constexpr std::uintmax_t kMaxBinaryFileBytes = std::uintmax_t(1) << 30;

// Throws InputError naming `path` unless it is an existing regular file of at most `maxBytes`.
// Returns the file's size.
std::uintmax_t checkInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes);

// checkInputFile, then the whole file. Reads at most maxBytes even if the file grows meanwhile.
std::string readInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes);

}  // namespace diptych
