// Tests of case/CaseRules on a CaseConfig built in code: the rules between keys need only the
// loaded values and where the keys were written (test_CaseLoader checks them through the file).
#include <gtest/gtest.h>

#include <string>

#include "core/Error.hpp"
#include "case/CaseRules.hpp"
#include "case/KeyLocations.hpp"

namespace qs {
namespace {

/// A 1D column of 1 cm cells: chamber 2 cm, one 10 cm layer of "sand", water at the sand top.
CaseConfig column() {
    CaseConfig c;
    c.grid.cellSize = 0.01;
    c.column.chamberHeight = 0.02;
    c.column.waterLevel = 0.12;
    c.column.top = 0.2;
    MaterialConfig sand;
    sand.name = "sand";
    c.materials.push_back(sand);
    LayerConfig layer;
    layer.material = "sand";
    layer.thickness = 0.1;
    c.layers.push_back(layer);
    return c;
}

/// Where the keys of column() were written: only [column] top (line 8) and the tables.
KeyLocations positions() {
    KeyLocations where("case.toml");
    for (const auto& [table, line] : {std::pair<const char*, int>{"", 1}, {"grid", 2}, {"column", 6},
                                      {"materials.sand", 10}, {"layers[0]", 14}, {"initial", 1}})
        where.addTable(table, line);
    where.addKey("column", "top", 8);
    return where;
}

std::string messageOf(void (*rules)(const CaseConfig&, const KeyLocations&), const CaseConfig& c) {
    try {
        rules(c, positions());
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(CaseRules, AValidColumnPasses) {
    EXPECT_EQ(messageOf(validateGeometry, column()), "");
    EXPECT_EQ(messageOf(validateInitialState, column()), "");
}

TEST(CaseRules, ARuleBlamesTheWrittenKeyAtItsLineAndADefaultAtItsTable) {
    CaseConfig high = column();
    high.column.waterLevel = 0.25;  // above the top, which was written at line 8
    EXPECT_EQ(messageOf(validateGeometry, high),
              "case.toml:8: key 'column.top': top = 0.2 m is not above water_level = 0.25 m; the grid must "
              "reach above the free surface");
    CaseConfig loose = column();
    loose.materials[0].porosity = 0.45;  // above the default n_max = 0.41: porosity is blamed
    EXPECT_EQ(messageOf(validateInitialState, loose).rfind("case.toml:10: key 'materials.sand.porosity': n0 = 0.45 "
                                                           ">= n_max = 0.41 (the default)",
                                                           0),
              0u);
    loose.initial.state = InitialState::Fluidised;  // a suspension may start beyond n_max
    EXPECT_EQ(messageOf(validateInitialState, loose), "");
}

TEST(CaseRules, AnUndrainedStartNeedsASurcharge) {
    CaseConfig c = column();
    c.initial.undrainedSurcharge = true;
    EXPECT_NE(messageOf(validateInitialState, c).find("key 'initial.undrained_surcharge'"), std::string::npos);
    c.loads.surcharge = 1000;
    EXPECT_EQ(messageOf(validateInitialState, c), "");
}

}  // namespace
}  // namespace qs
