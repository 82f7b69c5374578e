#include "core/enum_names.h"

#include <gtest/gtest.h>

namespace slamkit {
namespace {

enum class Colour { kRed, kGreen, kBlue };
constexpr EnumNames<Colour, 3> kColours = {
    {{Colour::kRed, "red"}, {Colour::kGreen, "green"}, {Colour::kBlue, "blue"}}};

TEST(EnumNames, NamesParseBackAndListTheChoices) {
  for (Colour c : {Colour::kRed, Colour::kGreen, Colour::kBlue})
    EXPECT_EQ(value_named(kColours, name_of(kColours, c)), c);
  EXPECT_EQ(value_named(kColours, "Red"), std::nullopt);  // names are exact
  EXPECT_EQ(choices(kColours), "red, green or blue");
}

}  // namespace
}  // namespace slamkit
