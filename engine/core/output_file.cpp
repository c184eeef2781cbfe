#include "engine/core/output_file.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "engine/core/error.h"

namespace diptych {

void checkOutputPath(const std::string& option, const std::filesystem::path& p) {
  namespace fs = std::filesystem;
  const fs::path parent = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(parent, ec))
    throw InputError(option, "", p.string() + ": folder " + parent.string() + " does not exist");
  if (fs::exists(p, ec) && !fs::is_regular_file(p, ec))
    throw InputError(option, "", p.string() + ": exists and is not a regular file");
  // Open it for appending (access() says yes to root everywhere, even in /proc); remove it
  // again if it did not exist, so that a failed run leaves nothing behind.
  const bool existed = fs::exists(p, ec);
  const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0)
    throw InputError(option, "", p.string() + ": cannot be written (" + std::strerror(errno) + ")");
  ::close(fd);
  if (!existed) fs::remove(p, ec);
}

void writeTextFile(const std::filesystem::path& path, std::string_view text) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw Error(path.string() + ": cannot open for writing (" + std::strerror(errno) + ")");
    out.write(text.data(), std::streamsize(text.size()));
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw Error(path.string() + ": write failed (disk full or I/O error)");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw Error(path.string() + ": cannot replace the file (" + ec.message() + ")");
  }
}

OutputFolderLock::OutputFolderLock(const std::filesystem::path& dir) {
  const std::string lockPath = (dir / ".diptych.lock").string();
  fd_ = ::open(lockPath.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw Error(dir.string() + ": cannot create the lock file .diptych.lock (" +
                std::strerror(errno) + ")");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    throw Error(dir.string() + ": " +
                (err == EWOULDBLOCK ? std::string("another diptych run is writing to this folder")
                                    : std::string("cannot lock (") + std::strerror(err) + ")"));
  }
}

OutputFolderLock::~OutputFolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the flock
}

}  // namespace diptych
