// Tests of the command line's overrides (case/CaseOverride.hpp): --set KEY=VALUE changes one key of
// case.toml for a run, validated exactly like the key in the file, and the run records the case
// as run. Which keys are reachable: every key of a table (time.end), of a named table
// (materials.sand.porosity), of an inline table (materials.sand.permeability.value), of an
// existing entry of an array of tables (layers[0].thickness); a table absent from the file is made
// (output.fields). An entry of an array of tables cannot be added or replaced whole.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/Error.hpp"
#include "case/CaseLoader.hpp"

namespace qs {
namespace {

const char* const kFile = "case.toml";

const std::string kCase = R"(title = "overrides"
[grid]
cell_size = 0.01
cross_section_area = 5.0e-3   # m2

[column]
chamber_height = 0.02
top = 0.2

[materials.sand]
porosity = 0.38
permeability = { mode = "constant", value = 1.49e-10 }

[[layers]]
material = "sand"
thickness = 0.1

[reservoir]
model = "lumped"
head = 0.15
area = 5.0e-5

[time]
end = 1.0
)";

CaseConfig withSets(const std::vector<std::string>& sets) {
    std::vector<CaseOverride> o;
    for (const auto& s : sets) o.push_back(parseOverride(s));
    return parseCase(kCase, kFile, ".", o);
}

/// The message of the InputError that loading with `sets` throws ("" if none).
std::string errorOf(const std::vector<std::string>& sets) {
    try {
        withSets(sets);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(CaseOverrides, ReachTablesNamedTablesInlineTablesAndEntriesOfArraysOfTables) {
    const CaseConfig c = withSets({"time.end=50", "reservoir.area=0.02", "materials.sand.porosity=0.4",
                                   "materials.sand.permeability.value=2e-10", "layers[0].thickness=0.12",
                                   "reservoir.tube_friction=laminar", "reservoir.tube_diameter=0.01",
                                   "reservoir.tube_length=2", "output.fields=false", "title=\"a b\""});
    EXPECT_EQ(c.time.end, 50.0) << "an integer is a number, as in the file";
    EXPECT_EQ(c.reservoir.area, 0.02);
    EXPECT_EQ(c.materials[0].porosity, 0.4);
    EXPECT_EQ(c.materials[0].permeability.value, 2e-10);
    EXPECT_DOUBLE_EQ(c.layers[0].thickness, 0.12);
    EXPECT_EQ(c.reservoir.tubeFriction, TubeFriction::Laminar) << "a bare word is a string";
    EXPECT_FALSE(c.output.fields) << "a table the file has not is made";
    EXPECT_EQ(c.title, "a b");
    ASSERT_EQ(c.overrides.size(), 10u);
    EXPECT_EQ(c.overrides[0].text(), "--set time.end=50");
}

TEST(CaseOverrides, AnUnknownKeyIsNamedWithItsOverrideAndTheNearestKey) {
    const std::string e = errorOf({"time.end=2", "reservoir.aera=0.02"});
    EXPECT_NE(e.find("case.toml, --set reservoir.aera=0.02: key 'reservoir.aera'"), std::string::npos) << e;
    EXPECT_NE(e.find("Did you mean 'area'"), std::string::npos) << e;
    const std::string table = errorOf({"reservior.area=1"});
    EXPECT_NE(table.find("--set reservior.area=1"), std::string::npos) << table;
    EXPECT_NE(table.find("Did you mean 'reservoir'"), std::string::npos) << table;
}

TEST(CaseOverrides, AWrongTypeOrUnitOrRangeIsRefusedAsInTheFile) {
    const std::string unit = errorOf({"time.end=50s"});
    EXPECT_NE(unit.find("--set time.end=50s: key 'time.end': expected a number"), std::string::npos) << unit;
    EXPECT_NE(unit.find("write the number alone, in s"), std::string::npos) << unit;
    const std::string range = errorOf({"materials.sand.porosity=-0.1"});
    EXPECT_NE(range.find("--set materials.sand.porosity=-0.1: key 'materials.sand.porosity'"), std::string::npos) << range;
    const std::string type = errorOf({"output.fields=3"});
    EXPECT_NE(type.find("--set output.fields=3: key 'output.fields'"), std::string::npos) << type;
    const std::string choice = errorOf({"reservoir.model=lumpy"});
    EXPECT_NE(choice.find("--set reservoir.model=lumpy"), std::string::npos) << choice;
    EXPECT_NE(choice.find("lumped"), std::string::npos) << choice;
}

TEST(CaseOverrides, AnOverrideThatMakesTheCaseInvalidNamesItself) {
    // a rule between keys (whole cells), found on the loaded values
    const std::string cells = errorOf({"layers[0].thickness=0.105"});
    EXPECT_NE(cells.find("--set layers[0].thickness=0.105: key 'layers[0].thickness'"), std::string::npos) << cells;
    // a key that does not apply with the model chosen by another override
    const std::string model = errorOf({"reservoir.model=constant_head"});
    EXPECT_NE(model.find("--set reservoir.model=constant_head"), std::string::npos) << model;
}

TEST(CaseOverrides, KeysThatCannotBeReachedAreRefusedWithWhy) {
    const std::string past = errorOf({"layers[1].thickness=0.1"});
    EXPECT_NE(past.find("the case has 1 [[layers]] (layers[0] to layers[0])"), std::string::npos) << past;
    const std::string whole = errorOf({"layers.thickness=0.1"});
    EXPECT_NE(whole.find("name the entry, as layers[0].thickness"), std::string::npos) << whole;
    const std::string through = errorOf({"time.end.x=1"});
    EXPECT_NE(through.find("'time.end' is 1.0 in the case, not a table"), std::string::npos) << through;
    EXPECT_THROW(parseOverride("time.end"), Error);
    EXPECT_THROW(parseOverride("=5"), Error);
    EXPECT_NE(errorOf({"time.end="}).find("no value after '='"), std::string::npos);
    EXPECT_NE(errorOf({"time..end=1"}).find("expected a dotted key"), std::string::npos);
}

TEST(CaseOverrides, TheEffectiveCaseKeepsTheFileAndMarksEachOverride) {
    const CaseConfig c = withSets({"reservoir.area=0.02", "materials.sand.permeability.value=2e-10", "output.fields=false",
                                   "reservoir.tube_diameter=0.004", "reservoir.tube_length=1.7", "reservoir.minor_loss=1.5"});
    const std::string& t = c.effectiveCase;
    EXPECT_NE(t.find("#   --set reservoir.area=0.02 (was 5.0e-5)"), std::string::npos) << t;
    EXPECT_NE(t.find("area = 0.02  # --set reservoir.area=0.02 (was 5.0e-5)"), std::string::npos) << t;
    EXPECT_NE(t.find("permeability = { mode = \"constant\", value = 2e-10 }  # --set materials.sand.permeability.value=2e-10 (was 1.49e-10)"),
              std::string::npos) << t;
    EXPECT_NE(t.find("minor_loss = 1.5  # --set reservoir.minor_loss=1.5 (not in the file)"), std::string::npos) << t;
    EXPECT_NE(t.find("[output]\nfields = false  # --set output.fields=false (not in the file)"), std::string::npos) << t;
    EXPECT_NE(t.find("cross_section_area = 5.0e-3   # m2"), std::string::npos) << "the file's comments stay";
    // read back, the effective case is the case as run
    const CaseConfig again = parseCase(t, kFile, ".");
    EXPECT_EQ(again.reservoir.area, 0.02);
    EXPECT_EQ(again.materials[0].permeability.value, 2e-10);
    EXPECT_EQ(again.reservoir.minorLoss, 1.5);
    EXPECT_FALSE(again.output.fields);
    // without overrides it is the file itself
    EXPECT_EQ(withSets({}).effectiveCase, kCase);
}

TEST(CaseOverrides, TheSameKeyTwiceTakesTheLastAndStillWritesACaseThatReadsBack) {
    const CaseConfig c = withSets({"time.end=2", "time.end=3"});
    EXPECT_EQ(c.time.end, 3.0);
    EXPECT_EQ(parseCase(c.effectiveCase, kFile, ".").time.end, 3.0) << c.effectiveCase;
}

}  // namespace
}  // namespace qs

namespace qs {
namespace {

// The tables of [reservoir] (area_table, head_schedule): each problem names the key, the row and
// what is expected.
std::string reservoirError(const std::string& reservoir) {
    const std::string text = kCase.substr(0, kCase.find("[reservoir]")) + "[reservoir]\n" + reservoir + "\n[time]\nend = 1.0\n";
    try {
        parseCase(text, kFile, ".");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(ReservoirTables, AreReadAndBadRowsAreRefusedNamingTheRow) {
    EXPECT_EQ(reservoirError("model = \"lumped\"\nhead = 0.25\narea_table = [[0.1, 1e-4], [0.3, 2e-4]]"), "");
    EXPECT_EQ(reservoirError("head_schedule = [[0, 0.2], [1, 0.3]]"), "");
    const std::string both = reservoirError("model = \"lumped\"\nhead = 0.25\narea = 1e-4\narea_table = [[0.1, 1e-4], [0.3, 2e-4]]");
    EXPECT_NE(both.find("key 'reservoir.area'"), std::string::npos) << both;
    EXPECT_NE(both.find("area_table gives the plan area at every level"), std::string::npos) << both;
    const std::string order = reservoirError("model = \"lumped\"\nhead = 0.25\narea_table = [[0.3, 1e-4], [0.1, 2e-4]]");
    EXPECT_NE(order.find("key 'reservoir.area_table': row 2: level = 0.1 m does not follow row 1's 0.3"), std::string::npos) << order;
    const std::string zero = reservoirError("model = \"lumped\"\nhead = 0.25\narea_table = [[0.1, 1e-4], [0.3, 0]]");
    EXPECT_NE(zero.find("row 2: area = 0 m2 is out of range"), std::string::npos) << zero;
    const std::string one = reservoirError("model = \"lumped\"\nhead = 0.25\narea_table = [[0.1, 1e-4]]");
    EXPECT_NE(one.find("expected at least 2 rows [[level, area], ...]"), std::string::npos) << one;
    const std::string above = reservoirError("model = \"lumped\"\nhead = 0.05\narea_table = [[0.1, 1e-4], [0.3, 2e-4]]");
    EXPECT_NE(above.find("the first row's level 0.1 m is above the initial head 0.05 m"), std::string::npos) << above;
    const std::string schedule = reservoirError("head_schedule = [[0, 0.2], [0, 0.3]]");
    EXPECT_NE(schedule.find("row 2: time = 0 s does not follow row 1's 0"), std::string::npos) << schedule;
    const std::string headToo = reservoirError("head = 0.2\nhead_schedule = [[0, 0.2], [1, 0.3]]");
    EXPECT_NE(headToo.find("key 'reservoir.head'"), std::string::npos) << headToo;
    EXPECT_NE(headToo.find("head_schedule gives the head at every time"), std::string::npos) << headToo;
    const std::string negative = reservoirError("head_schedule = [[0, -0.2]]");
    EXPECT_NE(negative.find("row 1: head = -0.2 m is out of range"), std::string::npos) << negative;
    const std::string shape = reservoirError("head_schedule = [0.2, 0.3]");
    EXPECT_NE(shape.find("row 1: expected two numbers [time, head]"), std::string::npos) << shape;
    const std::string lumped = reservoirError("model = \"lumped\"\nhead = 0.2\narea = 1e-4\nhead_schedule = [[0, 0.2]]");
    EXPECT_NE(lumped.find("key 'reservoir.head_schedule'"), std::string::npos) << lumped;
    EXPECT_NE(lumped.find("a scheduled head is model = \"constant_head\""), std::string::npos) << lumped;
}

}  // namespace
}  // namespace qs
