// The CONTACT card: a valid card builds the elements it describes; each mistake is an InputError
// naming the file, the line and the field.
#include "contact/contact_elements.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "square_mesh.hpp"

#include <gtest/gtest.h>
#include <string>

namespace sig {
namespace {

const std::string kFile = "deck.dat";

std::optional<ContactElements> from_text(const std::string& text, const Mesh& mesh) {
  return contact_from_cards(Datafile::parse(text, kFile), mesh);
}

// The card on line 2 of the deck must fail on `field`, with `detail` in the message.
void expect_input_error(const std::string& card, const std::string& field,
                        const std::string& detail) {
  const Mesh mesh = test::square_mesh(2);
  try {
    from_text("TITLE card errors\n" + card + "\n", mesh);
    ADD_FAILURE() << "no error for: " << card;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.file(), kFile);
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.field(), field) << message;
    EXPECT_NE(message.find(kFile + ":2"), std::string::npos) << message;
    EXPECT_NE(message.find(field), std::string::npos) << message;
    EXPECT_NE(message.find(detail), std::string::npos) << message;
  }
}

TEST(ContactCards, NoCardMeansNoContact) {
  EXPECT_FALSE(from_text("TITLE no contact\n", test::square_mesh(2)).has_value());
}

TEST(ContactCards, PlaneCardBuildsTheElements) {
  const Mesh mesh = test::square_mesh(4, 1.0, 0.5);
  const auto e =
      from_text("# lifted square over the foundation x2 <= 0\n"
                "CONTACT ref=3 obstacle=plane point=0,0 normal=0,2 law=Signorini gap=0.25\n",
                mesh);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->size(), 5);
  EXPECT_EQ(e->ref, 3);
  EXPECT_EQ(e->obstacle.kind, "plane");
  EXPECT_EQ(e->obstacle.normal, Eigen::Vector2d(0, 1)); // normalized
  for (int i = 0; i < e->size(); ++i)
    EXPECT_NEAR(e->gap(i), 0.75, 1e-15);
  EXPECT_NEAR(e->weight.sum(), 1.0, 1e-14);
}

TEST(ContactCards, DefaultsAreSignoriniWithoutExtraGap) {
  const auto e =
      from_text("CONTACT ref=3 obstacle=plane point=0,-1 normal=0,1\n", test::square_mesh(2));
  ASSERT_TRUE(e.has_value());
  for (int i = 0; i < e->size(); ++i) {
    EXPECT_EQ(e->law[i], kLawSignorini);
    EXPECT_EQ(e->gap(i), 1.0);
  }
}

// Disc obstacles need the fields centre= and radius= in the CONTACT card schema (core cards.cpp).
bool schema_has_disc_fields() {
  for (const CardSpec& spec : card_schema()) {
    if (std::string(spec.keyword) != "CONTACT") continue;
    int found = 0;
    for (const FieldSpec& field : spec.fields)
      found += std::string(field.name) == "centre" || std::string(field.name) == "radius";
    return found == 2;
  }
  return false;
}

TEST(ContactCards, DiscCard) {
  if (!schema_has_disc_fields())
    GTEST_SKIP() << "CONTACT card schema lacks centre= and radius= (core cards.cpp)";
  const auto e =
      from_text("CONTACT ref=3 obstacle=disc centre=0.5,-2 radius=2\n", test::square_mesh(2));
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->obstacle.kind, "disc");
  EXPECT_EQ(e->gap(1), 0.0); // the bottom centre (0.5, 0) touches the disc
}

TEST(ContactCards, BadReferenceListsThePresentOnes) {
  expect_input_error("CONTACT ref=7 obstacle=plane point=0,0 normal=0,1", "ref",
                     "references on edges: 1 2 3");
}

TEST(ContactCards, ZeroNormal) {
  expect_input_error("CONTACT ref=3 obstacle=plane point=0,0 normal=0,0", "normal", "zero-length");
}

TEST(ContactCards, UnknownLaw) {
  expect_input_error("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=tresca", "law",
                     "law 'tresca' is not implemented; known: signorini");
}

TEST(ContactCards, OtherMistakes) {
  expect_input_error("CONTACT ref=3 obstacle=plane point=0 normal=0,1", "point", "two");
  expect_input_error("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 gap=-1", "gap", ">= 0");
  if (schema_has_disc_fields())
    expect_input_error("CONTACT ref=3 obstacle=disc centre=0,-2 radius=0", "radius", "> 0");
  // The plane x2 = 0.25 cuts the square: its bottom nodes start inside the obstacle.
  expect_input_error("CONTACT ref=3 obstacle=plane point=0,0.25 normal=0,1", "obstacle", "inside");
}

} // namespace
} // namespace sig
