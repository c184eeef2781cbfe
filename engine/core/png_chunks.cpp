#include "engine/core/png_chunks.h"

#include <array>

#include "engine/core/memory_stream.h"

namespace diptych {
namespace {

constexpr std::array<unsigned char, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr std::uint32_t kMaxChunkLength = 0x7fffffffu;  // PNG spec 5.3: "limited to 2^31 - 1"

std::uint32_t bigEndian32(const unsigned char* b) {
  return std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 |
         std::uint32_t(b[3]);
}

// The chunk type as text when it is four letters (as the spec requires), else as hex bytes.
std::string typeName(const unsigned char* t) {
  std::string name;
  bool letters = true;
  for (int i = 0; i < 4; ++i) letters = letters && ((t[i] | 0x20) >= 'a' && (t[i] | 0x20) <= 'z');
  if (letters) return "'" + std::string(reinterpret_cast<const char*>(t), 4) + "'";
  static const char* const kHex = "0123456789abcdef";
  for (int i = 0; i < 4; ++i) name += std::string("\\x") + kHex[t[i] >> 4] + kHex[t[i] & 15];
  return "'" + name + "'";
}

}  // namespace

std::string pngChunkProblem(std::istream& in, std::uint64_t size) {
  unsigned char head[8];
  if (!in.read(reinterpret_cast<char*>(head), 8)) return "";
  for (std::size_t i = 0; i < kSignature.size(); ++i)
    if (head[i] != kSignature[i]) return "";
  std::uint64_t offset = 8;
  for (;;) {
    unsigned char lengthAndType[8];
    if (!in.read(reinterpret_cast<char*>(lengthAndType), 8))
      return "PNG is truncated: the file ends at byte " + std::to_string(size) +
             " inside or before a chunk header, with no IEND chunk";
    const std::uint32_t length = bigEndian32(lengthAndType);
    const std::string type = typeName(lengthAndType + 4);
    if (length > kMaxChunkLength)
      return "PNG chunk " + type + " at byte " + std::to_string(offset) + " declares " +
             std::to_string(length) + " bytes, more than the format's 2^31 - 1";
    // The data and its 4-byte CRC must lie inside the file.
    const std::uint64_t end = offset + 8 + std::uint64_t(length) + 4;
    if (end > size)
      return "PNG is truncated: chunk " + type + " at byte " + std::to_string(offset) + " needs " +
             std::to_string(end - offset) + " bytes, the file has " +
             std::to_string(size - offset) + " left";
    if (type == "'IEND'") return "";
    in.ignore(std::streamsize(length) + 4);
    offset = end;
  }
}

std::string pngChunkProblem(const void* data, std::size_t size) {
  MemoryBuffer buffer(data, size);
  std::istream in(&buffer);
  return pngChunkProblem(in, size);
}

}  // namespace diptych
