#pragma once
// A structural check of a PNG's chunk list before OpenImageIO opens it. OpenImageIO 2.4's PNG
// read callback, on a short read, builds its error text in a std::string and then longjmps out
// through libpng's png_error, leaking the string (31 bytes per truncated file, found by
// fuzz_image; docs/robustness.md). A file whose every chunk lies inside it, up to IEND, never
// makes libpng read past the end, so truncated files get our named error instead. Layout: PNG
// specification (ISO/IEC 15948, W3C 2003), section 5: the signature 89 50 4E 47 0D 0A 1A 0A, then
// chunks of a 4-byte big-endian length (at most 2^31 - 1), a 4-byte type, the data and a CRC.
#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>

namespace diptych {

// The problem with the chunk list read from `in` (the stream of a file of `size` bytes) in one
// line, naming the chunk and its byte offset; empty when every chunk up to IEND lies inside the
// file or the data is not PNG at all (other formats are left to their readers).
std::string pngChunkProblem(std::istream& in, std::uint64_t size);
std::string pngChunkProblem(const void* data, std::size_t size);

}  // namespace diptych
