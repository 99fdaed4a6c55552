// JSON string literals for the statistics (bisect/json_text.hpp): a refusal's message carries
// quotes, backslashes and line breaks, and the --stats file must still parse.
#include <gtest/gtest.h>

#include "bisect/json_text.hpp"

namespace bisect {
namespace {

TEST(JsonText, QuotesBackslashesAndControlCharactersAreEscaped) {
  EXPECT_EQ(json_string("plain"), "\"plain\"");
  EXPECT_EQ(json_string("Face \"3\""), "\"Face \\\"3\\\"\"");
  EXPECT_EQ(json_string("C:\\part.step"), "\"C:\\\\part.step\"");
  EXPECT_EQ(json_string("two\nlines"), "\"two\\nlines\"");
  EXPECT_EQ(json_string(std::string("tab\there")), "\"tab\\u0009here\"");
  EXPECT_EQ(json_string(""), "\"\"");
}

}  // namespace
}  // namespace bisect
