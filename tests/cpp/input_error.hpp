// Shared by the tests of every reader and writer: what an InputError says.
#pragma once
#include <gtest/gtest.h>

#include <exception>
#include <string>

#include "bisect/errors.hpp"

namespace bisect::test {

// The message of the InputError that `f` throws, checked to be one line; fails the test when
// `f` throws nothing or something else.
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << "one line: " << m;
    return m;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not an InputError: " << e.what();
    return "";
  }
  ADD_FAILURE() << "no error";
  return "";
}

}  // namespace bisect::test

#define EXPECT_HAS(message, part) EXPECT_NE((message).find(part), std::string::npos) << (message)
