#pragma once
// Errors the engine reports. Every error about an input names the file and the element in it,
// so a user can find the problem without a debugger.
#include <stdexcept>
#include <string>

namespace diptych {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A problem in something the user gave us: a scene, a recipe, an image, an option.
// what() reads "FILE: PLACE: MESSAGE" (PLACE omitted when empty).
class InputError : public Error {
 public:
  InputError(std::string file, std::string place, const std::string& message);
  const std::string& file() const { return file_; }
  const std::string& place() const { return place_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_, place_, message_;
};

}  // namespace diptych
