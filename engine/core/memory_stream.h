#pragma once
// A read-only view of memory as a stream buffer, for the header checks that read files and
// in-memory images (embedded glTF textures) through one std::istream code path.
#include <cstddef>
#include <ios>
#include <streambuf>

namespace diptych {

// Reading and relative or absolute seeks within the data (the PNG check skips chunk data).
struct MemoryBuffer : std::streambuf {
  MemoryBuffer(const void* data, std::size_t size) {
    char* p = static_cast<char*>(const_cast<void*>(data));
    setg(p, p, p + size);
  }

 protected:
  pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
    const off_type size = egptr() - eback();
    const off_type from = dir == std::ios_base::beg   ? 0
                          : dir == std::ios_base::cur ? gptr() - eback()
                                                      : size;
    if (off < -from || off > size - from) return pos_type(off_type(-1));
    setg(eback(), eback() + from + off, egptr());
    return pos_type(from + off);
  }
  pos_type seekpos(pos_type pos, std::ios_base::openmode mode) override {
    return seekoff(off_type(pos), std::ios_base::beg, mode);
  }
};

}  // namespace diptych
