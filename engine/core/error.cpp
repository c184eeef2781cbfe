#include "engine/core/error.h"

namespace diptych {
namespace {
std::string compose(const std::string& file, const std::string& place, const std::string& msg) {
  std::string out = file.empty() ? std::string("<input>") : file;
  if (!place.empty()) out += ": " + place;
  return out + ": " + msg;
}
}  // namespace

InputError::InputError(std::string file, std::string place, const std::string& message)
    : Error(compose(file, place, message)),
      file_(std::move(file)),
      place_(std::move(place)),
      message_(message) {}

}  // namespace diptych
