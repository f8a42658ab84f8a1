// Tests of case/TomlSection on its own, with a made-up format (no quicksand key): typed look-ups and
// their messages, the unknown-key check, and where KeyLocations places a problem.
#include <gtest/gtest.h>

#include <string>

#include "core/Error.hpp"
#include "case/DidYouMean.hpp"
#include "case/KeyLocations.hpp"
#include "case/TomlSection.hpp"

namespace qs {
namespace {

constexpr const char* kTopKeys[] = {"name", "pump"};
constexpr const char* kPumpKeys[] = {"speed", "mode", "head"};
const TableKeys kTop = tableKeys("the top level", kTopKeys);
const TableKeys kPump = tableKeys("[pump]", kPumpKeys);
const TableCatalogue kFormat = {&kTop, &kPump};

enum class Mode { Steady, Pulsed };
const Options<Mode> kModes = {{"steady", Mode::Steady}, {"pulsed", Mode::Pulsed}};

toml::table parsed(const std::string& text) { return toml::parse(text, std::string_view("pump.toml")); }

/// The InputError that `read` throws, or a failure.
template <class Read>
InputError errorOf(Read read) {
    try {
        read();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError";
    return InputError("", 0, "", "");
}

TEST(TomlSection, ANumberOutOfItsRangeNamesFileLineKeyValueAndRange) {
    const toml::table file = parsed("name = \"p1\"\n[pump]\nspeed = -3.5\n");
    KeyLocations where("pump.toml");
    const Section top(file, kTop, kFormat, where);
    const Section pump = top.subsection("pump", kPump, true);
    const InputError e = errorOf([&] { pump.optionalNumber("speed", 1.0, positive("rpm"), "shaft speed"); });
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.key(), "pump.speed");
    EXPECT_STREQ(e.what(), "pump.toml:3: key 'pump.speed': value -3.5 rpm is out of range: expected a value > 0 rpm "
                           "(shaft speed)");
    // a missing required key is reported at its table's line
    const InputError missing = errorOf([&] { pump.requiredNumber("head", nonNegative("m")); });
    EXPECT_EQ(missing.line(), 2);
    EXPECT_STREQ(missing.what(), "pump.toml:2: key 'pump.head': missing required key 'head' in [pump] (expected a "
                                 "number >= 0 m)");
}

TEST(TomlSection, AnUnknownKeySuggestsTheNearestOrSaysWhereItBelongs) {
    const toml::table typo = parsed("[pump]\nsped = 3\n");
    KeyLocations where("pump.toml");
    const Section top(typo, kTop, kFormat, where);
    EXPECT_STREQ(errorOf([&] { top.subsection("pump", kPump, true); }).what(),
                 "pump.toml:2: key 'pump.sped': unknown key 'sped'. Did you mean 'speed'?");
    // a top-level key written after a header lands in that table
    const toml::table misplaced = parsed("[pump]\nspeed = 3\nname = \"p1\"\n");
    const Section top2(misplaced, kTop, kFormat, where);
    const std::string what = errorOf([&] { top2.subsection("pump", kPump, true); }).what();
    EXPECT_NE(what.find("'name' belongs in the top level (before the first [table] header"), std::string::npos)
        << what;
}

TEST(TomlSection, AChoiceOutsideItsOptionsListsThemAndGuesses) {
    const toml::table file = parsed("[pump]\nmode = \"pulsd\"\n");
    KeyLocations where("pump.toml");
    const Section pump = Section(file, kTop, kFormat, where).subsection("pump", kPump, true);
    EXPECT_STREQ(errorOf([&] { pump.choice("mode", Mode::Steady, kModes); }).what(),
                 "pump.toml:2: key 'pump.mode': unknown value \"pulsd\"; allowed: \"steady\", \"pulsed\". Did you "
                 "mean \"pulsed\"?");
    EXPECT_EQ(nameOf(kModes, Mode::Pulsed), "\"pulsed\"");
}

TEST(TomlSection, KeyLocationsPlaceALaterCheckAsTheReaderWould) {
    // what a rule checked after reading sees: the key's line if written, else its table's
    const toml::table file = parsed("name = \"p1\"\n\n[pump]\nspeed = 3\n");
    KeyLocations where("pump.toml");
    const Section top(file, kTop, kFormat, where);
    const Section pump = top.subsection("pump", kPump, true);
    const KeyLocations::Table table = where.table("pump");
    EXPECT_TRUE(table.has("speed"));
    EXPECT_FALSE(table.has("head"));
    EXPECT_EQ(table.lineOf("speed"), 4);
    EXPECT_EQ(table.lineOf("head"), 3);
    const InputError e = errorOf([&] { table.fail("head", "head must exceed the suction lift"); });
    EXPECT_EQ(e.line(), pump.lineOf("head"));
    EXPECT_STREQ(e.what(), "pump.toml:3: key 'pump.head': head must exceed the suction lift");
    EXPECT_EQ(where.table("").keyPath("name"), "name");
}

TEST(DidYouMean, NamesATypoAndNotAnUnrelatedWord) {
    EXPECT_EQ(editDistance("porosty", "porosity"), 1u);
    EXPECT_EQ(editDistance("Gimp", "gimp"), 0u);  // case-insensitive
    EXPECT_EQ(editDistance("hte", "the"), 1u);    // a transposition is one edit
    EXPECT_EQ(nearest("fluidized", {"solid", "fluidised"}), std::optional<std::string>("fluidised"));
    EXPECT_EQ(nearest("liquid", {"solid", "fluidised"}), std::nullopt);
}

}  // namespace
}  // namespace qs
