#pragma once
// RefusedSetting: a render setting the renderer or its OpenGL driver cannot
// draw (bad input, exit 2), with the name the scene file gives it under
// "render" ("resolution", "msaa"), so that the caller can point at the field.
#include <string>
#include <utility>

#include "core/error.h"

namespace recoil::render {

class RefusedSetting : public Error {
 public:
  RefusedSetting(std::string field, const std::string& message)
      : Error(ErrorKind::bad_input, message), m_field(std::move(field)) {}
  const std::string& field() const { return m_field; }

 private:
  std::string m_field;
};

}  // namespace recoil::render
