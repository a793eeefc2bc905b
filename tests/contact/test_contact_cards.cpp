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

// The deck (a TITLE line, then `cards`) must fail on line `line` and field `field`, with
// `detail` in the message.
void expect_deck_error(const std::string& cards, int line, const std::string& field,
                       const std::string& detail) {
  const Mesh mesh = test::square_mesh(2);
  try {
    from_text("TITLE card errors\n" + cards + "\n", mesh);
    ADD_FAILURE() << "no error for: " << cards;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.file(), kFile);
    EXPECT_EQ(e.line(), line) << message;
    EXPECT_EQ(e.field(), field) << message;
    EXPECT_NE(message.find(kFile + ":" + std::to_string(line)), std::string::npos) << message;
    EXPECT_NE(message.find(field), std::string::npos) << message;
    EXPECT_NE(message.find(detail), std::string::npos) << message;
  }
}

// The CONTACT card, on line 2 of the deck, must fail on `field`.
void expect_input_error(const std::string& card, const std::string& field,
                        const std::string& detail) {
  expect_deck_error(card, 2, field, detail);
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
  for (int i = 0; i < e->size(); ++i) {
    EXPECT_NEAR(e->gap(i), 0.5, 1e-15); // the old spelling gap= is the wall depth g
    EXPECT_NEAR(e->bound(i), 0.75, 1e-15);
  }
  EXPECT_NEAR(e->weight.sum(), 1.0, 1e-14);
}

TEST(ContactCards, DefaultsAreSignoriniWithoutExtraGap) {
  const auto e =
      from_text("CONTACT ref=3 obstacle=plane point=0,-1 normal=0,1\n", test::square_mesh(2));
  ASSERT_TRUE(e.has_value());
  for (int i = 0; i < e->size(); ++i) {
    EXPECT_EQ(e->law[i], ContactLaw{});
    EXPECT_EQ(e->gap(i), 1.0);
    EXPECT_EQ(e->bound(i), 1.0);
  }
}

// A disc obstacle from the card: if the schema lost centre= or radius=, the deck is refused and
// the test fails (it used to skip itself then, so a schema regression read as SKIP).
TEST(ContactCards, DiscCard) {
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

TEST(ContactCards, LawsAndFriction) {
  const Mesh mesh = test::square_mesh(2);
  const auto e = from_text("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 "
                           "law=compliance-unilateral cn=10 g=0.5\n"
                           "FRICTION ref=3 law=coulomb mu=0.3\n",
                           mesh);
  ASSERT_TRUE(e.has_value());
  EXPECT_TRUE(e->has_friction());
  for (const ContactLaw& law : e->law) {
    EXPECT_EQ(law.normal, NormalLaw::compliance_unilateral);
    EXPECT_EQ(law.cn, 10);
    EXPECT_EQ(law.depth, 0.5);
    EXPECT_EQ(law.c3, INFINITY);
    EXPECT_EQ(law.friction, FrictionLaw::coulomb);
    EXPECT_EQ(law.mu, 0.3);
  }
  const auto t = from_text("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=compliance "
                           "cn=2 c3=1e8\nFRICTION ref=3 law=tresca threshold=4\n",
                           mesh);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->law.front().c3, 1e8);
  EXPECT_EQ(t->law.front().friction, FrictionLaw::tresca);
  EXPECT_EQ(t->law.front().threshold, 4);
  EXPECT_FALSE(from_text("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1\n"
                         "FRICTION ref=3 law=none\n",
                         mesh)
                   ->has_friction());
}

TEST(ContactCards, LawsInVelocity) {
  const Mesh mesh = test::square_mesh(2);
  const auto e = from_text("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 "
                           "law=damped-unilateral cn=10 g=0.01\n",
                           mesh);
  ASSERT_TRUE(e.has_value());
  for (const ContactLaw& law : e->law) {
    EXPECT_EQ(law.normal, NormalLaw::damped_unilateral);
    EXPECT_EQ(law.cn, 10);
    EXPECT_EQ(law.depth, 0.01);
    EXPECT_TRUE(law.in_velocity());
  }
  const auto d =
      from_text("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=damped cn=2\n", mesh);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->law.front().normal, NormalLaw::damped);
  EXPECT_FALSE(d->law.front().has_wall());
}

