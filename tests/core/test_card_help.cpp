// The card schema as the single source of help texts and defaults: the accessors read a field's
// default from it, --help and sig-dump --cards print it, and a stage's help lists its cards.
#include "core/card_help.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "core/stage.hpp"

#include <gtest/gtest.h>
#include <sstream>

namespace sig {
namespace {

TEST(CardDefaults, AnAbsentFieldTakesTheSchemaDefaultAndARequiredOneFails) {
  const Datafile deck =
      Datafile::parse("MATERIAL E=1 nu=0.3\nTIME scheme=midpoint T=1 k=0.1\n", "d.dat");
  const Card& material = deck.require("MATERIAL");
  EXPECT_FALSE(material.has("thickness")); // a default is not a given field
  EXPECT_EQ(material.real("thickness"), 1.0);
  EXPECT_EQ(material.choice("plane", {"strain", "stress"}), "strain");
  EXPECT_EQ(material.real("thickness", 7.0), 7.0); // an explicit fallback wins
  EXPECT_EQ(deck.require("TIME").integer("output_every"), 1);
  try {
    deck.require("TIME").real("T2"); // not a schema field
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
  }
  const Datafile no_e = Datafile::parse("MATERIAL nu=0.3\n", "d.dat");
  EXPECT_THROW(no_e.require("MATERIAL").real("E"), InputError); // required: no default
}

TEST(CardDefaults, EveryDefaultIsAValueItsFieldAccepts) {
  // A default that does not parse would only fail in the deck of a user who left it out.
  for (const CardSpec& spec : card_schema()) {
    for (const FieldSpec& field : spec.fields) {
      if (field.fallback == nullptr) continue;
      const std::string line = std::string(spec.keyword) + " " + field.name + "=" + field.fallback;
      EXPECT_NO_THROW(Datafile::parse(line + "\n", "d.dat")) << line;
    }
  }
}

TEST(CardHelp, WrapsAtTheWidthAndIndentsContinuationLines) {
  const std::string text = wrap_text("aaa bbb ccc ddd eee", 2, 4, 12);
  EXPECT_EQ(text, "aaa bbb\n    ccc ddd\n    eee\n");
  std::istringstream lines(wrap_text(std::string(300, 'x') + " y", 0, 2, 20));
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line.size(), 300u); // a long word stays whole
  std::getline(lines, line);
  EXPECT_EQ(line, "  y");
}

TEST(CardHelp, ACardShowsEveryFieldWithItsHelpAndDefault) {
  const std::string text = card_help(*find_card_spec("material"));
  EXPECT_EQ(text.rfind("MATERIAL (repeatable): ", 0), 0u) << text;
  for (const FieldSpec& field : find_card_spec("MATERIAL")->fields)
    EXPECT_NE(text.find(std::string("    ") + field.name + " "), std::string::npos) << field.name;
  EXPECT_NE(text.find("[default: hooke]"), std::string::npos) << text;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    EXPECT_LE(line.size(), 100u) << line;
  const std::string index = card_index();
  for (const CardSpec& spec : card_schema())
    EXPECT_NE(index.find(std::string("  ") + spec.keyword + " "), std::string::npos)
        << spec.keyword;
}

TEST(CardReference, MarkdownHasEveryCardAndFieldWithDefaultAndRange) {
  const std::string text = card_reference_markdown();
  for (const CardSpec& spec : card_schema()) {
    EXPECT_NE(text.find(std::string("\n## ") + spec.keyword + "\n"), std::string::npos)
        << spec.keyword;
    for (const FieldSpec& field : spec.fields)
      EXPECT_NE(text.find(std::string("- `") + field.name + "`"), std::string::npos)
          << spec.keyword << " " << field.name;
  }
  // The fields and laws the hand-written table once lacked, and a default and a range together,
  // in the text with its line breaks and indents as single spaces (wrapping moves them).
  std::istringstream words(text);
  std::string flat;
  for (std::string word; words >> word;)
    flat += " " + word;
  for (const char* expected :
       {"- `search` (default `auto`)", "- `exclude`: boundary references", "damped (1.25)",
        "damped-unilateral (1.28)", "- `nu` (range in (-1, 0.5)):",
        "- `maxit` (range in [1, 10000]):", "- `eps` (default `1e-5`; range in [1e-14, 1)):"})
    EXPECT_NE(flat.find(expected), std::string::npos) << expected;
}

TEST(CardReference, WrappedLinesNeverOpenAMarkdownBlock) {
  // "I1 - 3" wrapped before "-" would turn the rest of a field's text into a nested list item.
  std::istringstream lines(card_reference_markdown());
  bool in_code = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("```", 0) == 0) in_code = !in_code;
    if (in_code) continue;
    if (line.rfind("  ", 0) == 0) { // a list item's continuation
      const std::string rest = line.substr(line.find_first_not_of(' '));
      EXPECT_EQ(std::string("-+*>#=|").find(rest.front()), std::string::npos) << line;
    }
  }
}

TEST(StageHelp, ListsFilesOptionsAndEveryCardAndRefusesAnUnknownCard) {
  const StageHelp help{.name = "sig-x",
                       .purpose = "Does x.",
                       .reads = {"OUTDIR/case.nopo"},
                       .writes = {"OUTDIR/case.x"},
                       .cards = {"TITLE", "SOLVER"},
                       .options = {{"--fast", "quickly"}}};
  const std::string text = stage_help_text(help);
  for (const char* expected :
       {"usage: sig-x DATAFILE [-o OUTDIR] [--time-limit SECONDS]\n", "Does x.\n",
        "  OUTDIR/case.nopo\n", "  OUTDIR/case.x\n", "  -o OUTDIR ", "  --time-limit SECONDS ",
        "  --fast  ", " quickly\n", "\nTITLE: ", "\nSOLVER: ", "    linear  ",
        "[default: cholmod]"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
  StageHelp wrong = help;
  wrong.cards.push_back("NOSUCHCARD");
  EXPECT_THROW(stage_help_text(wrong), Error);
}

TEST(StageHelp, HelpAndVersionPrintAndExitZero) {
  const StageHelp help{.name = "sig-x", .purpose = "Does x.", .cards = {"TITLE"}};
  for (const char* option : {"--help", "-h", "--version"}) {
    std::string words[] = {"sig-x", "deck.dat", option};
    char* argv[] = {words[0].data(), words[1].data(), words[2].data()};
    ::testing::internal::CaptureStdout();
    const int code = run_stage("sig-x", [&] { parse_stage_args(3, argv, help); });
    const std::string out = ::testing::internal::GetCapturedStdout();
    EXPECT_EQ(code, 0) << option;
    if (std::string(option) == "--version")
      EXPECT_EQ(out.rfind("sig-x (Signorini) ", 0), 0u) << out;
    else
      EXPECT_EQ(out.rfind("usage: sig-x ", 0), 0u) << out;
  }
}

} // namespace
} // namespace sig
