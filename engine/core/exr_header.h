#pragma once
// A structural check of an OpenEXR header before OpenImageIO opens the file. OpenEXR allocates
// every attribute's declared size while it reads the header, before any image spec exists, so a
// 600-byte file declaring a 2 GB attribute costs seconds and gigabytes (docs/robustness.md,
// found by fuzz_image). Layout: OpenEXR "File Layout" document, section "Header": magic
// 76 2f 31 01, a 4-byte version with flags (0x400 long names, 0x1000 multi-part), then per
// header a list of (name\0, type\0, int32 size, size bytes) ended by an empty name, and for
// multi-part files a list of headers ended by an empty header.
#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>

namespace diptych {

// The problem with the EXR header read from `in` (the stream of a file of `size` bytes) in one
// line, naming the attribute and its byte offset; empty when the header is consistent or the
// data is not EXR at all (other formats are left to their readers).
std::string exrHeaderProblem(std::istream& in, std::uint64_t size);
std::string exrHeaderProblem(const void* data, std::size_t size);

}  // namespace diptych
