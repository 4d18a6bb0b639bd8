#pragma once
// The analyzer's deck definition (benchpilot.deck, docs/plates.md): travel,
// table height, syringe, how each axis moves, slots and stations. The one the
// application uses is resources/machines/analyzer.deck.json, built into the
// program (builtinDeckText); `--deck FILE` reads another.
#include "device/files/json_fields.h"
#include "motion/plans/plates/deck.h"

#include <optional>
#include <string>
#include <string_view>

namespace dev::files::plates {

constexpr const char* kDeckSchema = "benchpilot.deck";
constexpr int kDeckVersion = 1;

struct DeckRead {
    std::optional<motion::plates::Deck> deck;  ///< only when there are no problems
    dev::files::json::Problems problems;
};

DeckRead parseDeck(std::string_view text);
std::string writeDeck(const motion::plates::Deck& deck);

/// resources/machines/analyzer.deck.json as built into the program.
std::string builtinDeckText();
/// The built-in deck, read (it is checked by a test, so this cannot fail in a release).
motion::plates::Deck builtinDeck();

} // namespace dev::files::plates