// exclude= drops the nodes of other references (the clamped ends of Gamma3); the others keep
// their tributary weights.
TEST(ContactCards, ExcludedNodes) {
  const Mesh mesh = test::square_mesh(4);
  const auto all = from_text("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1\n", mesh);
  const auto inner =
      from_text("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 exclude=1,2\n", mesh);
  ASSERT_TRUE(all && inner);
  ASSERT_EQ(all->size(), 5);
  ASSERT_EQ(inner->size(), 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(inner->node[i], all->node[i + 1]);
    EXPECT_EQ(inner->weight[i], 0.25);
    EXPECT_EQ(inner->lagrange_node[i], mesh.num_nodes() + i);
  }
  expect_input_error("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 exclude=9", "exclude",
                     "reference 9 carries no mesh node");
}

TEST(ContactCards, UnknownLaw) {
  expect_input_error("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=tresca", "law",
                     "expected one of signorini|compliance|compliance-unilateral");
}

TEST(ContactCards, BadLawParameters) {
  const std::string plane = "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 ";
  expect_input_error(plane + "law=compliance cn=0", "cn", "> 0");
  expect_input_error(plane + "law=compliance cn=-2", "cn", "> 0");
  expect_input_error(plane + "law=compliance", "cn", "missing");
  expect_input_error(plane + "law=compliance cn=1 c3=0", "c3", "> 0");
  expect_input_error(plane + "law=compliance-unilateral cn=1 g=-0.5", "g", ">= 0");
  expect_input_error(plane + "law=compliance-unilateral cn=1", "g", "depth");
  expect_input_error(plane + "g=1 gap=1", "gap", "once");
  // A field the law does not read.
  expect_input_error(plane + "cn=10", "cn", "not a parameter of law=signorini");
  expect_input_error(plane + "law=compliance cn=10 g=0.5", "g", "not a parameter");
  expect_input_error(plane + "law=damped-unilateral cn=10", "g", "velocity bound");
  expect_input_error(plane + "law=damped cn=10 g=0.5", "g", "not a parameter of law=damped");
  expect_input_error(plane + "law=damped cn=10 c3=5", "c3", "not a parameter of law=damped");
  expect_input_error(plane + "law=damped", "cn", "missing");
  // Chapter 6's truncation c3 <= 0, and the bilateral test law: no truncation, no friction.
  expect_input_error(plane + "law=compliance cn=10 c3=-1e8", "c3", "> 0");
  expect_input_error(plane + "law=compliance-bilateral cn=10 c3=1e8", "c3",
                     "not a parameter of law=compliance-bilateral");
  expect_deck_error(plane + "law=compliance-bilateral cn=10\nFRICTION ref=3 law=coulomb mu=0.2", 3,
                    "law", "is frictionless");
}

// FRICTION on line 3 of a deck with a CONTACT card on line 2 must fail on `field`.
void expect_friction_error(const std::string& friction, const std::string& field,
                           const std::string& detail) {
  expect_deck_error("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1\n" + friction, 3, field,
                    detail);
}

TEST(ContactCards, BadFriction) {
  expect_friction_error("FRICTION ref=3 law=coulomb mu=-0.1", "mu", ">= 0");
  expect_friction_error("FRICTION ref=3 law=coulomb", "mu", "missing");
  expect_friction_error("FRICTION ref=3 law=tresca threshold=-1", "threshold", ">= 0");
  expect_friction_error("FRICTION ref=3 law=coulomb mu=0.2 threshold=1", "threshold",
                        "not a parameter of law=coulomb");
  expect_friction_error("FRICTION ref=2 law=coulomb mu=0.2", "ref", "has no CONTACT card");
  expect_friction_error("FRICTION ref=3 law=viscous", "law",
                        "expected one of none|tresca|coulomb|nonmonotone");
  // Friction without any CONTACT card.
  expect_deck_error("FRICTION ref=3 law=coulomb mu=0.2", 2, "ref", "needs a CONTACT card");
}

