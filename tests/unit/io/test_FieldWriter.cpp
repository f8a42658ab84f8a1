// FieldWriter: write point sets, read them back with the HDF5 C API, check the XDMF index.
#include "core/BuildInfo.hpp"
#include "io/FieldWriter.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// A fresh directory per test, removed afterwards.
class FieldWriterTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("qs_fieldwriter_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

int occurrences(const std::string& text, const std::string& what) {
    int n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

/// Reads a whole double dataset, reporting its dimensions.
std::vector<double> readDoubles(hid_t file, const std::string& name, std::vector<hsize_t>* dims = nullptr) {
    const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    EXPECT_GE(dataset, 0) << name;
    if (dataset < 0) return {};
    const hid_t space = H5Dget_space(dataset);
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> d(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space, d.data(), nullptr);
    std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    if (!values.empty()) {
        EXPECT_GE(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
    }
    H5Sclose(space);
    H5Dclose(dataset);
    if (dims) *dims = d;
    return values;
}

double readDoubleAttribute(hid_t file, const std::string& object, const std::string& name) {
    double value = -1.0;
    const hid_t attribute = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    EXPECT_GE(attribute, 0) << object << "@" << name;
    if (attribute >= 0) {
        H5Aread(attribute, H5T_NATIVE_DOUBLE, &value);
        H5Aclose(attribute);
    }
    return value;
}

std::string readStringAttribute(hid_t file, const std::string& object, const std::string& name) {
    const hid_t attribute = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (attribute < 0) return "<missing>";
    const hid_t type = H5Aget_type(attribute);
    std::string value(H5Tget_size(type), '\0');
    H5Aread(attribute, type, &value[0]);
    H5Tclose(type);
    H5Aclose(attribute);
    return value.substr(0, value.find('\0'));
}

bool exists(hid_t file, const std::string& path) { return H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0; }

}  // namespace

TEST_F(FieldWriterTest, OneDimensionalColumnStandsAlongZ) {
    const std::vector<double> z = {0.1, 0.2, 0.3};
    const std::vector<double> porosity = {0.40, 0.41, 0.42};
    const std::vector<double> velocity = {-1.0, -2.0, -3.0};
    const std::vector<double> state = {0.0, 1.0, 2.0};  // integers, converted by the caller
    {
        qs::FieldWriter writer(dir_.string(), 1);
        writer.beginStep(0.25);
        writer.writePointSet("solid", 3, z.data(),
                             {{"porosity", porosity.data(), 1},
                              {"velocity", velocity.data(), 1, qs::FieldKind::Vector},
                              {"state", state.data(), 1}});
        writer.endStep();
        EXPECT_EQ(writer.stepsWritten(), 1);
    }
    const hid_t file = H5Fopen((dir_ / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    std::vector<hsize_t> dims;
    EXPECT_EQ(readDoubles(file, "/step_000000/solid/positions", &dims),
              (std::vector<double>{0, 0, 0.1, 0, 0, 0.2, 0, 0, 0.3}));
    EXPECT_EQ(dims, (std::vector<hsize_t>{3, 3}));
    EXPECT_EQ(readDoubles(file, "/step_000000/solid/porosity", &dims), porosity);
    EXPECT_EQ(dims, (std::vector<hsize_t>{3}));
    EXPECT_EQ(readDoubles(file, "/step_000000/solid/velocity", &dims),
              (std::vector<double>{0, 0, -1, 0, 0, -2, 0, 0, -3}));
    EXPECT_EQ(dims, (std::vector<hsize_t>{3, 3}));
    EXPECT_EQ(readDoubles(file, "/step_000000/solid/state"), state);
    EXPECT_EQ(readDoubleAttribute(file, "/step_000000", "time"), 0.25);
    int dimension = 0;
    const hid_t attribute = H5Aopen(file, "dimension", H5P_DEFAULT);
    H5Aread(attribute, H5T_NATIVE_INT, &dimension);
    H5Aclose(attribute);
    EXPECT_EQ(dimension, 1);
    // which build wrote it (core/BuildInfo.hpp)
    EXPECT_EQ(readStringAttribute(file, "/", "quicksand"), qs::buildLine());
    EXPECT_EQ(readStringAttribute(file, "/", "quicksand").rfind("quicksand " + qs::version() + " (commit ", 0), 0u);
    H5Fclose(file);
}

TEST_F(FieldWriterTest, TwoDimensionalPointsKeepTheVerticalInZAndTensorsUnchanged) {
    const std::vector<double> xz = {1.0, 10.0, 2.0, 20.0};
    const std::vector<double> velocity = {0.5, -0.5, 0.25, -0.25};
    const std::vector<double> stress = {1, 2, 3, 4, 5, 6, 11, 12, 13, 14, 15, 16};  // Voigt
    {
        qs::FieldWriter writer(dir_.string(), 2);
        writer.beginStep(1.0);
        writer.writePointSet("solid", 2, xz.data(),
                             {{"velocity", velocity.data(), 2}, {"effective_stress", stress.data(), 6}});
        writer.endStep();
    }
    const hid_t file = H5Fopen((dir_ / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    EXPECT_EQ(readDoubles(file, "/step_000000/solid/positions"), (std::vector<double>{1, 0, 10, 2, 0, 20}));
    EXPECT_EQ(readDoubles(file, "/step_000000/solid/velocity"),
              (std::vector<double>{0.5, 0, -0.5, 0.25, 0, -0.25}));
    std::vector<hsize_t> dims;
    EXPECT_EQ(readDoubles(file, "/step_000000/solid/effective_stress", &dims), stress);
    EXPECT_EQ(dims, (std::vector<hsize_t>{2, 6}));
    EXPECT_EQ(readStringAttribute(file, "/step_000000/solid/effective_stress", "components"), "xx yy zz yz xz xy");
    H5Fclose(file);

    const std::string xdmf = readText(dir_ / "fields.xdmf");
    EXPECT_NE(xdmf.find("AttributeType=\"Tensor6\""), std::string::npos);
    EXPECT_NE(xdmf.find("AttributeType=\"Vector\""), std::string::npos);
    EXPECT_NE(xdmf.find("Dimensions=\"2 6\""), std::string::npos);
}

TEST_F(FieldWriterTest, ThreeDimensionalPositionsAreCopiedAsTheyAre) {
    const std::vector<double> xyz = {1, 2, 3, 4, 5, 6};
    {
        qs::FieldWriter writer(dir_.string(), 3);
        writer.beginStep(0.0);
        writer.writePointSet("liquid", 2, xyz.data(), {{"velocity", xyz.data(), 3}});
        writer.endStep();
    }
    const hid_t file = H5Fopen((dir_ / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    EXPECT_EQ(readDoubles(file, "/step_000000/liquid/positions"), xyz);
    EXPECT_EQ(readDoubles(file, "/step_000000/liquid/velocity"), xyz);
    H5Fclose(file);
}

TEST_F(FieldWriterTest, XdmfIndexesEveryStepAndDatasetAndIsValidAfterEachStep) {
    const std::vector<double> z = {0.1, 0.2};
    const std::vector<double> p = {1000.0, 2000.0};
    qs::FieldWriter writer(dir_.string(), 1);
    ASSERT_TRUE(fs::exists(dir_ / "fields.xdmf"));  // an empty but valid series from the start

    writer.beginStep(0.0);
    writer.writePointSet("solid", 2, z.data(), {{"porosity", p.data(), 1}});
    writer.writePointSet("liquid", 2, z.data(), {{"pore_pressure", p.data(), 1}});
    writer.endStep();
    // Readable while the run goes on (a crash from here on loses nothing written so far).
    std::string xdmf = readText(dir_ / "fields.xdmf");
    EXPECT_NE(xdmf.find("fields/step_000000.h5:/liquid/pore_pressure"), std::string::npos);
    EXPECT_EQ(occurrences(xdmf, "<Time "), 1);

    writer.beginStep(0.5);
    writer.writePointSet("solid", 2, z.data(), {{"porosity", p.data(), 1}});
    writer.writePointSet("liquid", 2, z.data(), {{"pore_pressure", p.data(), 1}});
    writer.endStep();
    xdmf = readText(dir_ / "fields.xdmf");
    EXPECT_NE(xdmf.find("CollectionType=\"Temporal\""), std::string::npos);
    EXPECT_NE(xdmf.find("<Time Value=\"0.5\"/>"), std::string::npos);
    EXPECT_NE(xdmf.find("TopologyType=\"Polyvertex\""), std::string::npos);
    EXPECT_NE(xdmf.find("GeometryType=\"XYZ\""), std::string::npos);
    for (const char* dataset : {"fields/step_000000.h5:/solid/positions", "fields/step_000000.h5:/solid/porosity",
                                "fields/step_000001.h5:/solid/connectivity", "fields/step_000001.h5:/liquid/positions",
                                "fields/step_000001.h5:/liquid/pore_pressure"})
        EXPECT_NE(xdmf.find(dataset), std::string::npos) << dataset;
    EXPECT_EQ(occurrences(xdmf, "<Grid "), occurrences(xdmf, "</Grid>"));
    EXPECT_EQ(occurrences(xdmf, "<Grid Name=\"solid\""), 2);
    EXPECT_FALSE(fs::exists(dir_ / "fields.xdmf.tmp"));
}

TEST_F(FieldWriterTest, EmptyPointSetHasEmptyDatasetsButNoXdmfGrid) {
    const std::vector<double> z = {0.1};
    {
        qs::FieldWriter writer(dir_.string(), 1);
        writer.beginStep(0.0);
        writer.writePointSet("solid", 1, z.data(), {{"porosity", z.data(), 1}});
        writer.writePointSet("liquid", 0, nullptr, {{"pore_pressure", nullptr, 1}});
        writer.endStep();
    }
    const hid_t file = H5Fopen((dir_ / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    std::vector<hsize_t> dims;
    EXPECT_TRUE(readDoubles(file, "/step_000000/liquid/pore_pressure", &dims).empty());
    EXPECT_EQ(dims, (std::vector<hsize_t>{0}));
    EXPECT_TRUE(readDoubles(file, "/step_000000/liquid/positions", &dims).empty());
    EXPECT_EQ(dims, (std::vector<hsize_t>{0, 3}));
    H5Fclose(file);
    const std::string xdmf = readText(dir_ / "fields.xdmf");
    EXPECT_EQ(xdmf.find("liquid"), std::string::npos);
    EXPECT_NE(xdmf.find("<Grid Name=\"solid\""), std::string::npos);
}

TEST_F(FieldWriterTest, DestructorAbandonsAnOpenStep) {
    // A step still open at destruction was cut short by an exception: it must not be published.
    const std::vector<double> z = {0.1};
    {
        qs::FieldWriter writer(dir_.string(), 1);
        writer.beginStep(1.0);
        writer.writePointSet("solid", 1, z.data(), {});
        writer.endStep();
        writer.beginStep(2.0);
        writer.writePointSet("solid", 1, z.data(), {});
    }
    const std::string xdmf = readText(dir_ / "fields.xdmf");
    EXPECT_EQ(occurrences(xdmf, "<Time "), 1);
    EXPECT_NE(xdmf.find("fields/step_000000.h5:/solid/positions"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir_ / "fields" / "step_000001.h5"));
    EXPECT_FALSE(fs::exists(dir_ / "fields" / "step_000001.h5.tmp"));
}

TEST_F(FieldWriterTest, ConstructorTruncatesAPreviousRun) {
    const std::vector<double> z = {0.1};
    for (int run = 0; run < 2; ++run) {
        qs::FieldWriter writer(dir_.string(), 1);
        writer.beginStep(run);
        writer.writePointSet("solid", 1, z.data(), {});
        writer.endStep();
    }
    const hid_t file = H5Fopen((dir_ / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    EXPECT_TRUE(exists(file, "/step_000000"));
    EXPECT_FALSE(exists(file, "/step_000001"));
    EXPECT_EQ(readDoubleAttribute(file, "/step_000000", "time"), 1.0);
    H5Fclose(file);
}

TEST_F(FieldWriterTest, MisuseThrowsQsError) {
    const std::vector<double> z = {0.1, 0.2};
    EXPECT_THROW(qs::FieldWriter(dir_.string(), 4), qs::Error);
    qs::FieldWriter writer(dir_.string(), 2);
    EXPECT_THROW(writer.writePointSet("solid", 1, z.data(), {}), qs::Error);  // no step open
    EXPECT_THROW(writer.endStep(), qs::Error);
    writer.beginStep(0.0);
    EXPECT_THROW(writer.beginStep(1.0), qs::Error);
    EXPECT_THROW(writer.writePointSet("a/b", 1, z.data(), {}), qs::Error);
    EXPECT_THROW(writer.writePointSet("solid", 1, z.data(), {{"v", z.data(), 1, qs::FieldKind::Vector}}),
                 qs::Error);
    EXPECT_THROW(writer.writePointSet("solid", 1, z.data(), {{"positions", z.data(), 1}}), qs::Error);
    EXPECT_THROW(writer.writePointSet("solid", 1, z.data(), {{"p", z.data(), 1}, {"p", z.data(), 1}}), qs::Error);
    EXPECT_THROW(writer.writePointSet("solid", 1, z.data(), {{"p", nullptr, 1}}), qs::Error);
    writer.writePointSet("solid", 1, z.data(), {});
    EXPECT_THROW(writer.writePointSet("solid", 1, z.data(), {}), qs::Error);  // twice in one step
    writer.endStep();
}

TEST_F(FieldWriterTest, UncreatableFileThrowsNamingThePath) {
    fs::create_directories(dir_);
    std::ofstream(dir_ / "not_a_directory") << "x";
    const std::string bad = (dir_ / "not_a_directory" / "out").string();
    try {
        qs::FieldWriter writer(bad, 1);
        FAIL() << "expected qs::Error";
    } catch (const qs::Error& e) {
        EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
    // A directory where fields.h5 should be: HDF5 itself fails.
    fs::create_directories(dir_ / "blocked" / "fields.h5");
    try {
        qs::FieldWriter writer((dir_ / "blocked").string(), 1);
        FAIL() << "expected qs::Error";
    } catch (const qs::Error& e) {
        EXPECT_NE(std::string(e.what()).find("fields.h5"), std::string::npos) << e.what();
    }
}

/// Names of the files in a directory, sorted.
std::vector<std::string> filesIn(const fs::path& directory) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

TEST_F(FieldWriterTest, EachStepIsAFileOfItsOwnPublishedByRename) {
    const std::vector<double> z = {0.1, 0.2};
    qs::FieldWriter writer(dir_.string(), 1);
    for (int step = 0; step < 3; ++step) {
        writer.beginStep(0.5 * step);
        writer.writePointSet("solid", 2, z.data(), {{"porosity", z.data(), 1}});
        // Mid-step the new step exists only under its temporary name; fields.h5 does not link it.
        EXPECT_TRUE(fs::exists(dir_ / "fields" / ("step_00000" + std::to_string(step) + ".h5.tmp")));
        const hid_t file = H5Fopen((dir_ / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        ASSERT_GE(file, 0);
        EXPECT_FALSE(exists(file, "/step_00000" + std::to_string(step)));
        H5Fclose(file);
        writer.endStep();
    }
    EXPECT_EQ(filesIn(dir_ / "fields"),
              (std::vector<std::string>{"step_000000.h5", "step_000001.h5", "step_000002.h5"}));
    EXPECT_EQ(filesIn(dir_), (std::vector<std::string>{"fields", "fields.h5", "fields.xdmf"}));
    const hid_t file = H5Fopen((dir_ / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    EXPECT_EQ(readDoubleAttribute(file, "/step_000002", "time"), 1.0);
    EXPECT_EQ(readDoubles(file, "/step_000002/solid/porosity"), z);
    H5Fclose(file);
}

/// One output of one solid point at time t (s) in a writer of `dimension`: what the listing
/// tests write (the point has as many coordinates as the writer's dimension)
void writeOneStep(qs::FieldWriter& writer, double t, int dimension = 1) {
    const std::vector<double> position(dimension, 0.1);
    const std::vector<double> porosity = {0.4};
    writer.beginStep(t);
    writer.writePointSet("solid", 1, position.data(), {{"porosity", porosity.data(), 1}});
    writer.endStep();
}

// With a listing interval (the run's: a second), fields.h5 and fields.xdmf list the steps ended
// since the last listing when the interval has passed, at makeDurable() (each checkpoint) and
// when the writer closes; each step's own file is published at once. The index is extended from
// the last one published, and lists what a whole rewrite would.
TEST_F(FieldWriterTest, AListingIntervalListsAtMakeDurableAndWhenTheWriterCloses) {
    auto linked = [&](int step) {
        const hid_t file = H5Fopen((dir_ / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        EXPECT_GE(file, 0);
        const bool found = exists(file, "/step_00000" + std::to_string(step));
        H5Fclose(file);
        return found;
    };
    auto writeStep = [&](qs::FieldWriter& writer, int step) {
        writeOneStep(writer, 0.5 * step);
        EXPECT_TRUE(fs::exists(dir_ / "fields" / ("step_00000" + std::to_string(step) + ".h5")));
    };
    {
        qs::FieldWriter writer(dir_.string(), 1);
        writer.setListingInterval(1e9);
        writeStep(writer, 0);
        writeStep(writer, 1);
        EXPECT_EQ(occurrences(readText(dir_ / "fields.xdmf"), "<Time "), 0);
        EXPECT_FALSE(linked(0));
        writer.makeDurable();
        EXPECT_EQ(occurrences(readText(dir_ / "fields.xdmf"), "<Time "), 2);
        EXPECT_TRUE(linked(0) && linked(1));
        writeStep(writer, 2);
        writeStep(writer, 3);
        EXPECT_EQ(occurrences(readText(dir_ / "fields.xdmf"), "<Time "), 2);
        EXPECT_FALSE(linked(2));
        writer.setListingInterval(0);  // lists as each step ends
        writeStep(writer, 4);
        EXPECT_EQ(occurrences(readText(dir_ / "fields.xdmf"), "<Time "), 5);
        EXPECT_TRUE(linked(2) && linked(3) && linked(4));
        writer.setListingInterval(1e9);
        writeStep(writer, 5);
        EXPECT_FALSE(linked(5));
    }
    const std::string xdmf = readText(dir_ / "fields.xdmf");
    EXPECT_EQ(occurrences(xdmf, "<Time "), 6);
    EXPECT_EQ(occurrences(xdmf, "<Grid "), occurrences(xdmf, "</Grid>"));
    for (int step = 0; step < 6; ++step) EXPECT_TRUE(linked(step)) << step;
    EXPECT_EQ(filesIn(dir_), (std::vector<std::string>{"fields", "fields.h5", "fields.xdmf"}));
}

/// fields.h5's links, name -> "file:object", in creation order (the order readers list them)
std::vector<std::string> indexLinks(const fs::path& index) {
    std::vector<std::string> links;
    const hid_t file = H5Fopen(index.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    EXPECT_GE(file, 0);
    if (file < 0) return links;
    H5G_info_t info;
    H5Gget_info(file, &info);
    for (hsize_t k = 0; k < info.nlinks; ++k) {
        char name[64] = {}, value[256] = {};
        H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, k, name, sizeof name, H5P_DEFAULT);
        H5Lget_val(file, name, value, sizeof value, H5P_DEFAULT);
        const char* target = nullptr;
        const char* object = nullptr;
        H5Lunpack_elink_val(value, sizeof value, nullptr, &target, &object);
        links.push_back(std::string(name) + " -> " + (target ? target : "?") + ":" + (object ? object : "?"));
    }
    H5Fclose(file);
    return links;
}

// The index extended step by step links what one written whole links: the same names, files and
// objects, and its dimension
TEST_F(FieldWriterTest, TheExtendedIndexLinksWhatAWholeOneLinks) {
    {
        qs::FieldWriter writer(dir_.string(), 2);
        for (int step = 0; step < 12; ++step) writeOneStep(writer, 0.5 * step, 2);  // past HDF5's compact links (8)
    }
    const std::vector<std::string> extended = indexLinks(dir_ / "fields.h5");
    ASSERT_EQ(extended.size(), 12u);
    EXPECT_EQ(extended[11], "step_000011 -> fields/step_000011.h5:/");
    // a resumed writer keeping every step writes the index whole
    { qs::FieldWriter resumed(dir_.string(), 2, 1e9); }
    EXPECT_EQ(indexLinks(dir_ / "fields.h5"), extended);
    const hid_t file = H5Fopen((dir_ / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    int dimension = 0;
    const hid_t attribute = H5Aopen(file, "dimension", H5P_DEFAULT);
    H5Aread(attribute, H5T_NATIVE_INT, &dimension);
    H5Aclose(attribute);
    H5Fclose(file);
    EXPECT_EQ(dimension, 2);
}

// A listing that fails leaves the step in its file; the next listing lists it, the index written
// whole when the copy cannot be extended
TEST_F(FieldWriterTest, AListingThatFailsIsMadeGoodByTheNext) {
    qs::FieldWriter writer(dir_.string(), 1);
    writeOneStep(writer, 0.0);
    // fields.h5.tmp blocked by a directory with a file in it: neither the copy nor a new file
    fs::create_directories(dir_ / "fields.h5.tmp" / "blocker");
    EXPECT_THROW(writeOneStep(writer, 0.5), qs::Error);
    EXPECT_TRUE(fs::exists(dir_ / "fields" / "step_000001.h5"));
    EXPECT_EQ(indexLinks(dir_ / "fields.h5").size(), 1u);
    fs::remove_all(dir_ / "fields.h5.tmp");
    writeOneStep(writer, 1.0);
    EXPECT_EQ(indexLinks(dir_ / "fields.h5").size(), 3u);
    EXPECT_EQ(occurrences(readText(dir_ / "fields.xdmf"), "<Time "), 3);
}

// listIfDue lists a waiting step once the interval has passed, with no output after it
TEST_F(FieldWriterTest, AWaitingStepIsListedOnceTheIntervalHasPassed) {
    qs::FieldWriter writer(dir_.string(), 1);
    writer.setListingInterval(0.5);
    writeOneStep(writer, 0.0);  // within 0.5 s of the constructor's listing: waits
    writer.listIfDue();
    EXPECT_EQ(occurrences(readText(dir_ / "fields.xdmf"), "<Time "), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(600));
    writer.listIfDue();
    EXPECT_EQ(occurrences(readText(dir_ / "fields.xdmf"), "<Time "), 1);
}

TEST_F(FieldWriterTest, AStepThatCannotBePublishedLeavesTheSeriesBeforeIt) {
    const std::vector<double> z = {0.1};
    qs::FieldWriter writer(dir_.string(), 1);
    writer.beginStep(0.0);
    writer.writePointSet("solid", 1, z.data(), {});
    writer.endStep();
    // A directory in the way of the second step's file: the rename fails, as a full disk would.
    fs::create_directories(dir_ / "fields" / "step_000001.h5" / "in_the_way");
    writer.beginStep(0.5);
    writer.writePointSet("solid", 1, z.data(), {});
    try {
        writer.endStep();
        FAIL() << "expected qs::Error";
    } catch (const qs::Error& e) {
        EXPECT_NE(std::string(e.what()).find("step_000001.h5"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir_ / "fields" / "step_000001.h5.tmp"));
    EXPECT_EQ(writer.stepsWritten(), 1);
    const std::string xdmf = readText(dir_ / "fields.xdmf");
    EXPECT_EQ(occurrences(xdmf, "<Time "), 1);
    const hid_t file = H5Fopen((dir_ / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    EXPECT_TRUE(exists(file, "/step_000000"));
    EXPECT_FALSE(exists(file, "/step_000001"));
    H5Fclose(file);
}

TEST_F(FieldWriterTest, AResumedSeriesKeepsTheStepsBeforeItsFirstNewOutput) {
    const std::vector<double> z = {0.1, 0.2};
    const std::vector<double> v = {1.0, 2.0};
    const std::vector<double> sigma(12, 3.0);
    {
        qs::FieldWriter writer(dir_.string(), 1);
        for (int step = 0; step < 4; ++step) {
            writer.beginStep(0.5 * step);
            writer.writePointSet("solid", 2, z.data(),
                                 {{"porosity", z.data(), 1},
                                  {"velocity", v.data(), 1, qs::FieldKind::Vector},
                                  {"effective_stress", sigma.data(), 6}});
            writer.writePointSet("liquid", 0, nullptr, {});
            writer.endStep();
        }
    }
    const std::string before = readText(dir_ / "fields.xdmf");
    std::ofstream(dir_ / "fields" / "step_000009.h5.tmp") << "a crash's leftover";
    std::ofstream(dir_ / "fields" / "notes.txt") << "a user's file, not ours to remove";
    {
        // Resumed at t = 0.6 s: its first new output is at 1.0 s, so 0, 0.5 stay and 1.0, 1.5 go.
        qs::FieldWriter writer(dir_.string(), 1, 1.0 - 1e-6);
        EXPECT_EQ(writer.stepsWritten(), 2);
        writer.beginStep(1.0);
        writer.writePointSet("solid", 2, z.data(),
                             {{"porosity", v.data(), 1},
                              {"velocity", v.data(), 1, qs::FieldKind::Vector},
                              {"effective_stress", sigma.data(), 6}});
        writer.writePointSet("liquid", 0, nullptr, {});
        writer.endStep();
    }
    EXPECT_EQ(filesIn(dir_ / "fields"),
              (std::vector<std::string>{"notes.txt", "step_000000.h5", "step_000001.h5", "step_000002.h5"}));
    const std::string after = readText(dir_ / "fields.xdmf");
    EXPECT_EQ(occurrences(after, "<Time "), 3);
    // The kept steps are indexed as they were written: same vector and tensor attributes.
    const std::string stepOne = before.substr(before.find("<Grid Name=\"step_000001\""),
                                              before.find("<Grid Name=\"step_000002\"") -
                                                  before.find("<Grid Name=\"step_000001\""));
    EXPECT_NE(after.find(stepOne), std::string::npos) << stepOne;
    EXPECT_NE(stepOne.find("AttributeType=\"Tensor6\""), std::string::npos);
    EXPECT_NE(stepOne.find("AttributeType=\"Vector\""), std::string::npos);
    const hid_t file = H5Fopen((dir_ / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    EXPECT_EQ(readDoubleAttribute(file, "/step_000001", "time"), 0.5);
    EXPECT_EQ(readDoubles(file, "/step_000001/solid/porosity"), z);
    EXPECT_EQ(readDoubles(file, "/step_000002/solid/porosity"), v);
    EXPECT_FALSE(exists(file, "/step_000003"));
    H5Fclose(file);
}
