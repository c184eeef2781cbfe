#include "engine/core/exr_header.h"

#include <array>

#include "engine/core/memory_stream.h"

namespace diptych {
namespace {

constexpr std::array<unsigned char, 4> kMagic = {0x76, 0x2f, 0x31, 0x01};
constexpr std::uint32_t kLongNames = 0x400, kMultiPart = 0x1000;
// Far above any real file (OpenEXR's standard attributes are about 20) and low enough that a
// header of empty attributes is rejected long before it costs anything.
constexpr int kMaxAttributes = 1 << 16;

std::uint32_t littleEndian32(const unsigned char* b) {
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
         std::uint32_t(b[3]) << 24;
}

// Reads a NUL-terminated string of at most maxLength characters; false when it is longer or the
// stream ends first.
bool readName(std::istream& in, std::size_t maxLength, std::string& out, std::uint64_t& offset) {
  out.clear();
  for (;;) {
    const int c = in.get();
    if (c == std::char_traits<char>::eof()) return false;
    ++offset;
    if (c == 0) return true;
    if (out.size() == maxLength) return false;
    out.push_back(char(c));
  }
}

}  // namespace

std::string exrHeaderProblem(std::istream& in, std::uint64_t size) {
  unsigned char head[8];
  if (!in.read(reinterpret_cast<char*>(head), 8)) return "";
  for (std::size_t i = 0; i < kMagic.size(); ++i)
    if (head[i] != kMagic[i]) return "";
  const std::uint32_t flags = littleEndian32(head + 4) & ~0xffu;
  const std::size_t maxName = (flags & kLongNames) ? 255 : 31;
  std::uint64_t offset = 8;
  std::string name, type;
  int attributes = 0;
  for (int header = 0;; ++header) {
    int inHeader = 0;
    for (;;) {
      const std::uint64_t at = offset;
      if (!readName(in, maxName, name, offset))
        return "EXR header: attribute name at byte " + std::to_string(at) +
               " is unterminated or longer than " + std::to_string(maxName) + " characters";
      if (name.empty()) break;
      if (!readName(in, maxName, type, offset))
        return "EXR header: type of attribute '" + name + "' at byte " + std::to_string(at) +
               " is unterminated or too long";
      unsigned char sizeBytes[4];
      if (!in.read(reinterpret_cast<char*>(sizeBytes), 4))
        return "EXR header: attribute '" + name + "' at byte " + std::to_string(at) +
               " is truncated";
      offset += 4;
      const auto declared = std::int32_t(littleEndian32(sizeBytes));
      if (declared < 0 || std::uint64_t(declared) > size - offset)
        return "EXR header: attribute '" + name + "' (" + type + ") at byte " + std::to_string(at) +
               " declares " + std::to_string(declared) + " bytes, more than the " +
               std::to_string(size - offset) + " left in the file";
      in.ignore(declared);
      offset += std::uint64_t(declared);
      if (++attributes > kMaxAttributes)
        return "EXR header: more than " + std::to_string(kMaxAttributes) + " attributes";
      ++inHeader;
    }
    // A single-part header ends at its empty name; a multi-part list ends at an empty header.
    if (!(flags & kMultiPart) || inHeader == 0) return "";
  }
}

std::string exrHeaderProblem(const void* data, std::size_t size) {
  MemoryBuffer buffer(data, size);
  std::istream in(&buffer);
  return exrHeaderProblem(in, size);
}

}  // namespace diptych
