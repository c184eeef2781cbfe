#include "engine/core/input_file.h"

#include <fstream>
#include <system_error>

#include "engine/core/error.h"

namespace diptych {

std::uintmax_t checkInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);  // follows links: judge the target
  if (ec || status.type() == fs::file_type::not_found)
    throw InputError(path.string(), "", "file not found");
  if (status.type() == fs::file_type::directory)
    throw InputError(path.string(), "", "is a directory, expected a file");
  if (status.type() != fs::file_type::regular)
    throw InputError(path.string(), "",
                     "not a regular file (a device, FIFO or socket is never read)");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw InputError(path.string(), "", "cannot read file size: " + ec.message());
  if (size > maxBytes)
    throw InputError(
        path.string(), "",
        "file is " + std::to_string(size) + " bytes; the limit is " + std::to_string(maxBytes));
  return size;
}

std::string readInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes) {
  const std::uintmax_t size = checkInputFile(path, maxBytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot open file");
  std::string text(size, '\0');
  in.read(text.data(), std::streamsize(size));
  if (in.bad() || std::uintmax_t(in.gcount()) != size)
    throw InputError(path.string(), "", "cannot read file (it changed while being read?)");
  return text;
}

}  // namespace diptych
