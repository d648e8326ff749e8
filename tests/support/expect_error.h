// SPDX-License-Identifier: Apache-2.0
// Asserting on strielad::Error: its code and the parts of the message that name the
// file, variable or axis at fault.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <string_view>

#include "core/error.h"

namespace strielad::testing {

// Runs `f`, expects a strielad::Error with `code` whose message contains every string
// of `parts`; returns the message ("" when nothing or something else was thrown).
template <typename F>
std::string expect_error(F&& f, ErrorCode code, std::initializer_list<std::string_view> parts) {
  try {
    f();
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.code(), code) << "code " << error_code_name(e.code()) << ", wanted "
                              << error_code_name(code) << ": " << message;
    for (std::string_view part : parts) {
      EXPECT_NE(message.find(part), std::string::npos)
          << "message lacks \"" << part << "\": " << message;
    }
    return message;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw something other than strielad::Error: " << e.what();
    return "";
  }
  ADD_FAILURE() << "no error thrown, wanted " << error_code_name(code);
  return "";
}

}  // namespace strielad::testing
