#include "engine/scene/gltf/accessors.h"

#include <cmath>
#include <cstring>

#include "engine/core/error.h"

namespace diptych::gltf {
namespace {

// An accessor without a bufferView is all zeros (before sparse substitution); cap its size so
// a hostile count cannot make us allocate terabytes.
constexpr std::uint64_t kMaxElementsWithoutBuffer = std::uint64_t(1) << 26;

[[noreturn]] void fail(const AccessorSite& site, int accessor, const std::string& message) {
  throw InputError(site.file, site.place, "accessor " + std::to_string(accessor) + ": " + message);
}

int componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

// Decodes one component. Normalized conversions are the spec's (3.11): e.g. signed byte
// f = max(c / 127, -1), unsigned short f = c / 65535.
float decodeComponent(const unsigned char* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? *p / 255.f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const auto c = static_cast<std::int8_t>(*p);
      return normalized ? std::max(c / 127.f, -1.f) : float(c);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t c;
      std::memcpy(&c, p, 2);
      return normalized ? c / 65535.f : float(c);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      std::int16_t c;
      std::memcpy(&c, p, 2);
      return normalized ? std::max(c / 32767.f, -1.f) : float(c);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t c;
      std::memcpy(&c, p, 4);
      return float(c);
    }
    default:
      return 0.f;
  }
}

std::uint32_t decodeIndex(const unsigned char* p, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t c;
      std::memcpy(&c, p, 2);
      return c;
    }
    default: {
      std::uint32_t c;
      std::memcpy(&c, p, 4);
      return c;
    }
  }
}

// A validated window into a buffer: `count` elements of `elementSize` bytes, `stride` apart.
struct ByteRange {
  const unsigned char* first = nullptr;
  std::uint64_t stride = 0;
};

// Checks that every byte of `count` elements lies inside both the bufferView and its buffer.
ByteRange resolve(const tinygltf::Model& model, int viewIndex, std::uint64_t byteOffset,
                  std::uint64_t stride, std::uint64_t elementSize, std::uint64_t count,
                  const AccessorSite& site, int accessor, const char* what) {
  if (viewIndex < 0 || viewIndex >= int(model.bufferViews.size()))
    fail(site, accessor,
         std::string(what) + " bufferView " + std::to_string(viewIndex) + " does not exist");
  const tinygltf::BufferView& view = model.bufferViews[viewIndex];
  if (view.buffer < 0 || view.buffer >= int(model.buffers.size()))
    fail(site, accessor,
         "bufferViews[" + std::to_string(viewIndex) + "].buffer " + std::to_string(view.buffer) +
             " does not exist");
  const std::vector<unsigned char>& data = model.buffers[view.buffer].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
    fail(site, accessor,
         "bufferViews[" + std::to_string(viewIndex) + "] extends past the end of " + "buffer " +
             std::to_string(view.buffer));
  if (count > 0) {
    // Last byte read: byteOffset + (count-1)*stride + elementSize; all terms are < 2^40 in any
    // real file, and we reject anything larger before multiplying.
    const std::uint64_t limit = std::uint64_t(1) << 40;
    if (count > limit || stride > limit || byteOffset > limit ||
        byteOffset + (count - 1) * stride + elementSize > view.byteLength)
      fail(site, accessor,
           std::string(what) + " reads " + std::to_string(count) +
               " elements past the end of bufferViews[" + std::to_string(viewIndex) +
               "] (byteLength " + std::to_string(view.byteLength) + ")");
  }
  return {data.data() + view.byteOffset + byteOffset, stride};
}

struct Layout {
  int components = 0;
  int componentBytes = 0;
  std::uint64_t elementBytes() const { return std::uint64_t(components) * componentBytes; }
};

Layout checkLayout(const tinygltf::Model& model, int index, const AccessorSite& site) {
  if (index < 0 || index >= int(model.accessors.size()))
    throw InputError(site.file, site.place,
                     "accessor " + std::to_string(index) + " does not exist (file has " +
                         std::to_string(model.accessors.size()) + ")");
  const tinygltf::Accessor& acc = model.accessors[index];
  Layout layout{tinygltf::GetNumComponentsInType(acc.type), componentSize(acc.componentType)};
  if (layout.components <= 0) fail(site, index, "unknown accessor type");
  if (layout.componentBytes <= 0) fail(site, index, "unknown componentType");
  return layout;
}

