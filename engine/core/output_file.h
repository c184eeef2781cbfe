#pragma once
// Writing the files a run produces (results.json/csv, reports, recipes) so that a reader never
// sees a half-written file presented as a result: the text goes to PATH.tmp, is checked, and is
// renamed over PATH (rename is atomic on one filesystem). docs/robustness.md.
#include <filesystem>
#include <string>
#include <string_view>

namespace diptych {

// Checks an output path before any work, so that a bad path never costs a render or leaves
// some outputs written and others not: its folder must exist (a typo in a folder name is an
// error, not a new tree), an existing path must be a regular file, and it must be writable.
// Throws InputError(option, "", ...) naming the path.
void checkOutputPath(const std::string& option, const std::filesystem::path& path);

// Writes `text` to `path` atomically; throws Error naming the file when it cannot be written
// completely (missing folder, full disk, permissions). The parent folder must exist.
void writeTextFile(const std::filesystem::path& path, std::string_view text);

// An exclusive advisory lock (flock) on DIR/.diptych.lock for the life of the object, so that two
// runs resuming into one output folder cannot interleave their writes. Throws Error naming the
// folder when another process holds it.
class OutputFolderLock {
 public:
  explicit OutputFolderLock(const std::filesystem::path& dir);
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace diptych