TEST(ContactCards, NonmonotoneFrictionAndItsBound) {
  const Mesh mesh = test::square_mesh(2);
  const auto e = from_text("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 "
                           "law=compliance-unilateral cn=10 g=0.5\n"
                           "FRICTION ref=3 law=nonmonotone a=2 b=0.02 alpha=1 bound=compliance\n",
                           mesh);
  ASSERT_TRUE(e.has_value());
  for (const ContactLaw& law : e->law) {
    EXPECT_EQ(law.friction, FrictionLaw::nonmonotone);
    EXPECT_EQ(law.a, 2);
    EXPECT_EQ(law.b, 0.02);
    EXPECT_EQ(law.alpha, 1);
    EXPECT_EQ(law.of, SlipMeasure::slip); // the default
    EXPECT_EQ(law.bound, FrictionBound::compliance);
    EXPECT_EQ(law.mu, 2); // mu(0) = a: the first convex solve starts from no slip
  }
  // Coulomb's bound defaults to the whole normal pressure (1.35), and of=slip-rate is read.
  const auto c = from_text("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1\n"
                           "FRICTION ref=3 law=coulomb mu=0.4\n",
                           mesh);
  EXPECT_EQ(c->law.front().bound, FrictionBound::normal);
  const auto r = from_text("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=compliance "
                           "cn=10\nFRICTION ref=3 law=nonmonotone a=1 b=0.5 alpha=2000 "
                           "of=slip-rate bound=normal\n",
                           mesh);
  EXPECT_EQ(r->law.front().of, SlipMeasure::slip_rate);
  EXPECT_EQ(r->law.front().bound, FrictionBound::normal);
}

TEST(ContactCards, BadNonmonotoneFriction) {
  const std::string compliance = "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 "
                                 "law=compliance-unilateral cn=10 g=0.5\n";
  const auto expect_error = [&](const std::string& friction, const std::string& field,
                                const std::string& detail) {
    expect_deck_error(compliance + friction, 3, field, detail);
  };
  expect_error("FRICTION ref=3 law=nonmonotone a=2 b=0.02 alpha=-1", "alpha", ">= 0");
  expect_error("FRICTION ref=3 law=nonmonotone a=1 b=2 alpha=1", "b", "must be <= a");
  expect_error("FRICTION ref=3 law=nonmonotone b=0.5 alpha=1", "a", "missing");
  expect_error("FRICTION ref=3 law=nonmonotone a=1 alpha=1", "b", "missing");
  expect_error("FRICTION ref=3 law=nonmonotone a=1 b=0.5", "alpha", "missing");
  expect_error("FRICTION ref=3 law=nonmonotone a=-1 b=0 alpha=1", "a", ">= 0");
  expect_error("FRICTION ref=3 law=nonmonotone a=1 b=0.5 alpha=1 mu=0.3", "mu",
               "not a parameter of law=nonmonotone");
  expect_error("FRICTION ref=3 law=nonmonotone a=1 b=0.5 alpha=1 of=speed", "of",
               "expected one of slip|slip-rate");
  expect_error("FRICTION ref=3 law=nonmonotone a=1 b=0.5 alpha=1 bound=wall", "bound",
               "expected one of normal|compliance");
  // The parameters of (1.39) and the bound belong to their laws.
  expect_error("FRICTION ref=3 law=coulomb mu=0.3 a=1", "a", "not a parameter of law=coulomb");
  expect_error("FRICTION ref=3 law=tresca threshold=1 bound=compliance", "bound",
               "not a parameter of law=tresca");
  // Signorini has no compliance pressure to bound the slip by.
  expect_friction_error("FRICTION ref=3 law=coulomb mu=0.3 bound=compliance", "bound",
                        "no compliance pressure");
}

TEST(ContactCards, OtherMistakes) {
  expect_input_error("CONTACT ref=3 obstacle=plane point=0 normal=0,1", "point", "two");
  expect_input_error("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 gap=-1", "gap", ">= 0");
  expect_input_error("CONTACT ref=3 obstacle=disc centre=0,-2 radius=0", "radius", "> 0");
  // The plane x2 = 0.25 cuts the square: its bottom nodes start inside the obstacle.
  expect_input_error("CONTACT ref=3 obstacle=plane point=0,0.25 normal=0,1", "obstacle", "inside");
}

} // namespace
} // namespace sig
