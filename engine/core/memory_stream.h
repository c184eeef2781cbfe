#pragma once
// A read-only view of memory as a stream buffer, for the header checks that read files and
// in-memory images (embedded glTF textures) through one std::istream code path.
#include <cstddef>
#include <streambuf>

namespace diptych {

// get/ignore only: the checks never seek.
struct MemoryBuffer : std::streambuf {
  MemoryBuffer(const void* data, std::size_t size) {
    char* p = static_cast<char*>(const_cast<void*>(data));
    setg(p, p, p + size);
  }
};

}  // namespace diptych
