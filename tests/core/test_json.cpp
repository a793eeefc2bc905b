// The JSON writer: escaping, number formatting (integers plain, others read back exactly), key
// order, layout.
#include "core/error.hpp"
#include "core/json.hpp"

#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>
#include <limits>

namespace sig {
namespace {

std::string one_line(const Json& j) {
  return j.dump(-1);
}

TEST(Json, StringsAreEscaped) {
  EXPECT_EQ(one_line(Json("plain")), "\"plain\"");
  EXPECT_EQ(one_line(Json("say \"hi\"")), "\"say \\\"hi\\\"\"");
  EXPECT_EQ(one_line(Json("C:\\out\\x")), "\"C:\\\\out\\\\x\"");
  EXPECT_EQ(one_line(Json("a\nb\tc\rd\be\ff")), "\"a\\nb\\tc\\rd\\be\\ff\"");
  EXPECT_EQ(one_line(Json(std::string("\x01\x1f", 2))), "\"\\u0001\\u001f\"");
  EXPECT_EQ(one_line(Json(std::string("nul\0", 4))), "\"nul\\u0000\"");
  EXPECT_EQ(one_line(Json("\xc3\xa9t\xc3\xa9 / \x7f")),
            "\"\xc3\xa9t\xc3\xa9 / \x7f\""); // UTF-8 as is
  Json o = Json::object();
  o.set("key \"q\"", 1);
  EXPECT_EQ(one_line(o), "{\"key \\\"q\\\"\":1}");
}

TEST(Json, IntegralNumbersHaveNoDecimalPoint) {
  EXPECT_EQ(one_line(Json(3.0)), "3");
  EXPECT_EQ(one_line(Json(-7)), "-7");
  EXPECT_EQ(one_line(Json(0.0)), "0");
  EXPECT_EQ(one_line(Json(97404L)), "97404");
  EXPECT_EQ(one_line(Json(999999999999999.0)), "999999999999999");
  // From 1e15 up, integral values use the general form; it must still read back exactly.
  const std::string big = one_line(Json(1e15));
  EXPECT_EQ(std::strtod(big.c_str(), nullptr), 1e15);
}

TEST(Json, OtherNumbersReadBackExactlyWithAtMost17Digits) {
  const double values[] = {0.1,
                           1.0 / 3.0,
                           -2.5e-7,
                           14.487,
                           6.02214076e23,
                           1e-300,
                           1e300,
                           std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(),
                           -0.5,
                           123456.789};
  for (const double x : values) {
    const std::string text = one_line(Json(x));
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), x) << text;
    std::size_t digits = 0;
    for (const char c : text.substr(0, text.find_first_of("eE")))
      digits += std::isdigit(c) != 0;
    EXPECT_LE(digits, 18u) << text; // 17 significant + a possible leading "0."
    EXPECT_EQ(text.find_first_not_of("0123456789.eE+-"), std::string::npos) << text;
  }
  EXPECT_EQ(one_line(Json(0.1)), "0.1"); // shortest form, not 0.10000000000000001
  EXPECT_EQ(one_line(Json(-2.5)), "-2.5");
}

TEST(Json, NonFiniteNumbersAreNull) {
  EXPECT_EQ(one_line(Json(std::nan(""))), "null");
  EXPECT_EQ(one_line(Json(std::numeric_limits<double>::infinity())), "null");
  EXPECT_EQ(one_line(Json(-std::numeric_limits<double>::infinity())), "null");
}

TEST(Json, ObjectsKeepInsertionOrderAndSetReplaces) {
  Json o = Json::object();
  o.set("zeta", 1).set("alpha", true).set("mid", nullptr);
  o.set("zeta", "replaced");
  EXPECT_EQ(one_line(o), "{\"zeta\":\"replaced\",\"alpha\":true,\"mid\":null}");
  Json not_object(1.5);
  EXPECT_THROW(not_object.set("k", 1), Error);
  EXPECT_THROW(Json::array_of(std::vector<int>{1}).set("k", 1), Error);
}

TEST(Json, IndentedLayout) {
  Json o = Json::object();
  o.set("scene", "hertz");
  o.set("iterations", Json::array_of(std::vector<int>{3, 4}));
  o.set("empty", Json::Array{});
  o.set("nested", Json::object().set("ok", false));
  o.set("none", Json::object());
  EXPECT_EQ(o.dump(2), "{\n"
                       "  \"scene\": \"hertz\",\n"
                       "  \"iterations\": [\n"
                       "    3,\n"
                       "    4\n"
                       "  ],\n"
                       "  \"empty\": [],\n"
                       "  \"nested\": {\n"
                       "    \"ok\": false\n"
                       "  },\n"
                       "  \"none\": {}\n"
                       "}");
  EXPECT_EQ(o.dump(-1),
            "{\"scene\":\"hertz\",\"iterations\":[3,4],\"empty\":[],\"nested\":{\"ok\":false},"
            "\"none\":{}}");
  EXPECT_EQ(Json().dump(), "null");
}

} // namespace
} // namespace sig

namespace sig {
namespace {

// JSON output is valid UTF-8 whatever a string holds: bad bytes become U+FFFD, good sequences
// (2, 3 and 4 bytes) pass unchanged; overlong forms and surrogates are bad bytes.
TEST(JsonUtf8, BadBytesAreReplaced) {
  std::size_t replaced = 0;
  EXPECT_EQ(valid_utf8("\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80 ok", &replaced),
            "\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80 ok");
  EXPECT_EQ(replaced, 0u);
  EXPECT_EQ(valid_utf8("caf\xe9!", &replaced), "caf\xef\xbf\xbd!");
  EXPECT_EQ(replaced, 1u);
  std::string seven;
  for (int k = 0; k < 7; ++k)
    seven += "\xef\xbf\xbd";
  EXPECT_EQ(valid_utf8("\xc0\xaf\xed\xa0\x80\xe2\x82", &replaced), seven);
  EXPECT_EQ(replaced, 7u); // overlong '/', a surrogate, a cut sequence: every byte replaced
  const std::string json = Json(Json::Object{{"title", "caf\xe9"}}).dump(-1);
  EXPECT_EQ(json, "{\"title\":\"caf\xef\xbf\xbd\"}");
}

} // namespace
} // namespace sig
