#pragma once
// One measured result of a validation check: printed on its own line and
// recorded as a property of the running test (measured_1, measured_2, ...),
// which `make validation-doc` reads from the suite's JSON output into
// docs/validation.md. Used as a temporary, `Measured() << ... ;`, or as a
// named value that records when it goes out of scope.
#include <gtest/gtest.h>

#include <iostream>
#include <sstream>
#include <string>

namespace recoil::sim::validation {

class Measured {
 public:
  Measured() = default;
  Measured(const Measured&) = delete;
  Measured& operator=(const Measured&) = delete;
  ~Measured() {
    std::string text = m_text.str();
    while (!text.empty() && text.back() == '\n') text.pop_back();
    std::cout << text << "\n";
    const testing::TestInfo* test = testing::UnitTest::GetInstance()->current_test_info();
    if (test == nullptr) return;
    // Numbered per test, so a check measured in a loop keeps every line.
    static const testing::TestInfo* last = nullptr;
    static int count = 0;
    count = test == last ? count + 1 : 1;
    last = test;
    testing::Test::RecordProperty("measured_" + std::to_string(count), text);
  }
  template <class T>
  Measured& operator<<(const T& value) {
    m_text << value;
    return *this;
  }
  Measured& operator<<(std::ios_base& (*manipulator)(std::ios_base&)) {
    m_text << manipulator;
    return *this;
  }

 private:
  std::ostringstream m_text;
};

}  // namespace recoil::sim::validation