// Calls visit(elementIndex, bytes) for every element, dense part first, then sparse values
// replacing their elements (spec 3.6.2.3).
template <typename Visit>
void forEachElement(const tinygltf::Model& model, int index, const Layout& layout,
                    const AccessorSite& site, Visit&& visit) {
  const tinygltf::Accessor& acc = model.accessors[index];
  const std::uint64_t count = acc.count;
  if (acc.bufferView >= 0) {
    const tinygltf::BufferView& view = acc.bufferView < int(model.bufferViews.size())
                                           ? model.bufferViews[acc.bufferView]
                                           : tinygltf::BufferView{};
    const std::uint64_t stride = view.byteStride ? view.byteStride : layout.elementBytes();
    if (view.byteStride && view.byteStride < layout.elementBytes())
      fail(site, index,
           "byteStride " + std::to_string(view.byteStride) + " is smaller than one element");
    const ByteRange range = resolve(model, acc.bufferView, acc.byteOffset, stride,
                                    layout.elementBytes(), count, site, index, "data");
    for (std::uint64_t i = 0; i < count; ++i) visit(i, range.first + i * range.stride);
  } else if (count > kMaxElementsWithoutBuffer) {
    fail(site, index, "count " + std::to_string(count) + " without a bufferView is implausible");
  }
  if (!acc.sparse.isSparse) return;
  const auto sparseCount = std::uint64_t(std::max(acc.sparse.count, 0));
  if (sparseCount > count) fail(site, index, "sparse.count exceeds accessor count");
  const int indexType = acc.sparse.indices.componentType;
  const int indexBytes = componentSize(indexType);
  if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail(site, index, "sparse.indices.componentType is not an unsigned integer type");
  const ByteRange where =
      resolve(model, acc.sparse.indices.bufferView, acc.sparse.indices.byteOffset, indexBytes,
              indexBytes, sparseCount, site, index, "sparse.indices");
  const ByteRange values = resolve(
      model, acc.sparse.values.bufferView, acc.sparse.values.byteOffset, layout.elementBytes(),
      layout.elementBytes(), sparseCount, site, index, "sparse.values");
  for (std::uint64_t k = 0; k < sparseCount; ++k) {
    const std::uint32_t target = decodeIndex(where.first + k * where.stride, indexType);
    if (target >= count)
      fail(site, index,
           "sparse.indices[" + std::to_string(k) + "] = " + std::to_string(target) +
               " is out of range");
    visit(target, values.first + k * values.stride);
  }
}

// Rejects counts that cannot fit in their bufferView before anything is allocated for them; the
// exact byte-range check happens in resolve().
void checkCountBeforeAllocating(const tinygltf::Model& model, int index, const AccessorSite& site) {
  const tinygltf::Accessor& acc = model.accessors[index];
  const bool hasView = acc.bufferView >= 0 && acc.bufferView < int(model.bufferViews.size());
  const std::uint64_t cap =
      hasView ? model.bufferViews[acc.bufferView].byteLength : kMaxElementsWithoutBuffer;
  if (std::uint64_t(acc.count) > cap)
    fail(site, index, "count " + std::to_string(acc.count) + " cannot fit in its data");
}

}  // namespace

std::vector<float> readFloatAccessor(const tinygltf::Model& model, int index, int components,
                                     const AccessorSite& site) {
  const Layout layout = checkLayout(model, index, site);
  if (layout.components != components)
    fail(site, index,
         "has " + std::to_string(layout.components) + " components, expected " +
             std::to_string(components));
  const tinygltf::Accessor& acc = model.accessors[index];
  checkCountBeforeAllocating(model, index, site);
  std::vector<float> out(std::size_t(acc.count) * components, 0.f);
  forEachElement(model, index, layout, site, [&](std::uint64_t i, const unsigned char* bytes) {
    for (int c = 0; c < components; ++c)
      out[i * components + c] =
          decodeComponent(bytes + c * layout.componentBytes, acc.componentType, acc.normalized);
  });
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!std::isfinite(out[i]))
      fail(site, index,
           "non-finite value " + std::to_string(out[i]) + " at element " +
               std::to_string(i / components) + " component " + std::to_string(i % components));
  }
  return out;
}

std::vector<std::uint32_t> readIndexAccessor(const tinygltf::Model& model, int index,
                                             const AccessorSite& site) {
  const Layout layout = checkLayout(model, index, site);
  const tinygltf::Accessor& acc = model.accessors[index];
  if (layout.components != 1) fail(site, index, "indices must be SCALAR");
  if (acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail(site, index, "indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  checkCountBeforeAllocating(model, index, site);
  std::vector<std::uint32_t> out(acc.count, 0);
  forEachElement(model, index, layout, site, [&](std::uint64_t i, const unsigned char* bytes) {
    out[i] = decodeIndex(bytes, acc.componentType);
  });
  return out;
}

}  // namespace diptych::gltf
