#pragma once
// The card schema as text for people: a stage's --help and `sig-dump --cards` print these, so a
// card's help and defaults are written once, in cards.cpp.
#include "core/datafile.hpp"

#include <string>

namespace sig {

/// A card: its keyword, whether it may repeat, its help, then one line per field with its help
/// and default, wrapped to 100 columns.
std::string card_help(const CardSpec& spec);

/// One line per card of the schema: keyword and help.
std::string card_index();

/// The whole schema as a Markdown card reference (datafiles/CARDS.md, `sig-dump
/// --cards-markdown`): an index of the cards, then per card its help and one item per field with
/// its default and its range (core/ranges.hpp), lines wrapped at 100 columns. Deterministic (no
/// date, no revision), so that the committed file can be diffed against a fresh one.
std::string card_reference_markdown();

/// `text` wrapped at word boundaries into lines ending by column `width`: the first line starts
/// at column `start` (the caller printed what comes before it), the others are indented by
/// `indent` spaces; a word longer than a line stays whole. Ends with a newline.
std::string wrap_text(const std::string& text, std::size_t start, std::size_t indent,
                      std::size_t width = 100);

} // namespace sig
